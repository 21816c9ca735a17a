#pragma once
// Renders a logged run: the composed world with each vehicle posed from the log at time t,
// the planned path as a polyline, the flown path as a trail in another colour, start and goal
// markers and a text overlay. Everything comes from the log, so a run can be re-rendered from
// another camera without simulating it again.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "render/offscreen_context.h"
#include "sim/run_log.h"
#include "sim/world_model.h"

namespace cosim {

// Colours of the overlays (RGB, 0..1), exposed so tests can look for them.
inline const Eigen::Vector3f kPlannedPathColour{1.0f, 0.3f, 0.05f};
inline const Eigen::Vector3f kFlownPathColour{0.05f, 0.4f, 1.0f};

class RunRenderer {
 public:
  RunRenderer(const WorldModel& world, const Scenario& scenario, const RunLog& log, int width,
              int height);
  ~RunRenderer();

  // camera: "chase" (behind the first vehicle, following its heading), "overview" (the whole
  // world at an angle), "top" (straight down). trail_until: draw the flown trail up to this
  // time (the frame time for videos; +inf for the final picture).
  void render(double t, const std::string& camera, std::vector<std::uint8_t>& rgb,
              bool overlay_text = true);

  // Pixel (column, row from the top) where world point p appears in the last rendered frame;
  // row/column may be outside the image. Returns false if p is behind the camera.
  bool project(const Eigen::Vector3d& p, Eigen::Vector2d& pixel) const;

  double endTime() const;
  int width() const { return ctx_->width(); }
  int height() const { return ctx_->height(); }

 private:
  void poseVehicles(double t);
  void placeCamera(double t, const std::string& camera);
  void addOverlays(double t);
  void addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3f& rgb,
                  double radius);
  void addSphere(const Eigen::Vector3d& p, double radius, const Eigen::Vector4f& rgba);
  std::size_t sampleIndex(const VehicleLog& v, double t) const;

  const WorldModel& world_;
  const Scenario& scenario_;
  const RunLog& log_;
  mjData* data_ = nullptr;
  mjvScene scene_;
  mjvCamera camera_;
  mjvOption option_;
  std::unique_ptr<OffscreenContext> ctx_;
  double line_radius_ = 0.05;
};

}  // namespace cosim
