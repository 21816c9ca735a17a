#pragma once
// ffmpeg as a child process that reads raw frames from a pipe on its stdin.
//
// It runs in a process group of its own, so a Ctrl-C at the terminal (SIGINT to the foreground
// group) reaches cosim only: cosim decides whether the video is finished or abandoned (ffmpeg
// killed, the partial file deleted), instead of ffmpeg dying under it mid-write. ffmpeg never
// touches the terminal from that background group: stdin is the pipe (and -nostdin), and its
// stderr goes to a temporary file that error messages quote. The pipe's write end is
// close-on-exec, so no other child holds it open and ffmpeg sees the end of its input as soon as
// it is closed here.
#include <sys/types.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace cosim {

class FfmpegProcess {
 public:
  // args: ffmpeg's arguments, without the program name. Throws std::runtime_error if ffmpeg
  // cannot be started.
  explicit FfmpegProcess(const std::vector<std::string>& args);
  // Kills ffmpeg if it is still running (an abandoned output) and reaps it.
  ~FfmpegProcess();
  FfmpegProcess(const FfmpegProcess&) = delete;
  FfmpegProcess& operator=(const FfmpegProcess&) = delete;

  // Writes all n bytes to ffmpeg's stdin; false if ffmpeg stopped reading (it exited or was
  // killed). Never raises SIGPIPE, whatever the process's disposition of it.
  bool write(const void* data, std::size_t n);
  // Closes ffmpeg's stdin and waits for it; true if it exited with status 0.
  bool finish();
  // SIGKILL: ffmpeg stops at once, and a write() blocked in another thread returns false.
  void kill();
  // The end of what ffmpeg wrote to stderr, on one line (for error messages).
  std::string errorOutput() const;

 private:
  void closeInput();
  int wait();  // the raw wait status

  pid_t pid_ = -1;
  int input_ = -1;               // write end of the pipe to ffmpeg's stdin
  std::FILE* errors_ = nullptr;  // ffmpeg's stderr (an unnamed temporary file)
};

}  // namespace cosim
