// timeseriesColumns (what Python's RunResult.timeseries returns) and timeseries.csv share one
// definition: the same column names in the same order, and the same values.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/csv_text.h"
#include "sim/run_log_io.h"

using namespace cosim;

namespace {

LogSample sampleAt(double t, double roll_deg) {
  LogSample s;
  s.t = t;
  s.pos = Eigen::Vector3d(1.0 + t, 2.0, 3.0);
  s.att = Eigen::Quaterniond(Eigen::AngleAxisd(roll_deg * M_PI / 180.0, Eigen::Vector3d::UnitX()));
  s.rotor_cmd = Eigen::Vector4d(3.5, 3.6, 3.7, 3.8);
  s.saturated = t > 0.0;
  return s;
}

RunLog twoVehicleLog() {
  RunLog log;
  for (const char* name : {"uav1", "uav,2"}) {
    VehicleLog& v = log.vehicles.emplace_back();
    v.name = name;
  }
  log.vehicles[0].samples = {sampleAt(0.0, 0.0)};
  log.vehicles[1].samples = {sampleAt(0.0, 10.0), sampleAt(0.002, 30.0)};
  return log;
}

}  // namespace

TEST(TimeseriesColumns, HaveTheCsvHeaderAndTheCsvValuesOfTheirVehicle) {
  const RunLog log = twoVehicleLog();
  const auto columns = timeseriesColumns(log, 1);
  std::istringstream csv(timeseriesCsv(log));
  std::string line;
  std::vector<std::string> header, row;
  std::getline(csv, line);
  ASSERT_TRUE(splitCsvRecord(line, header));
  ASSERT_EQ(columns.size() + 1, header.size());  // all but `vehicle`
  for (std::size_t c = 0; c < columns.size(); ++c) EXPECT_EQ(columns[c].first, header[c]);
  EXPECT_EQ(header.back(), "vehicle");

  std::size_t vehicle_row = 0;
  while (std::getline(csv, line)) {
    ASSERT_TRUE(splitCsvRecord(line, row));
    if (row.back() != "uav,2") continue;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      ASSERT_EQ(columns[c].second.size(), 2u);
      // The file holds 9 significant digits.
      EXPECT_NEAR(columns[c].second[vehicle_row], std::stod(row[c]),
                  1e-8 * std::max(1.0, std::abs(std::stod(row[c]))))
          << columns[c].first;
    }
    ++vehicle_row;
  }
  EXPECT_EQ(vehicle_row, 2u);
}

TEST(TimeseriesColumns, DeriveRollAndFlagSaturationAsTheFileDoes) {
  const auto columns = timeseriesColumns(twoVehicleLog(), 1);
  auto column = [&](const std::string& name) {
    for (const auto& [n, values] : columns)
      if (n == name) return values;
    ADD_FAILURE() << "no column " << name;
    return std::vector<double>();
  };
  EXPECT_NEAR(column("roll_deg")[1], 30.0, 1e-9);
  EXPECT_NEAR(column("pitch_deg")[1], 0.0, 1e-9);
  EXPECT_EQ(column("saturated"), (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(column("x"), (std::vector<double>{1.0, 1.002}));
  EXPECT_EQ(column("cmd2")[0], 3.7);
}

TEST(TimeseriesColumns, AreEmptyForAVehicleTheLogDoesNotHave) {
  EXPECT_TRUE(timeseriesColumns(twoVehicleLog(), 2).empty());
}
