#include "render/video_encoder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>

namespace cosim {

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

namespace {

std::string rawInput(int width, int height, int fps) {
  return "ffmpeg -nostdin -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " +
         std::to_string(width) + "x" + std::to_string(height) + " -r " + std::to_string(fps) +
         " -i - ";
}

std::filesystem::path temporaryName(const std::filesystem::path& path) {
  std::string name = ".";  // piece by piece: GCC 12's -Wrestrict misfires on operator+ chains
  name += path.filename().string();
  name += ".part";
  name += std::to_string(getpid());
  return path.parent_path() / name;
}

void closePipe(std::FILE* pipe, const std::filesystem::path& tmp, const std::string& what) {
  const int status = pclose(pipe);
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(tmp);
    throw std::runtime_error("ffmpeg failed while writing " + what);
  }
}

}  // namespace

VideoEncoder::VideoEncoder(const std::filesystem::path& path, int width, int height, int fps)
    : path_(path), tmp_(temporaryName(path)), width_(width), height_(height) {
  // yuv420p and +faststart: plays in browsers; -preset veryfast keeps encoding off the
  // critical path of rendering.
  const std::string cmd = rawInput(width, height, fps) +
                          "-c:v libx264 -preset veryfast -crf 20 -pix_fmt yuv420p "
                          "-movflags +faststart -f mp4 " +
                          shellQuote(tmp_.string());
  pipe_ = popen(cmd.c_str(), "w");
  if (!pipe_) throw std::runtime_error("cannot start ffmpeg (is it installed?)");
}

VideoEncoder::~VideoEncoder() {
  if (pipe_) {
    pclose(pipe_);
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void VideoEncoder::addFrame(const std::vector<std::uint8_t>& rgb) {
  const std::size_t n = static_cast<std::size_t>(width_) * height_ * 3;
  if (rgb.size() != n) throw std::runtime_error("frame size does not match the video");
  if (std::fwrite(rgb.data(), 1, n, pipe_) != n)
    throw std::runtime_error("ffmpeg stopped accepting frames for " + path_.string());
  ++frames_;
}

void VideoEncoder::finish() {
  std::FILE* p = pipe_;
  pipe_ = nullptr;
  closePipe(p, tmp_, path_.string());
  std::filesystem::rename(tmp_, path_);
}

void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb, int width,
              int height) {
  const std::filesystem::path tmp = temporaryName(path);
  const std::string cmd = rawInput(width, height, 1) + "-frames:v 1 -c:v png -f image2 " +
                          shellQuote(tmp.string());
  std::FILE* pipe = popen(cmd.c_str(), "w");
  if (!pipe) throw std::runtime_error("cannot start ffmpeg (is it installed?)");
  const std::size_t n = static_cast<std::size_t>(width) * height * 3;
  const bool ok = rgb.size() == n && std::fwrite(rgb.data(), 1, n, pipe) == n;
  closePipe(pipe, tmp, path.string());
  if (!ok) {
    std::filesystem::remove(tmp);
    throw std::runtime_error("cannot write " + path.string());
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace cosim
