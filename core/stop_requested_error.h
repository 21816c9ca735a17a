#pragma once
// Thrown by work that a stop request (core/stop_request.h) ended midway, such as a child
// process killed or a stage abandoned: whoever catches it writes nothing that looks finished;
// the program says "interrupted" and exits 1.
#include <stdexcept>
#include <string>

namespace cosim {

class StopRequestedError : public std::runtime_error {
 public:
  explicit StopRequestedError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace cosim
