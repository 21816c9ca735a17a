#include "experiments/compare/flight_log.h"

#include "core/input_file.h"
#include "experiments/compare/usd_log_reader.h"

namespace cosim {

FlightLog readFlightLog(const std::string& path, const FlightLogOptions& options) {
  std::string bytes = readInputFile(path, kMaxLogFileBytes, "flight log");
  if (looksLikeUsdLog(bytes)) return parseFlightLogUsd(std::move(bytes), path, options);
  return parseFlightLogCsv(bytes, path);
}

}  // namespace cosim
