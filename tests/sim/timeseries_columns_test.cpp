// timeseriesColumns hands a front end timeseries.csv's numbers without a file: the file's numeric
// columns, in its order, with its values (the file writes 9 significant digits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "sim/run_log_io.h"

namespace cosim {
namespace {

RunLog twoVehicleLog() {
  RunLog log;
  for (const char* name : {"a", "b"}) {
    VehicleLog& v = log.vehicles.emplace_back();
    v.name = name;
    for (int k = 0; k < 3; ++k) {
      LogSample s;
      s.t = 0.1 * k;
      s.pos = {1.0 + k, 2.0, name[0] == 'b' ? 5.0 : 3.0};
      s.att = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()));
      s.rotor_speed = {100.0 + k, 200.0, 300.0, 400.0};
      s.saturated = k == 1;
      v.samples.push_back(s);
    }
  }
  return log;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

TEST(TimeseriesColumns, AreTheFilesNumericColumnsWithTheFilesValues) {
  const RunLog log = twoVehicleLog();
  const auto columns = timeseriesColumns(log, 1);
  std::stringstream csv(timeseriesCsv(log));
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = fields(line);
  ASSERT_EQ(columns.size() + 1, header.size());  // all but the vehicle's name
  EXPECT_EQ(header.back(), "vehicle");
  for (std::size_t c = 0; c < columns.size(); ++c) EXPECT_EQ(columns[c].first, header[c]);
  for (int skip = 0; skip < 3; ++skip) std::getline(csv, line);  // vehicle a's rows
  for (std::size_t k = 0; k < 3; ++k) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> row = fields(line);
    EXPECT_EQ(row.back(), "b");
    for (std::size_t c = 0; c < columns.size(); ++c) {
      char text[32];
      std::snprintf(text, sizeof text, "%.9g", columns[c].second[k]);
      EXPECT_EQ(row[c], text) << columns[c].first << " row " << k;
    }
  }
}

TEST(TimeseriesColumns, HoldOneVehiclesSamplesWithDerivedAngles) {
  const auto columns = timeseriesColumns(twoVehicleLog(), 1);
  const auto column = [&](const std::string& name) {
    for (const auto& [n, values] : columns)
      if (n == name) return values;
    ADD_FAILURE() << "no column " << name;
    return std::vector<double>();
  };
  EXPECT_EQ(column("z"), (std::vector<double>{5.0, 5.0, 5.0}));  // b's, not a's 3.0
  EXPECT_EQ(column("x"), (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(column("saturated"), (std::vector<double>{0.0, 1.0, 0.0}));
  EXPECT_NEAR(column("yaw_deg")[2], 30.0, 1e-9);
  EXPECT_EQ(column("w0"), (std::vector<double>{100.0, 101.0, 102.0}));
}

TEST(TimeseriesColumns, PastTheLastVehicleIsOutOfRange) {
  EXPECT_THROW(timeseriesColumns(twoVehicleLog(), 2), std::out_of_range);
}

}  // namespace
}  // namespace cosim
