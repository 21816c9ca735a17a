#include "experiments/reproduce/crazyflie_figure8_reference.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cosim::reproduce {

namespace {

// figure8.csv: uav_trajectories' format, one row per piece: duration, then 8 coefficients each
// of x, y, z and yaw, lowest power first, in the piece's local time (yaw is 0 throughout).
PiecewisePolynomialTrajectory loadFigureEight() {
  const std::string path = std::string(COSIM_SCENARIOS_DIR) + "/figure8.csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  std::getline(in, line);  // header
  std::vector<PolynomialPiece> pieces;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \r\n") == std::string::npos) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    double duration = 0.0;
    PolynomialPiece::Coefficients c;
    row >> duration;
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < PolynomialPiece::kCoefficients; ++k) row >> c(k, axis);
    if (!row || !(duration > 0.0)) throw std::runtime_error(path + ": bad row");
    pieces.push_back(PiecewisePolynomialTrajectory::pieceFromTimeCoefficients(duration, c));
  }
  return PiecewisePolynomialTrajectory(std::move(pieces));
}

}  // namespace

FigureEightFlight::FigureEightFlight(double hover_before, double timescale,
                                     const Eigen::Vector3d& start)
    : figure_(loadFigureEight()), hover_before_(hover_before), start_(start) {
  figure_.scaleTime(timescale);
}

FlatReference FigureEightFlight::reference(double t, const VehicleState&) {
  FlatReference r;
  r.position = start_;
  finished_ = t >= hover_before_ + figure_.duration();
  if (t < hover_before_) return r;
  const TrajectorySample s = figure_.sample(t - hover_before_);
  r.position = start_ + s.position;
  r.velocity = s.velocity;
  r.acceleration = s.acceleration;
  r.jerk = s.jerk;
  r.snap = s.snap;
  return r;
}

}  // namespace cosim::reproduce
