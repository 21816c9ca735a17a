// The CSV flight log (t,x,y,z and optional ref_x,ref_y,ref_z) and its bad inputs.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "experiments/compare/flight_log.h"

namespace cosim::test {
namespace {

std::string rows(int n, int from = 0) {
  std::string s;
  for (int k = from; k < from + n; ++k)
    s += std::to_string(0.01 * k) + "," + std::to_string(k) + ",2,3\n";
  return s;
}

std::string errorOf(const std::string& text) {
  try {
    parseFlightLogCsv(text, "log.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FlightLogCsv, ReadsPositionsAndReferenceColumnsInAnyOrder) {
  const FlightLog plain = parseFlightLogCsv("t,x,y,z\r\n" + rows(12), "log.csv");
  EXPECT_FALSE(plain.hasReference());
  ASSERT_EQ(plain.position.size(), 12u);
  EXPECT_DOUBLE_EQ(plain.position.p[7].x(), 7.0);
  EXPECT_DOUBLE_EQ(plain.position.t[7], 0.07);
  std::string text = "ref_z,t,x,vx,y,z,ref_x,ref_y\n";
  for (int k = 0; k < 10; ++k)
    text += "1.5," + std::to_string(k) + ",0.5,9,1,2,0.25," + std::to_string(-k) + "\n";
  const FlightLog with_ref = parseFlightLogCsv(text, "log.csv");
  ASSERT_TRUE(with_ref.hasReference());
  EXPECT_EQ(with_ref.reference.p[4], Eigen::Vector3d(0.25, -4, 1.5));
  EXPECT_EQ(with_ref.position.p[4], Eigen::Vector3d(0.5, 1, 2));
  // Between samples, the path is read linearly.
  EXPECT_DOUBLE_EQ(with_ref.reference.at(4.25).y(), -4.25);
}

TEST(FlightLogCsv, BadFilesNameTheLineAndTheProblem) {
  EXPECT_EQ(errorOf(""), "log.csv: line 1: empty file, expected a header t,x,y,z");
  EXPECT_NE(errorOf("time,x,y,z\n" + rows(12)).find("line 1: missing column 't'"),
            std::string::npos);
  EXPECT_NE(errorOf("t,x,y,z,ref_x\n").find("need all of ref_x,ref_y,ref_z"), std::string::npos);
  EXPECT_NE(errorOf("t,x,y,z\n" + rows(5) + "0.05,nan,2,3\n" + rows(6, 6))
                .find("line 7, column x: not a finite number: 'nan'"),
            std::string::npos);
  EXPECT_NE(errorOf("t,x,y,z\n" + rows(5) + "0.02,1,2,3\n")
                .find("line 7, column t: time does "
                      "not increase"),
            std::string::npos);
  EXPECT_NE(errorOf("t,x,y,z\n" + rows(3) + "0.5,1,2\n").find("line 5: has 3 fields"),
            std::string::npos);
  EXPECT_NE(errorOf("t,x,y,z\n" + rows(9)).find("too few samples: 9 rows"), std::string::npos);
}

}  // namespace
}  // namespace cosim::test
