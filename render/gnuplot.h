#pragma once
// Figures are drawn by the gnuplot program (Debian package gnuplot-nox), driven with a
// generated script: its pngcairo and svg terminals give publication-quality output.
#include <filesystem>
#include <string>

namespace cosim {

// Runs gnuplot on `script` with `work_dir` as its working directory (data files referenced by
// relative names live there); the SVG files it made there are then made well-formed
// (wellFormedSvgText). Throws std::runtime_error with gnuplot's messages on failure, and
// StopRequestedError (core/stop_requested_error.h) if a stop request came first or while gnuplot
// ran (gnuplot is then killed and reaped).
void runGnuplot(const std::string& script, const std::filesystem::path& work_dir);

// A scratch folder for one figure, beside its outputs (`out_base`'s folder): gnuplot runs in it,
// and publish() renames the finished PNG and SVG out of it, so each output appears complete or
// not at all. The folder and whatever is left in it go when this object does.
class GnuplotScratch {
 public:
  GnuplotScratch(const std::filesystem::path& out_base, const std::string& tag);
  ~GnuplotScratch();
  GnuplotScratch(const GnuplotScratch&) = delete;
  GnuplotScratch& operator=(const GnuplotScratch&) = delete;

  const std::filesystem::path& dir() const { return work_; }
  // Writes a data file into the folder; throws std::runtime_error if it cannot.
  void write(const std::string& name, const std::string& text) const;
  // Renames `name`.png and `name`.svg from the folder to out_base.png and out_base.svg.
  void publish(const std::string& name) const;

 private:
  std::filesystem::path out_dir_, out_base_name_, work_;
};

// A number for a gnuplot script or data file: six significant digits (printf's %.6g).
std::string gnuplotNumber(double v);

// A string literal for a gnuplot script: single-quoted, in which gnuplot reads every character
// as itself but the quote (doubled); the terminals are noenhanced, so '@', '^', '_', '{', '}' and
// '&' are plain text too. Control bytes and bytes that are not UTF-8 (a file name may hold any)
// are written as the text \xNN: a line break would end the script's line, and neither is
// allowed in the SVG's XML.
std::string gnuplotString(const std::string& s);

// gnuplot's SVG with its text made well-formed XML: the svg terminal escapes '<' and '&' in
// labels but not '>', and "]]>" may not stand in XML character data (a vehicle named q"x'y]]>
// made error.svg unreadable); outside CDATA sections it becomes "]]&gt;". runGnuplot applies it
// to every SVG its script writes.
std::string wellFormedSvgText(const std::string& svg);

// The terminal lines that make `base`.png and `base`.svg from the same plot commands:
// `plotBoth(base, width, height, body)` is body run once per terminal.
std::string plotBoth(const std::string& base, int width, int height, const std::string& body);

}  // namespace cosim
