#include "experiments/sweep/job_result.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/json_reading.h"
#include "core/json_writer.h"

namespace cosim {

const char* jobStatusName(JobStatus s) {
  switch (s) {
    case JobStatus::Ok:
      return "ok";
    case JobStatus::Failed:
      return "failed";
    case JobStatus::Timeout:
      return "timeout";
    case JobStatus::Crashed:
      return "crashed";
    case JobStatus::BadInput:
      return "bad_input";
  }
  return "crashed";
}

std::optional<JobStatus> jobStatusNamed(const std::string& name) {
  for (const JobStatus s : {JobStatus::Ok, JobStatus::Failed, JobStatus::Timeout,
                            JobStatus::Crashed, JobStatus::BadInput})
    if (name == jobStatusName(s)) return s;
  return std::nullopt;
}

JobStatus classifyJobExit(int wait_status, bool timed_out) {
  if (timed_out) return JobStatus::Timeout;
  if (wait_status == -1 || !WIFEXITED(wait_status)) return JobStatus::Crashed;
  switch (WEXITSTATUS(wait_status)) {
    case 0:
      return JobStatus::Ok;
    case 1:
      return JobStatus::Failed;
    case 2:
      return JobStatus::BadInput;
    default:
      return JobStatus::Crashed;  // 3 internal error, 127 cannot exec, ...
  }
}

std::string programBuildIdentity(const std::string& program) {
  struct stat st {};
  if (::stat(program.c_str(), &st) != 0) return "unknown";
  return std::to_string(static_cast<long long>(st.st_size)) + "@" +
         std::to_string(static_cast<long long>(st.st_mtime));
}

void writeJobResult(const std::filesystem::path& job_dir, const JobResult& r) {
  JsonObject j;
  j.add("job", r.job)
      .add("fingerprint", r.fingerprint)
      .add("scenario", r.scenario)
      .add("status", jobStatusName(r.status))
      .add("exit_code", r.exit_code)
      .add("signal", r.signal)
      .add("wall_time_s", r.wall_time_s)
      .add("program_build", r.program_build);
  writeFileAtomically(job_dir / "result.json", j.str() + "\n");
}

std::optional<JobResult> readJobResult(const std::filesystem::path& job_dir) {
  std::error_code ec;
  if (!std::filesystem::exists(job_dir / "result.json", ec)) return std::nullopt;
  try {
    const nlohmann::ordered_json n = readJsonFile(job_dir / "result.json");
    JobResult r;
    r.job = n.at("job").get<std::size_t>();
    r.fingerprint = n.at("fingerprint").get<std::string>();
    r.scenario = n.at("scenario").get<std::string>();
    const std::optional<JobStatus> status = jobStatusNamed(n.at("status").get<std::string>());
    if (!status) return std::nullopt;  // a status no runner writes
    r.status = *status;
    r.exit_code = n.at("exit_code").get<int>();
    r.signal = n.at("signal").get<int>();
    r.wall_time_s = n.at("wall_time_s").get<double>();
    if (n.contains("program_build")) r.program_build = n.at("program_build").get<std::string>();
    return r;
  } catch (const InputError&) {
    return std::nullopt;  // unreadable or not JSON
  } catch (const nlohmann::ordered_json::exception&) {
    return std::nullopt;  // a field missing or of the wrong type
  }
}

}  // namespace cosim
