#include "core/input_error.h"

#include <cstdio>

namespace cosim {

std::string printableText(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

std::string quotedExcerpt(const std::string& text, std::size_t max_chars) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < max_chars; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x20 || byte >= 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += text[i];
    }
  }
  return out + (text.size() > max_chars ? "...'" : "'");
}

std::string setAssignmentPlace(const std::string& assignment) {
  constexpr std::size_t kShown = 80;
  return "--set " +
         (assignment.size() > kShown ? assignment.substr(0, kShown) + "..." : assignment);
}

std::string InputError::compose(const std::string& file, const std::string& place,
                                const std::string& problem) {
  std::string s = file.empty() ? std::string("input") : file;
  if (!place.empty()) s += ": " + place;
  return printableText(s + ": " + problem);
}

InputError InputError::inFile(const std::string& file) const {
  return file_.empty() ? InputError(file, place_, problem_) : *this;
}

}  // namespace cosim
