#include "render/gnuplot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/temporary_name.h"
#include "render/video_encoder.h"

namespace cosim {

GnuplotScratch::GnuplotScratch(const std::filesystem::path& out_base, const std::string& tag)
    : out_dir_(out_base.has_parent_path() ? out_base.parent_path() : std::filesystem::path(".")),
      out_base_name_(out_base.filename()),
      // A new folder of this process's own: nothing already at the name is followed or removed.
      work_(createTemporaryFolder(out_dir_ / tag, ".part")) {}

GnuplotScratch::~GnuplotScratch() {
  std::error_code ec;
  std::filesystem::remove_all(work_, ec);
}

void GnuplotScratch::write(const std::string& name, const std::string& text) const {
  std::ofstream out(work_ / name);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + (work_ / name).string());
}

void GnuplotScratch::publish(const std::string& name) const {
  const std::string base = out_base_name_.string();
  moveIntoPlace(work_ / (name + ".png"), out_dir_ / (base + ".png"));
  moveIntoPlace(work_ / (name + ".svg"), out_dir_ / (base + ".svg"));
}

std::string gnuplotNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string gnuplotString(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string plotBoth(const std::string& base, int width, int height, const std::string& body) {
  std::ostringstream s;
  s << "set terminal pngcairo size " << width << "," << height
    << " noenhanced font 'DejaVu Sans,11' linewidth 1.2\n"
    << "set output " << gnuplotString(base + ".png") << "\n"
    << body << "\nunset output\n"
    << "set terminal svg size " << width << "," << height
    << " dynamic noenhanced font 'DejaVu Sans,11' linewidth 1.2 background '#ffffff'\n"
    << "set output " << gnuplotString(base + ".svg") << "\n"
    << body << "\nunset output\n";
  return s.str();
}

void runGnuplot(const std::string& script, const std::filesystem::path& work_dir) {
  const std::filesystem::path script_file = work_dir / "plot.gp", log_file = work_dir / "plot.log";
  {
    std::ofstream out(script_file);
    out << script;
    if (!out) throw std::runtime_error("cannot write " + script_file.string());
  }
  const std::string cmd =
      "cd " + shellQuote(work_dir.string()) + " && gnuplot plot.gp > plot.log 2>&1";
  const int status = std::system(cmd.c_str());
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(log_file);
    std::ostringstream msg;
    msg << in.rdbuf();
    throw std::runtime_error("gnuplot failed (is gnuplot-nox installed?): " +
                             msg.str().substr(0, 600));
  }
}

}  // namespace cosim
