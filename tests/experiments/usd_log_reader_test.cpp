// The Crazyflie uSD-card log reader on logs this test writes byte by byte (usd_log_writer.h):
// both versions of the format, several event types with every value type, the CRC, and the
// ways a log can be broken.
#include "experiments/compare/usd_log_reader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "experiments/compare/flight_log.h"
#include "tests/experiments/usd_log_writer.h"

namespace cosim::test {
namespace {

using W = UsdLogWriter;

// fixedFrequency (id 0xFFFF, as the firmware names it) with the mocap and estimated positions,
// a "setpoint" event with the controller's target, and an event with one variable of each
// remaining type.
UsdLogWriter threeTypeLog(int version) {
  W w(version);
  w.addType({0xFFFF,
             "fixedFrequency",
             {"locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)", "stateEstimate.x(f)",
              "stateEstimate.y(f)", "stateEstimate.z(f)"}});
  w.addType({7, "setpoint", {"ctrltarget.x(f)", "ctrltarget.y(f)", "ctrltarget.z(f)"}});
  w.addType({9,
             "mixed",
             {"a.i8(b)", "a.u8(B)", "a.i16(h)", "a.u16(H)", "a.i32(i)", "a.u32(I)", "a.i64(q)",
              "a.u64(Q)", "a.half(e)", "a.dbl(d)"}});
  for (int k = 0; k < 20; ++k) {
    const double t = 1.0 + 0.01 * k;
    const float x = 0.1f * k, y = -0.05f * k, z = 1.0f;
    w.record(0xFFFF, t,
             W::f32(x) + W::f32(y) + W::f32(z) + W::f32(x + 0.5f) + W::f32(y) + W::f32(z));
    if (k % 2 == 0)  // the target at half the rate, 5 ms later: read between its samples
      w.record(7, t + 0.005, W::f32(0.1f * k + 0.01f) + W::f32(0.0f) + W::f32(1.0f));
  }
  w.record(9, 1.5,
           W::integer(-5, 1) + W::integer(250, 1) + W::integer(-30000, 2) + W::integer(65000, 2) +
               W::integer(-2000000000, 4) + W::integer(4000000000LL, 4) +
               W::integer(-9000000000LL, 8) + W::integer(9000000000LL, 8) +
               W::integer(0xC000, 2) /* half -2.0 */ + W::f64(3.141592653589793));
  return w;
}

TEST(UsdLogReader, ReadsHeaderAndEveryValueTypeOfBothVersions) {
  for (int version : {1, 2}) {
    const UsdLog log = UsdLog::parse(threeTypeLog(version).bytes(), "v.bin");
    EXPECT_EQ(log.version(), version);
    ASSERT_EQ(log.eventTypes().size(), 3u);
    EXPECT_EQ(log.eventTypes()[0].name, "fixedFrequency");
    EXPECT_EQ(log.eventTypes()[0].records, 20u);
    EXPECT_EQ(log.eventTypes()[1].records, 10u);
    EXPECT_EQ(log.eventTypes()[2].value_bytes, 1u + 1 + 2 + 2 + 4 + 4 + 8 + 8 + 2 + 8);
    EXPECT_EQ(log.eventTypes()[2].variables[8].offset, 30u);  // 1+1+2+2+4+4+8+8 bytes before it
    const UsdSeries pos = log.series(0, {"locSrv.x", "locSrv.z"});
    ASSERT_EQ(pos.t.size(), 20u);
    EXPECT_DOUBLE_EQ(pos.t[3], 1.03);
    EXPECT_DOUBLE_EQ(pos.values[0][3], static_cast<double>(0.1f * 3));
    EXPECT_DOUBLE_EQ(pos.values[1][19], 1.0);
    const UsdSeries m = log.series(2, {"a.i8", "a.u8", "a.i16", "a.u16", "a.i32", "a.u32", "a.i64",
                                       "a.u64", "a.half", "a.dbl"});
    const std::vector<double> expected = {
        -5,           250,           -30000,       65000, -2000000000,
        4000000000.0, -9000000000.0, 9000000000.0, -2.0,  3.141592653589793};
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(m.values[i][0], expected[i]) << i;
    EXPECT_DOUBLE_EQ(m.t[0], 1.5);
  }
}

TEST(UsdLogReader, FlightLogTakesMocapPositionAndTheTargetOfAnotherEvent) {
  const FlightLog log = parseFlightLogUsd(threeTypeLog(2).bytes(), "v2.bin");
  EXPECT_EQ(log.format, "Crazyflie uSD log version 2");
  EXPECT_EQ(log.position_source, "locSrv.x,locSrv.y,locSrv.z (event fixedFrequency)");
  ASSERT_TRUE(log.hasReference());
  // Targets at 1.005, 1.025, ..., 1.185 s: position samples from 1.01 to 1.18 s lie inside.
  ASSERT_EQ(log.position.size(), 18u);
  EXPECT_DOUBLE_EQ(log.position.t.front(), 1.01);
  // At 1.01 s the target lies a quarter of the way from its 1.005 s value (0.01) to its
  // 1.025 s value (0.21): 0.06.
  EXPECT_NEAR(log.reference.p.front().x(), 0.06, 1e-6);
  EXPECT_NEAR(log.position.p.front().x(), 0.1, 1e-6);
}

TEST(UsdLogReader, ZeroMocapFallsBackToTheEstimateAndNamedVariablesWin) {
  W w(2);
  w.addType({1,
             "fixedFrequency",
             {"locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)", "stateEstimate.x(f)",
              "stateEstimate.y(f)", "stateEstimate.z(f)", "my.px(d)", "my.py(d)", "my.pz(d)"}});
  for (int k = 0; k < 12; ++k)
    w.record(1, 0.1 * k,
             W::f32(0) + W::f32(0) + W::f32(0) + W::f32(2.0f) + W::f32(3.0f) + W::f32(k) +
                 W::f64(-1) + W::f64(-2) + W::f64(-3));
  const FlightLog estimate = parseFlightLogUsd(w.bytes(), "z.bin");
  EXPECT_EQ(estimate.position_source.substr(0, 15), "stateEstimate.x");
  EXPECT_FALSE(estimate.hasReference());
  EXPECT_DOUBLE_EQ(estimate.position.p[5].z(), 5.0);
  FlightLogOptions o;
  o.position_vars = {"my.px", "my.py", "my.pz"};
  EXPECT_DOUBLE_EQ(parseFlightLogUsd(w.bytes(), "z.bin", o).position.p[0].y(), -2.0);
}

std::string errorOf(const std::string& bytes, const FlightLogOptions& o = {}) {
  try {
    parseFlightLogUsd(bytes, "bad.bin", o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(UsdLogReader, BrokenLogsAreInputErrorsNamingTheByte) {
  const W good = threeTypeLog(2);
  const std::string bytes = good.bytes();
  EXPECT_NE(errorOf(good.bytes(true))
                .find("byte " + std::to_string(bytes.size() - 4) + ": CRC-32 mismatch"),
            std::string::npos)
      << errorOf(good.bytes(true));
  // A record cut short, with the CRC made right: the reader finds the cut itself.
  std::string cut = bytes.substr(0, bytes.size() - 4 - 3);
  W::putInt(cut, crc32(reinterpret_cast<const unsigned char*>(cut.data()), cut.size()), 4);
  EXPECT_NE(errorOf(cut).find("truncated record of event mixed"), std::string::npos)
      << errorOf(cut);
  W letter(2);
  letter.addType({1, "fixedFrequency", {"locSrv.x(f)", "locSrv.y(z)"}});
  EXPECT_NE(errorOf(letter.bytes()).find("unknown type letter 'z' of variable locSrv.y"),
            std::string::npos)
      << errorOf(letter.bytes());
  W unknown(1);
  unknown.addType({1, "fixedFrequency", {"locSrv.x(f)"}});
  unknown.record(2, 0.0, "");
  EXPECT_NE(errorOf(unknown.bytes()).find("event id 2, which the header does not declare"),
            std::string::npos);
  W none(2);
  none.addType({1, "fixedFrequency", {"pm.vbat(f)"}});
  EXPECT_NE(errorOf(none.bytes()).find("no position variables"), std::string::npos);
  EXPECT_NE(errorOf(none.bytes()).find("fixedFrequency: pm.vbat"), std::string::npos);
  W back(2);
  back.addType({1, "fixedFrequency", {"locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)"}});
  for (double t : {0.1, 0.2, 0.15}) back.record(1, t, W::f32(1) + W::f32(1) + W::f32(1));
  EXPECT_NE(errorOf(back.bytes()).find("time goes back"), std::string::npos);
  EXPECT_NE(errorOf(std::string("\xBC\x02", 2)).find("too short"), std::string::npos);
  W future(3);
  future.addType({1, "fixedFrequency", {"locSrv.x(f)"}});
  EXPECT_NE(errorOf(future.bytes()).find("byte 1: unsupported uSD log version 3"),
            std::string::npos);
  W nan(2);
  nan.addType({1, "fixedFrequency", {"locSrv.x(f)", "locSrv.y(f)", "locSrv.z(f)"}});
  for (int k = 0; k < 12; ++k)
    nan.record(1, 0.01 * k, W::f32(1) + W::f32(k == 4 ? std::nanf("") : 1.0f) + W::f32(1));
  // Header: 5 bytes, id 2, "fixedFrequency\0" 15, count 2, three "locSrv.?(f)\0" of 12 = 60;
  // records of 2 + 8 + 12 = 22 bytes: the fifth starts at 60 + 4 * 22 = 148.
  EXPECT_NE(
      errorOf(nan.bytes()).find("byte 148: not a finite number in locSrv.x,locSrv.y,locSrv.z"),
      std::string::npos)
      << errorOf(nan.bytes());
}

}  // namespace
}  // namespace cosim::test
