#include "cli/set_options.h"

#include "core/input_error.h"

namespace cosim::cli {

void applySetOptions(const std::vector<std::string>& sets, ParamSet& params) {
  for (const std::string& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("command line", setAssignmentPlace(s), "expected key=value");
    params.set(s.substr(0, eq), s.substr(eq + 1), setAssignmentPlace(s));
  }
}

}  // namespace cosim::cli
