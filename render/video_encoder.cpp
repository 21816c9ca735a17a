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

// At most this many frames wait for the pipe: rendering runs ahead of encoding by one or two
// frames, and memory stays bounded.
constexpr std::size_t kQueuedFrames = 2;

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
    std::error_code ec;
    std::filesystem::remove_all(tmp, ec);
    throw std::runtime_error("ffmpeg failed while writing " + what);
  }
}

}  // namespace

VideoEncoder::VideoEncoder(const std::filesystem::path& path, int width, int height, int fps,
                           VideoFormat format)
    : path_(path), tmp_(temporaryName(path)), width_(width), height_(height), format_(format) {
  std::string cmd = rawInput(width, height, fps);
  if (format == VideoFormat::Mp4) {
    // yuv420p and +faststart: plays in browsers. -preset superfast: ffmpeg shares the two
    // cores with software rendering; against veryfast it raised the pipeline from 65 % to 79 %
    // of the bare render rate (cosim bench --section render_pipeline) at a somewhat larger file.
    cmd += "-c:v libx264 -preset superfast -crf 20 -pix_fmt yuv420p -movflags +faststart -f mp4 " +
           shellQuote(tmp_.string());
  } else {
    std::error_code ec;
    std::filesystem::remove_all(tmp_, ec);
    std::filesystem::create_directories(tmp_);
    cmd += "-c:v png -f image2 -start_number 1 " + shellQuote((tmp_ / "%05d.png").string());
  }
  pipe_ = popen(cmd.c_str(), "w");
  if (!pipe_) throw std::runtime_error("cannot start ffmpeg (is it installed?)");
  writer_ = std::thread([this] { writerLoop(); });
}

void VideoEncoder::writerLoop() {
  const std::size_t n = static_cast<std::size_t>(width_) * height_ * 3;
  for (;;) {
    std::vector<std::uint8_t> frame;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
      if (queue_.empty()) return;  // closing and drained
      frame = std::move(queue_.front());
      queue_.pop_front();
    }
    const bool ok = std::fwrite(frame.data(), 1, n, pipe_) == n;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      spare_.push_back(std::move(frame));
      if (!ok) write_failed_ = true;
    }
    changed_.notify_all();
  }
}

void VideoEncoder::stopWriter() {
  if (!writer_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  writer_.join();
}

VideoEncoder::~VideoEncoder() {
  stopWriter();
  if (pipe_) {
    pclose(pipe_);
    std::error_code ec;
    std::filesystem::remove_all(tmp_, ec);
  }
}

void VideoEncoder::addFrame(std::vector<std::uint8_t>& rgb) {
  const std::size_t n = static_cast<std::size_t>(width_) * height_ * 3;
  if (rgb.size() != n) throw std::runtime_error("frame size does not match the video");
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < kQueuedFrames || write_failed_; });
  if (write_failed_)
    throw std::runtime_error("ffmpeg stopped accepting frames for " + path_.string());
  queue_.push_back(std::move(rgb));
  if (!spare_.empty()) {
    rgb = std::move(spare_.front());
    spare_.pop_front();
  }
  rgb.resize(n);
  lock.unlock();
  changed_.notify_all();
  ++frames_;
}

void VideoEncoder::finish() {
  stopWriter();
  std::FILE* p = pipe_;
  pipe_ = nullptr;
  closePipe(p, tmp_, path_.string());
  if (write_failed_) {
    std::error_code ec;
    std::filesystem::remove_all(tmp_, ec);
    throw std::runtime_error("ffmpeg stopped accepting frames for " + path_.string());
  }
  if (format_ == VideoFormat::PngSequence) {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);  // a folder cannot be renamed over a non-empty one
  }
  std::filesystem::rename(tmp_, path_);
}

void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb, int width,
              int height) {
  const std::filesystem::path tmp = temporaryName(path);
  const std::string cmd =
      rawInput(width, height, 1) + "-frames:v 1 -c:v png -f image2 " + shellQuote(tmp.string());
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
