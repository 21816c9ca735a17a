#pragma once
// H.264 MP4 (yuv420p, playable in browsers), a PNG frame sequence, or a single PNG, through
// the ffmpeg program (render/ffmpeg_process.h): frames go down a pipe as raw RGB. Writing to the
// pipe happens on a separate thread, so the caller renders the next frame while this one is
// handed over and ffmpeg (another process) encodes. Outputs appear under their final name only
// once complete; an abandoned one (an exception, an interrupt) is deleted.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/ffmpeg_process.h"

namespace cosim {

enum class VideoFormat {
  Mp4,          // path is the .mp4 file
  PngSequence,  // path is a folder; frames are 00001.png, 00002.png, ...
};

class VideoEncoder {
 public:
  // Starts ffmpeg; throws std::runtime_error if it cannot.
  VideoEncoder(const std::filesystem::path& path, int width, int height, int fps,
               VideoFormat format = VideoFormat::Mp4);
  // Abandons an unfinished video at once: queued frames are dropped, ffmpeg is killed and the
  // partial output removed.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // width*height*3 bytes, top row first. Takes the frame's buffer (rgb is left with a buffer
  // of the same size to render the next frame into, avoiding reallocation).
  void addFrame(std::vector<std::uint8_t>& rgb);
  // Flushes, waits for ffmpeg and renames the output into place; throws if ffmpeg failed.
  void finish();
  int frames() const { return frames_; }

 private:
  void writerLoop();
  void stopWriter(bool drop_queued);
  [[noreturn]] void fail(const std::string& what);

  // work_: a new folder of this process's own beside path_ (core/temporary_name.h), holding
  // tmp_, what ffmpeg writes (ffmpeg follows whatever is at the name it is given).
  std::filesystem::path path_, work_, tmp_;
  int width_, height_;
  VideoFormat format_;
  std::unique_ptr<FfmpegProcess> ffmpeg_;  // null once finished
  int frames_ = 0;
  // Frames waiting for the writer thread, and spare buffers to swap in.
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<std::uint8_t>> queue_, spare_;
  bool closing_ = false, dropping_ = false, write_failed_ = false;
  std::thread writer_;
};

// Writes one RGB image as PNG (through ffmpeg), atomically.
void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb, int width,
              int height);

// Quotes a string for /bin/sh.
std::string shellQuote(const std::string& s);

}  // namespace cosim
