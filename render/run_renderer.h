#pragma once
// Renders a logged run: the composed world with each vehicle posed from the log at time t, the
// planned path as a line (one colour per agent), the reference trajectory as a thin dashed
// line, the flown trail coloured by tracking error, start and goal markers, optionally
// see-through obstacles, and a 2D overlay (state box, legend, colour scale). Everything comes
// from the log, so a run can be re-rendered from another camera without simulating it again.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "render/camera_rig.h"
#include "render/frame_annotations.h"
#include "render/log_lookup.h"
#include "render/offscreen_context.h"
#include "render/overlay_palette.h"
#include "render/ribbon_batch.h"
#include "run/record/run_record.h"
#include "sim/run_log.h"
#include "sim/world_model.h"

namespace cosim {

// Where the last frame's time went (wall clock, seconds), for benchmarks comparing frames.
struct FrameTimings {
  double scene = 0.0;       // posing the vehicles, mjv_updateScene, camera and lights
  double overlays = 0.0;    // adding paths, trails, markers and arrows to the scene
  double render = 0.0;      // mjr_render, a team's ribbons, and OSMesa finishing the raster
  double annotate = 0.0;    // the 2D state box, legend and colour scale
  double read = 0.0;        // reading the pixels back
  int model_geoms = 0;      // geoms from the model (world and vehicles)
  int overlay_geoms = 0;    // geoms the overlays added
  int ribbon_segments = 0;  // a team's line segments drawn as ribbons (render/ribbon_batch.h)
};

class RunRenderer {
 public:
  // Draws the record of a run of `scenario` (its world, log and tracking errors); both must
  // outlive the renderer.
  RunRenderer(const Scenario& scenario, const RunRecord& record, int width, int height);
  ~RunRenderer();
  RunRenderer(const RunRenderer&) = delete;
  RunRenderer& operator=(const RunRenderer&) = delete;

  // The frame at simulated time t from a named camera (chase, orbit, top, overview, fixed).
  // The trail is drawn up to t (pass endTime() for the final picture). annotate: the 2D
  // overlay (state box, legend, colour scale).
  void render(double t, CameraKind camera, std::vector<std::uint8_t>& rgb, bool annotate = true);
  void render(double t, const std::string& camera, std::vector<std::uint8_t>& rgb,
              bool annotate = true) {
    render(t, cameraKind(camera), rgb, annotate);
  }

  // Pixel (column, row from the top) where world point p appears in the last rendered frame;
  // row/column may be outside the image. Returns false if p is behind the camera.
  bool project(const Eigen::Vector3d& p, Eigen::Vector2d& pixel) const;

  double endTime() const { return end_time_; }
  const FrameTimings& lastFrameTimings() const { return timings_; }
  // The 2D boxes of the last annotated frame (pixels from the bottom left): the state box, the
  // legend, then one per colour scale.
  const std::vector<mjrRect>& lastOverlayBoxes() const { return overlay_boxes_; }
  // What this renderer draws from, for renderers of the same run on other threads.
  const WorldModel& world() const { return world_; }
  const Scenario& scenario() const { return scenario_; }
  const RunRecord& record() const { return record_; }
  const RunLog& log() const { return log_; }
  // m, the top of the colour scale vehicle's trail is coloured on. Vehicles whose errors are
  // measured against the same kind of reference (sim/error_reference.h) share a scale; a mixed run
  // has one for the robots and one for the quadrotors, each with its own bar and title.
  double errorScale(std::size_t vehicle) const { return scales_[scale_of_[vehicle]].top; }
  ErrorReference errorReferenceOf(std::size_t vehicle) const {
    return record_.errorReferenceOf(vehicle);
  }
  const std::vector<double>& trackingErrorsOf(std::size_t vehicle) const {
    return record_.metrics.tracking_errors[vehicle];
  }
  int width() const { return ctx_->width(); }
  int height() const { return ctx_->height(); }

 private:
  void poseVehicles(double t);
  void applyCamera(const CameraPose& pose);
  void fadeObstacles(const CameraPose& pose, CameraKind camera, double t);
  void addOverlays(double t, CameraKind camera);
  // Removes from the scene the airframes of team members smaller than a marker on screen.
  void hideTinyVehicles(double t);
  void addTrail(std::size_t vehicle, double t);
  void addReference(const VehicleLog& v);
  // A line: a geom (a capsule by default) for one vehicle, an opaque team line a ribbon.
  void addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3f& rgb,
                  double radius, float alpha = 1.0f, int type = mjGEOM_CAPSULE);
  void addSphere(const Eigen::Vector3d& p, double radius, const Eigen::Vector3f& rgb, float alpha);
  // p moved toward the camera by `widths` line radii: drawn in front of the lines behind it
  // (the flown trail in front of the planned band, the reference in front of both) at the
  // same place on screen.
  Eigen::Vector3d towardEye(const Eigen::Vector3d& p, double widths) const;
  // An arrow from the vehicle along its velocity (render/heading_arrow.h), from 0.6 to 2.2
  // `radius` (m) from its centre, `width` (m) thick; none while the vehicle is nearly still.
  void addHeadingArrow(const LogSample& s, double radius, double width);
  void annotate(double t);
  // room: the most entries the frame has room for; compact: short labels for small frames.
  std::vector<LegendEntry> legendEntries(std::size_t room, bool compact) const;
  bool isGround(std::size_t vehicle) const;
  // The flown trails are coloured by tracking error: a single vehicle's always, a team's with
  // render.team_error (otherwise each member's trail is in its own colour).
  bool trailsShowError() const { return log_.vehicles.size() == 1 || scenario_.render.team_error; }
  Eigen::Vector3f plannedColour(std::size_t vehicle) const;

  struct ErrorScale {
    ErrorReference reference;
    double top = 0.1;  // m
  };

  const WorldModel& world_;
  const Scenario& scenario_;
  const RunRecord& record_;
  const RunLog& log_;
  CameraRig rig_;
  std::vector<ErrorReference> references_;  // per vehicle, the record's
  // Per vehicle, per sample: the record's tracking errors (RunMetrics::tracking_errors).
  const std::vector<std::vector<double>>& errors_;
  std::vector<ErrorScale> scales_;     // one per kind of reference, in order of vehicles
  std::vector<std::size_t> scale_of_;  // per vehicle, into scales_
  std::vector<int> obstacle_geoms_;    // geom id of each scenario obstacle (-1 if absent)
  std::vector<std::vector<Eigen::Vector3d>> planned_paths_;  // per vehicle, corners only
  Eigen::Vector3d eye_ = Eigen::Vector3d::Zero();            // the camera of the current frame
  double fovy_deg_ = 45.0;                                   // and its lens
  // Kept trail vertices per vehicle, for the line width they were decimated for (recomputed
  // when the camera changes it).
  std::vector<std::vector<std::size_t>> trail_vertices_;
  double trail_line_radius_ = -1.0;
  double end_time_ = 0.0;
  mjData* data_ = nullptr;
  mjvScene scene_;
  mjvCamera camera_;
  mjvOption option_;
  std::unique_ptr<OffscreenContext> ctx_;
  double line_radius_ = 0.05;
  FrameTimings timings_;
  std::vector<mjrRect> overlay_boxes_;
  RibbonBatch ribbons_;  // a team's trails, drawn after mjr_render
};

}  // namespace cosim
