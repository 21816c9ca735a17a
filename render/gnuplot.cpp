#include "render/gnuplot.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/atomic_file.h"
#include "core/display_text.h"
#include "core/stop_request.h"
#include "core/stop_requested_error.h"
#include "core/temporary_name.h"

extern char** environ;

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
  for (char c : displayText(s)) q += (c == '\'') ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string wellFormedSvgText(const std::string& svg) {
  static const std::string kCdataOpen = "<![CDATA[", kCdataClose = "]]>";
  std::string out;
  out.reserve(svg.size());
  for (std::size_t at = 0; at < svg.size();) {
    const std::size_t cdata = svg.find(kCdataOpen, at), close = svg.find(kCdataClose, at);
    if (close == std::string::npos) {
      out.append(svg, at, std::string::npos);
      break;
    }
    if (cdata < close) {  // a CDATA section is copied whole: its "]]>" ends it
      const std::size_t end = close + kCdataClose.size();
      out.append(svg, at, end - at);
      at = end;
      continue;
    }
    out.append(svg, at, close - at).append("]]&gt;");
    at = close + kCdataClose.size();
  }
  return out;
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

namespace {

// gnuplot on plot.gp in `work_dir`, its output into plot.log there, in a process group of its
// own (a Ctrl-C at the terminal reaches cosim only, which then ends gnuplot itself) with the
// default dispositions of the signals cosim handles or ignores. Its pid.
pid_t spawnGnuplot(const std::filesystem::path& work_dir) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, work_dir.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "plot.log",
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  for (int sig : {SIGPIPE, SIGINT, SIGTERM}) sigaddset(&defaults, sig);
  sigemptyset(&none);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::string program = "gnuplot", script = "plot.gp";
  char* argv[] = {program.data(), script.data(), nullptr};
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, "gnuplot", &actions, &attr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (rc != 0)
    throw std::runtime_error(std::string("cannot start gnuplot (is gnuplot-nox installed?): ") +
                             std::strerror(rc));
  return pid;
}

}  // namespace

void runGnuplot(const std::string& script, const std::filesystem::path& work_dir) {
  const std::filesystem::path script_file = work_dir / "plot.gp", log_file = work_dir / "plot.log";
  if (stopRequested()) throw StopRequestedError("stopped before plotting");
  {
    std::ofstream out(script_file);
    out << script;
    if (!out) throw std::runtime_error("cannot write " + script_file.string());
  }
  const pid_t pid = spawnGnuplot(work_dir);
  // Waits for gnuplot, looking at the stop request every 10 ms: a stop ends gnuplot at once
  // (a figure of 500 flights takes it many seconds).
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR)) break;
    if (stopRequested()) {
      kill(pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      throw StopRequestedError("gnuplot stopped");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(log_file);
    std::ostringstream msg;
    msg << in.rdbuf();
    throw std::runtime_error("gnuplot failed (is gnuplot-nox installed?): " +
                             msg.str().substr(0, 600));
  }
  // Every SVG the script made, its text made well-formed before anyone publishes it.
  for (const auto& entry : std::filesystem::directory_iterator(work_dir)) {
    if (entry.path().extension() != ".svg" || !entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string fixed = wellFormedSvgText(text.str());
    if (fixed.size() == text.str().size()) continue;
    in.close();
    std::ofstream out(entry.path(), std::ios::binary | std::ios::trunc);
    out << fixed;
    if (!out) throw std::runtime_error("cannot write " + entry.path().string());
  }
}

}  // namespace cosim
