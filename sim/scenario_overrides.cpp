#include "sim/scenario_overrides.h"

namespace cosim {

namespace {

// Whether `key` is `path` or lies under it ("planner.name" under "planner", "a[2]" under "a").
bool keyIsUnder(const std::string& key, const std::string& path) {
  return key.compare(0, path.size(), path) == 0 &&
         (key.size() == path.size() || key[path.size()] == '.' || key[path.size()] == '[');
}

}  // namespace

std::string overrideBehind(const std::vector<std::string>& overrides, const std::string& key,
                           bool created) {
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string path = o->substr(0, o->find('='));
    if (keyIsUnder(key, path) || (created && keyIsUnder(path, key))) return *o;
  }
  return "";
}

std::string overridePlace(const std::string& assignment, const std::string& key) {
  return setAssignmentPlace(assignment) + ", key " + key;
}

InputError placedAtOverride(const InputError& e, const std::string& file,
                            const std::vector<std::string>& overrides) {
  const std::string& place = e.place();
  if (e.file() != file || overrides.empty()) return e;
  std::size_t key_at = std::string::npos;
  const bool positioned = place.rfind("line ", 0) == 0;
  if (positioned && place.find(", key ") != std::string::npos)
    key_at = place.find(", key ") + 6;
  else if (place.rfind("key ", 0) == 0)
    key_at = 4;
  if (key_at == std::string::npos) return e;
  const std::string key = place.substr(key_at);
  const std::string assignment = overrideBehind(overrides, key, !positioned);
  return assignment.empty() ? e : InputError(file, overridePlace(assignment, key), e.problem());
}

}  // namespace cosim
