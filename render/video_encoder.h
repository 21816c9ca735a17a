#pragma once
// H.264 MP4 (yuv420p, playable in browsers) and PNG output through the ffmpeg program: frames
// go down a pipe as raw RGB. Files appear under their final name only once complete.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

class VideoEncoder {
 public:
  // Starts ffmpeg; throws std::runtime_error if it cannot.
  VideoEncoder(const std::filesystem::path& path, int width, int height, int fps);
  // Abandons an unfinished video: the partial file is removed.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  void addFrame(const std::vector<std::uint8_t>& rgb);  // width*height*3 bytes, top row first
  // Flushes, waits for ffmpeg and renames the file into place; throws if ffmpeg failed.
  void finish();
  int frames() const { return frames_; }

 private:
  std::filesystem::path path_, tmp_;
  int width_, height_;
  std::FILE* pipe_ = nullptr;
  int frames_ = 0;
};

// Writes one RGB image as PNG (through ffmpeg), atomically.
void writePng(const std::filesystem::path& path, const std::vector<std::uint8_t>& rgb, int width,
              int height);

// Quotes a string for /bin/sh.
std::string shellQuote(const std::string& s);

}  // namespace cosim
