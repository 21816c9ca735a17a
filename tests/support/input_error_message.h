#pragma once
// The message of the InputError `build` throws, or "no InputError": for tests that assert a bad
// input's one line.
#include <functional>
#include <string>

#include "core/input_error.h"

namespace cosim::test {

inline std::string inputErrorMessageOf(const std::function<void()>& build) {
  try {
    build();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

}  // namespace cosim::test
