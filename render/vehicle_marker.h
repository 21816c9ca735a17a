#pragma once
// The marker drawn around each vehicle of a team, in the vehicle's colour: from the overview of
// a 12 m room a Crazyflie (0.05 m) spans about three pixels and disappears, so its marker is a
// solid ball of a fixed size on screen; a vehicle large enough to see gets a see-through halo
// that only tells its colour.
namespace cosim {

// Pixels: a marker's radius on screen is at least this (a 14 px disc).
constexpr double kMarkerMinPixels = 7.0;

// Metres one pixel covers at `depth` metres from the eye, through a lens of vertical field of
// view `fovy_deg` onto `height_px` rows (pinhole camera: visible height 2 depth tan(fovy / 2)).
double metresPerPixel(double depth, double fovy_deg, int height_px);

struct VehicleMarker {
  double radius = 0.0;  // m
  bool solid = false;   // the vehicle itself would be under kMarkerMinPixels: an opaque ball
};

// The marker of a vehicle of `vehicle_radius` (m) seen at `depth` (m): 1.3 vehicle radii, or
// kMarkerMinPixels on screen when that is larger (then solid).
VehicleMarker vehicleMarker(double vehicle_radius, double depth, double fovy_deg, int height_px);

}  // namespace cosim
