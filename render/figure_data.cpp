#include "render/figure_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/stop_request.h"
#include "core/stop_requested_error.h"
#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

std::size_t plotRowsPerVehicle(std::size_t vehicles) {
  return std::clamp(kPlotRowBudget / std::max<std::size_t>(1, vehicles), kMinPlotRowsPerVehicle,
                    kMaxPlotRowsPerVehicle);
}

std::vector<std::size_t> evenSampleIndices(std::size_t count, std::size_t rows) {
  std::vector<std::size_t> kept;
  if (count == 0) return kept;
  const std::size_t step =
      std::max<std::size_t>(1, (count + rows - 1) / std::max<std::size_t>(1, rows));
  for (std::size_t i = 0; i < count; i += step) kept.push_back(i);
  if (kept.back() != count - 1) kept.push_back(count - 1);  // always end with the last sample
  return kept;
}

long rgbNumber(const Eigen::Vector3f& rgb) {
  const auto byte = [](float c) { return std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f); };
  return (byte(rgb.x()) << 16) | (byte(rgb.y()) << 8) | byte(rgb.z());
}

namespace {

void writeDataFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

void point(std::ostringstream& s, const Eigen::Vector3d& p, long rgb) {
  s << gnuplotNumber(p.x()) << ' ' << gnuplotNumber(p.y()) << ' ' << gnuplotNumber(p.z()) << ' '
    << rgb << '\n';
}

}  // namespace

FigureFiles writeFigureFiles(const RunRecord& record, const std::filesystem::path& dir) {
  const RunLog& log = record.log;
  const bool several = log.vehicles.size() > 1;
  const std::size_t rows = plotRowsPerVehicle(log.vehicles.size());
  std::ostringstream flown, refs, plans, starts, goals;
  FigureFiles files;
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
    // A 500-vehicle team's files take a second to write: a stop request is answered midway.
    if (stopRequested()) throw StopRequestedError("stopped while writing the figures' data");
    const VehicleLog& v = log.vehicles[a];
    const std::vector<double>& err = record.metrics.tracking_errors[a];
    const long own = rgbNumber(vehicleColour(a));
    const bool trajectory = record.errorReferenceOf(a) == ErrorReference::Trajectory;
    std::ostringstream block;
    for (std::size_t i : evenSampleIndices(v.samples.size(), rows)) {
      const LogSample& x = v.samples[i];
      block << gnuplotNumber(x.t) << ' ' << gnuplotNumber(x.pos.x()) << ' '
            << gnuplotNumber(x.pos.y()) << ' ' << gnuplotNumber(x.pos.z()) << ' '
            << gnuplotNumber(x.ref_pos.x()) << ' ' << gnuplotNumber(x.ref_pos.y()) << ' '
            << gnuplotNumber(x.ref_pos.z()) << ' ' << gnuplotNumber(i < err.size() ? err[i] : 0.0)
            << ' ' << own << '\n';
    }
    if (v.samples.empty()) {
      // A block with no points keeps the next vehicle's block index its own (figures/error
      // selects a vehicle's rows by it).
      flown << "# " << a << ": no samples\n\n";
    } else {
      files.duration = std::max(files.duration, v.samples.back().t);
      files.any_flown = true;
      flown << block.str() << '\n';
      if (trajectory) {
        refs << block.str() << '\n';
        files.any_reference = true;
      }
    }
    const long plan_rgb = several ? own : rgbNumber(kPlannedPathColour);
    for (const Eigen::Vector3d& p : v.planned_path) point(plans, p, plan_rgb);
    if (!v.planned_path.empty()) plans << '\n';
    files.any_plan = files.any_plan || v.planned_path.size() > 1;
    const Eigen::Vector3d start = !v.planned_path.empty() ? v.planned_path.front()
                                  : !v.samples.empty()    ? v.samples.front().pos
                                                          : v.goal;
    point(starts, start, several ? own : rgbNumber(kStartColour));
    point(goals, v.goal, several ? own : rgbNumber(kGoalColour));
  }
  // gnuplot refuses to plot an empty file: a comment line stands for none.
  const auto text = [](const std::ostringstream& s) {
    return s.str().empty() ? std::string("# none\n") : s.str();
  };
  writeDataFile(dir / "flown.dat", text(flown));
  writeDataFile(dir / "refs.dat", text(refs));
  writeDataFile(dir / "plans.dat", text(plans));
  writeDataFile(dir / "starts.dat", text(starts));
  writeDataFile(dir / "goals.dat", text(goals));
  return files;
}

}  // namespace cosim
