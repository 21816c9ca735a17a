#include "render/vehicle_marker.h"

#include <cmath>

namespace cosim {

double metresPerPixel(double depth, double fovy_deg, int height_px) {
  return 2.0 * depth * std::tan(0.5 * fovy_deg * M_PI / 180.0) / height_px;
}

VehicleMarker vehicleMarker(double vehicle_radius, double depth, double fovy_deg, int height_px) {
  const double least = kMarkerMinPixels * metresPerPixel(depth, fovy_deg, height_px);
  const double halo = 1.3 * vehicle_radius;
  if (halo >= least) return {halo, false};
  return {least, true};
}

}  // namespace cosim
