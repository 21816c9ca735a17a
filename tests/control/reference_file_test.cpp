// Reading reference files (control/reference_file.h): the bundled figure-eight in the
// uav_trajectories format, worked by hand from its first row; a sampled table; and every kind
// of bad file refused with its line (1-based) and what is wrong.
#include "control/reference_file.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"

namespace cosim {
namespace {

std::string polynomialHeader() {
  std::string h = "duration";
  for (const char* axis : {"x", "y", "z", "yaw"})
    for (int k = 0; k < 8; ++k) h += std::string(",") + axis + "^" + std::to_string(k);
  return h;
}

// A row of `duration` and 32 coefficients, all zero but x^1 = 1 (x = tau) and z^0 = z0.
std::string row(const std::string& duration, double z0 = 1.0) {
  std::string r = duration;
  for (int i = 0; i < 32; ++i) {
    r += ',';  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "," + std::string
    r += i == 1 ? std::string("1") : i == 16 ? std::to_string(z0) : std::string("0");
  }
  return r;
}

TEST(ReferenceFile, ReadsTheFigureEightAsWorkedByHandFromItsFirstRow) {
  const ReferenceFile f =
      readReferenceFile(std::string(COSIM_SOURCE_DIR) + "/experiments/references/figure8.csv");
  EXPECT_EQ(f.format, ReferenceFormat::PolynomialPieces);
  ASSERT_EQ(f.reference.pieces().size(), 10u);
  EXPECT_NEAR(f.reference.duration(), 7.283185, 1e-9);  // the sum of the durations
  // Row 1 (1.05 s): x = 0.830443 tau^4 - 0.276140 tau^5 - 0.384219 tau^6 + 0.180493 tau^7.
  const FlatReference r = f.reference.at(0.5);
  EXPECT_NEAR(r.position.x(), 0.830443 / 16 - 0.276140 / 32 - 0.384219 / 64 + 0.180493 / 128,
              1e-12);
  EXPECT_NEAR(r.velocity.x(),
              4 * 0.830443 / 8 - 5 * 0.276140 / 16 - 6 * 0.384219 / 32 + 7 * 0.180493 / 64, 1e-12);
  EXPECT_NEAR(r.acceleration.x(),
              12 * 0.830443 / 4 - 20 * 0.276140 / 8 - 30 * 0.384219 / 16 + 42 * 0.180493 / 32,
              1e-12);
  EXPECT_EQ(r.position.z(), 0.0);
  // Its pieces join: row 2 starts where row 1 ends (to the file's 6 decimals).
  const FlatReference end1 = f.reference.at(1.05 - 1e-12), start2 = f.reference.at(1.05);
  EXPECT_NEAR(start2.position.x(), 0.396058, 1e-12);
  EXPECT_NEAR(end1.position.x(), start2.position.x(), 1e-6);
  EXPECT_NEAR(end1.velocity.x(), start2.velocity.x(), 1e-5);
  // It starts and ends at the origin.
  EXPECT_LT(f.reference.at(0.0).position.norm(), 1e-12);
  EXPECT_LT(f.reference.at(f.reference.duration()).position.norm(), 1e-5);
}

TEST(ReferenceFile, ReadsASampledTableWithYawCrlfBlankLinesAndSpaces) {
  const ReferenceFile f = parseReferenceText(
      "t, x, y, z, yaw\r\n0,0,0,1,0\r\n\r\n1, 1 ,0,1,0.5\r\n2,1,1,1,1\r\n", "s.csv");
  EXPECT_EQ(f.format, ReferenceFormat::Samples);
  EXPECT_DOUBLE_EQ(f.reference.duration(), 2.0);
  EXPECT_NEAR(f.reference.at(1.0).position.x(), 1.0, 1e-12);  // through every sample
  EXPECT_NEAR(f.reference.at(2.0).yaw, 1.0, 1e-12);
  const ReferenceFile no_yaw = parseReferenceText("t,x,y,z\n0,0,0,1\n1,1,0,1\n", "s.csv");
  EXPECT_EQ(no_yaw.reference.at(0.5).yaw, 0.0);
}

TEST(ReferenceFile, APolynomialRowMayEndWithACommaAsUavTrajectoriesWritesIt) {
  const ReferenceFile f =
      parseReferenceText(polynomialHeader() + ",\n" + row("2") + ",\n", "p.csv");
  EXPECT_DOUBLE_EQ(f.reference.at(1.5).position.x(), 1.5);
  EXPECT_DOUBLE_EQ(f.reference.at(1.5).velocity.x(), 1.0);
}

struct BadFile {
  const char* name;
  std::string text;
  std::string place;    // InputError::place()
  std::string problem;  // a part of InputError::problem()
};

std::vector<BadFile> badFiles() {
  const std::string h = polynomialHeader() + "\n";
  std::string many = "t,x,y,z\n";
  for (int i = 0; i <= 100001; ++i) many += std::to_string(i * 0.001) + ",0,0,1\n";
  return {
      {"empty", "", "line 1", "empty file"},
      {"blank_lines_only", "\n  \n", "line 1", "empty file"},
      {"unknown_header", "time,x,y,z\n0,0,0,1\n", "line 1", "unknown header 'time,x,y,z'"},
      {"sampled_header_missing_z", "t,x,y\n0,0,0\n", "line 1", "unknown header"},
      {"polynomial_header_short", "duration,x^0,x^1\n1,0,0\n", "line 1",
       "header has 3 columns, expected 33"},
      {"polynomial_header_misnamed",
       "duration,x^0,x^1,x^2,x^3,x^5,x^4,x^6,x^7" + h.substr(h.find(",y^0")), "line 1, column 6",
       "header 'x^5' where 'x^4' was expected"},
      {"row_too_short", h + row("1") + "\n1,2,3\n", "line 3", "3 values, expected 33"},
      {"row_not_a_number", "t,x,y,z\n0,0,0,1\n1,abc,0,1\n", "line 3, column x",
       "'abc' is not a decimal number"},
      {"row_nan", "t,x,y,z\n0,0,0,1\n1,nan,0,1\n", "line 3, column x",
       "'nan' is not a decimal number"},
      {"row_inf", h + row("1") + "\n" + row("inf") + "\n", "line 3, column duration",
       "'inf' is not a decimal number"},
      // strtod reads hexadecimal: "0x10" was taken as 16.
      {"row_hexadecimal", "t,x,y,z\n0,0,0,1\n1,0x10,0,1\n", "line 3, column x",
       "'0x10' is not a decimal number"},
      {"row_hexadecimal_float", "t,x,y,z\n0,0,0,1\n1,0x1p3,0,1\n", "line 3, column x",
       "'0x1p3' is not a decimal number"},
      // Any readable file may be named: its first line is quoted short, non-ASCII escaped.
      {"binary_header", std::string("\x89PNG\x1a\xff\xfe") + std::string(200, 'A') + "\n", "line 1",
       "unknown header '\\x89PNG\\x1a\\xff\\xfe" + std::string(33, 'A') + "...'"},
      {"row_overflowing", "t,x,y,z\n0,0,0,1e999\n", "line 2, column z", "is not a finite number"},
      {"row_beyond_1e9", "t,x,y,z\n0,0,0,1\n1,2e9,0,1\n", "line 3, column x", "beyond +-1e9"},
      {"empty_value", "t,x,y,z\n0,0,,1\n", "line 2, column y", "empty value"},
      {"zero_duration", h + row("1") + "\n" + row("0") + "\n", "line 3, column duration",
       "is not > 0"},
      {"negative_duration", h + row("-0.5") + "\n", "line 2, column duration", "is not > 0"},
      {"times_going_back", "t,x,y,z\n0,0,0,1\n1,0,0,1\n0.5,0,0,1\n", "line 4, column t",
       "times must increase"},
      {"repeated_time", "t,x,y,z\n0,0,0,1\n0,1,0,1\n", "line 3, column t", "times must increase"},
      {"one_sample", "t,x,y,z\n0,0,0,1\n", "line 2", "at least two rows"},
      {"header_only", h, "line 1", "no pieces after the header"},
      {"longer_than_a_day", "t,x,y,z\n0,0,0,1\n90000,0,0,1\n", "line 3", "more than a day"},
      {"too_many_rows", many, "line 100003", "more than 100000 intervals"},
  };
}

class BadReferenceFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadReferenceFile, IsRefusedNamingTheFileTheLineAndTheProblem) {
  const BadFile& c = GetParam();
  try {
    parseReferenceText(c.text, "bad.csv");
    FAIL() << "accepted " << c.name;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.csv");
    EXPECT_EQ(e.place(), c.place) << e.what();
    EXPECT_NE(e.problem().find(c.problem), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, BadReferenceFile, ::testing::ValuesIn(badFiles()),
                         [](const ::testing::TestParamInfo<BadFile>& i) { return i.param.name; });

}  // namespace
}  // namespace cosim
