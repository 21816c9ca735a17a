// compare-real refuses what it cannot compare, exit 2 and one line naming the file, the place
// and the problem: a run folder's time series cut short or added to (read as render and
// export-mcap read it), positions of 1e308 m, a reference that never moves, a log that nowhere
// holds the flight.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <sstream>

#include "tests/experiments/compare_real_fixture.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// A copy of the run whose timeseries.csv lines go through `edit` (header first).
fs::path editedRun(const fs::path& dir, const std::string& name,
                   const std::function<void(std::vector<std::string>&)>& edit) {
  const fs::path run = dir / name;
  fs::remove_all(run);
  fs::copy(dir / "run", run, fs::copy_options::recursive);
  std::vector<std::string> lines;
  std::istringstream in(slurp(run / "timeseries.csv"));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  edit(lines);
  std::ofstream out(run / "timeseries.csv", std::ios::trunc);
  for (const auto& l : lines) out << l << "\n";
  return run;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::istringstream in(line);
  for (std::string x; std::getline(in, x, ',');) f.push_back(x);
  return f;
}

std::string joined(const std::vector<std::string>& f) {
  std::string s;
  for (std::size_t i = 0; i < f.size(); ++i) s += (i ? "," : "") + f[i];
  return s;
}

std::size_t column(const std::string& header, const std::string& name) {
  const auto f = fields(header);
  return static_cast<std::size_t>(std::find(f.begin(), f.end(), name) - f.begin());
}

TEST_F(CompareReal, BadRunFoldersAreRefusedNamingTheFileAndPlace) {
  const auto log = writeLog("late.csv", 0.7, Eigen::Vector3d::Zero());
  const auto refuse = [&](const fs::path& run, const std::string& expected) {
    const CommandResult r = runCosim("compare-real " + run.string() + " " + log.string() +
                                     " --out " + (*dir_ / "bad").string());
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(*dir_ / "bad" / "compare.json"));
  };
  // Cut at a line boundary: it parses, but run.json says how many rows the run wrote.
  refuse(editedRun(*dir_, "cut", [](auto& l) { l.resize(l.size() - 50); }),
         "the file was cut short");
  // A row appended at t = 1e9 s (which would widen the window to 1e9 s).
  refuse(editedRun(*dir_, "appended",
                   [](auto& l) {
                     auto f = fields(l.back());
                     f[column(l[0], "t")] = "1000000000";
                     l.push_back(joined(f));
                   }),
         "column t: time 1000000000.000000 s is outside the run (0 to 21.000000 s)");
  // A position of 1e308 m: finite, but its square is not.
  refuse(editedRun(*dir_, "huge",
                   [](auto& l) {
                     auto f = fields(l[100]);
                     f[column(l[0], "z")] = "1e308";
                     l[100] = joined(f);
                   }),
         "timeseries.csv: vehicle cf, t = ");
  // A reference that never moves: no window, nothing to place a log by.
  refuse(editedRun(*dir_, "hover",
                   [](auto& l) {
                     const auto first = fields(l[1]);
                     for (std::size_t i = 1; i < l.size(); ++i) {
                       auto f = fields(l[i]);
                       for (const char* c : {"ref_x", "ref_y", "ref_z"})
                         f[column(l[0], c)] = first[column(l[0], c)];
                       l[i] = joined(f);
                     }
                   }),
         "timeseries.csv: vehicle cf: the reference never moves (a hover)");
}

TEST_F(CompareReal, BadLogsAreRefusedAndFarSamplesAroundTheFlightAreNot) {
  // A position of 1e308 m in the log.
  {
    std::ofstream out(*dir_ / "huge.csv");
    out << "t,x,y,z\n";
    for (int k = 0; k < 30; ++k) out << 0.01 * k << ",1,1," << (k == 7 ? "1e308" : "1") << "\n";
  }
  CommandResult r = compare(*dir_ / "huge.csv", "", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("huge.csv: line 9, column z: '1e308' m is further than 1e6 m from the "
                       "origin: not a flight"),
            std::string::npos)
      << r.err;
  // The flight with one sample 1e7 s before it and one 1e7 s after: a log spanning 2e7 s is
  // searched where its samples are, and the flight is found.
  const auto padded = writeLog("far.csv", 0.7, Eigen::Vector3d::Zero());
  {
    std::string text = slurp(padded);
    const std::size_t header_end = text.find('\n') + 1;
    text.insert(header_end, "-10000000,1,1,1\n");
    text += "10000000,1,1,1\n";
    std::ofstream(padded) << text;
  }
  r = compare(padded);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(jsonNumber(result(), "time_offset_s"), 0.7, 0.02);
  EXPECT_NEAR(jsonNumber(result(), "ratio"), 1.0, 0.02);
  // The flight's samples 1e6 s apart (a log in the wrong unit): nowhere does the window hold
  // ten of them, and the message says there is no overlap.
  {
    std::ofstream out(*dir_ / "sparse.csv");
    out << "t,x,y,z\n";
    for (int k = 0; k < 20; ++k) out << 1e6 * k << ",1,1,1\n";
  }
  r = compare(*dir_ / "sparse.csv", "", "bad");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("sparse.csv: no overlap with the run: wherever the run's reference window"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("the log's samples are 1e+06 s apart"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(*dir_ / "bad" / "compare.json"));
}

}  // namespace
}  // namespace cosim::test
