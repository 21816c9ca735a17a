#include "render/video_encoder.h"

#include <unistd.h>

#include <stdexcept>

#include "core/atomic_file.h"
#include "core/temporary_name.h"

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

// ffmpeg's arguments for raw RGB frames on stdin, then `output` (codec, format, file).
std::vector<std::string> ffmpegArguments(int width, int height, int fps,
                                         const std::vector<std::string>& output) {
  std::vector<std::string> args = {"-nostdin",
                                   "-hide_banner",
                                   "-loglevel",
                                   "error",
                                   "-y",
                                   "-f",
                                   "rawvideo",
                                   "-pix_fmt",
                                   "rgb24",
                                   "-s",
                                   std::to_string(width) + "x" + std::to_string(height),
                                   "-r",
                                   std::to_string(fps),
                                   "-i",
                                   "-"};
  args.insert(args.end(), output.begin(), output.end());
  return args;
}

void removeOutput(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::remove_all(p, ec);
}

std::string ffmpegFailure(const FfmpegProcess& ffmpeg, const std::string& what) {
  const std::string said = ffmpeg.errorOutput();
  return "ffmpeg failed while writing " + what + (said.empty() ? "" : ": " + said);
}

}  // namespace

VideoEncoder::VideoEncoder(const std::filesystem::path& path, int width, int height, int fps,
                           VideoFormat format)
    : path_(path),
      work_(createTemporaryFolder(path, ".part")),
      tmp_(work_ / (format == VideoFormat::Mp4 ? "video.mp4" : "frames")),
      width_(width),
      height_(height),
      format_(format) {
  std::vector<std::string> output;
  if (format == VideoFormat::Mp4) {
    // yuv420p and +faststart: plays in browsers. -preset ultrafast: ffmpeg shares the cores
    // with the rendering threads. Encoding 200 frames of the default run's chase video took
    // 3.1 s of CPU with veryfast, 2.3 s with superfast, 1.4 s with ultrafast (files of 0.6,
    // 1.4 and 2.6 MB): about a tenth of a frame's whole cost saved for a larger file.
    output = {"-c:v",    "libx264",   "-preset",    "ultrafast", "-crf", "20",         "-pix_fmt",
              "yuv420p", "-movflags", "+faststart", "-f",        "mp4",  tmp_.string()};
  } else {
    std::filesystem::create_directory(tmp_);
    output = {"-c:v", "png", "-f", "image2", "-start_number", "1", (tmp_ / "%05d.png").string()};
  }
  try {
    ffmpeg_ = std::make_unique<FfmpegProcess>(ffmpegArguments(width, height, fps, output));
  } catch (...) {
    removeOutput(work_);
    throw;
  }
  writer_ = std::thread([this] { writerLoop(); });
}

void VideoEncoder::writerLoop() {
  const std::size_t n = static_cast<std::size_t>(width_) * height_ * 3;
  for (;;) {
    std::vector<std::uint8_t> frame;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
      if (queue_.empty() || dropping_ || write_failed_) return;  // closing and drained, or given up
      frame = std::move(queue_.front());
      queue_.pop_front();
    }
    const bool ok = ffmpeg_->write(frame.data(), n);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      spare_.push_back(std::move(frame));
      if (!ok) write_failed_ = true;
    }
    changed_.notify_all();
  }
}

void VideoEncoder::stopWriter(bool drop_queued) {
  if (!writer_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
    dropping_ = drop_queued;
  }
  changed_.notify_all();
  // A frame the writer is handing over may be blocked on a full pipe: killing ffmpeg makes that
  // write fail at once instead of waiting for ffmpeg to encode what is queued.
  if (drop_queued) ffmpeg_->kill();
  writer_.join();
}

VideoEncoder::~VideoEncoder() {
  if (!ffmpeg_) return;  // finished (or failed and cleaned up)
  stopWriter(/*drop_queued=*/true);
  ffmpeg_.reset();  // reaps the killed ffmpeg
  removeOutput(work_);
}

void VideoEncoder::fail(const std::string& what) {
  stopWriter(/*drop_queued=*/true);
  ffmpeg_.reset();
  removeOutput(work_);
  throw std::runtime_error(what);
}

void VideoEncoder::addFrame(std::vector<std::uint8_t>& rgb) {
  const std::size_t n = static_cast<std::size_t>(width_) * height_ * 3;
  if (rgb.size() != n) throw std::runtime_error("frame size does not match the video");
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return queue_.size() < kQueuedFrames || write_failed_; });
  if (write_failed_) {
    lock.unlock();
    // ffmpeg has exited: reap it to say why.
    ffmpeg_->kill();
    ffmpeg_->finish();
    fail(ffmpegFailure(*ffmpeg_, path_.string()) + " (it stopped accepting frames)");
  }
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
  stopWriter(/*drop_queued=*/false);
  const bool exited_cleanly = ffmpeg_->finish();
  if (write_failed_ || !exited_cleanly) fail(ffmpegFailure(*ffmpeg_, path_.string()));
  ffmpeg_.reset();
  try {
    moveIntoPlace(tmp_, path_);
  } catch (...) {
    removeOutput(work_);
    throw;
  }
  removeOutput(work_);
}

void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb, int width,
              int height) {
  const std::size_t n = static_cast<std::size_t>(width) * height * 3;
  if (rgb.size() != n) throw std::runtime_error("image size does not match for " + path.string());
  // ffmpeg writes into a new folder of this process's own (it follows what is at its name).
  const std::filesystem::path work = createTemporaryFolder(path, ".part");
  const std::filesystem::path tmp = work / "frame.png";
  try {
    FfmpegProcess ffmpeg(ffmpegArguments(
        width, height, 1, {"-frames:v", "1", "-c:v", "png", "-f", "image2", tmp.string()}));
    const bool written = ffmpeg.write(rgb.data(), n);
    if (!ffmpeg.finish() || !written)
      throw std::runtime_error(ffmpegFailure(ffmpeg, path.string()));
    moveIntoPlace(tmp, path);
  } catch (...) {
    removeOutput(work);
    throw;
  }
  removeOutput(work);
}

}  // namespace cosim
