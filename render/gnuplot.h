#pragma once
// Figures are drawn by the gnuplot program (Debian package gnuplot-nox), driven with a
// generated script: its pngcairo and svg terminals give publication-quality output.
#include <filesystem>
#include <string>

namespace cosim {

// Runs gnuplot on `script` with `work_dir` as its working directory (data files referenced by
// relative names live there). Throws std::runtime_error with gnuplot's messages on failure.
void runGnuplot(const std::string& script, const std::filesystem::path& work_dir);

// A string literal for a gnuplot script (single-quoted; gnuplot doubles inner quotes).
std::string gnuplotString(const std::string& s);

// The terminal lines that make `base`.png and `base`.svg from the same plot commands:
// `plotBoth(base, width, height, body)` is body run once per terminal.
std::string plotBoth(const std::string& base, int width, int height, const std::string& body);

}  // namespace cosim
