#pragma once
// JOBDIR/result.json: written (atomically) by the sweep runner after a job's process has ended.
// Its presence is what makes a job finished: a resumed sweep skips it, the merge reads it.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace cosim {

enum class JobStatus { Ok, Failed, Timeout, Crashed, BadInput };
const char* jobStatusName(JobStatus s);  // ok, failed, timeout, crashed, bad_input
// The status of a name jobStatusName gives; nullopt for any other text.
std::optional<JobStatus> jobStatusNamed(const std::string& name);

// From waitpid's status (-1: unknown) and whether the runner killed the job for its time limit.
// `cosim run` exits 0 (ok), 1 (task failed), 2 (bad input); anything else, or a signal, is a crash.
JobStatus classifyJobExit(int wait_status, bool timed_out);

struct JobResult {
  std::size_t job = 0;
  std::string fingerprint;
  std::string scenario;
  JobStatus status = JobStatus::Crashed;  // result.json holds its jobStatusName
  int exit_code = -1;                     // -1 when ended by a signal
  int signal = 0;
  double wall_time_s = 0.0;
  // Which build of the job program ran it (size and modification time of the executable): a
  // sweep resumed after a rebuild mixes builds, which the merge reports.
  std::string program_build;
};

// The build identity of an executable file (following symlinks such as /proc/self/exe).
std::string programBuildIdentity(const std::string& program);

void writeJobResult(const std::filesystem::path& job_dir, const JobResult& r);
// nullopt if missing or unreadable (then the job is not finished).
std::optional<JobResult> readJobResult(const std::filesystem::path& job_dir);

}  // namespace cosim
