#pragma once
// Who takes a parameter, in a message: "planner theta_star" or "planners a_star, theta_star".
#include <string>
#include <vector>

namespace cosim {

// `kind` (singular, e.g. "planner") and the names, comma-separated, with an "s" on the kind when
// there are several.
inline std::string ownerList(const std::string& kind, const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return kind + (names.size() == 1 ? " " : "s ") + list;
}

}  // namespace cosim
