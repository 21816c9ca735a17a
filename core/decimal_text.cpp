#include "core/decimal_text.h"

#include <cctype>
#include <sstream>

namespace cosim {

namespace {

bool isDigit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// Moves `at` past a run of digits; returns how many there were.
std::size_t skipDigits(const std::string& s, std::size_t& at) {
  const std::size_t from = at;
  while (at < s.size() && isDigit(s[at])) ++at;
  return at - from;
}

}  // namespace

bool isDecimalNumberText(const std::string& text) {
  std::size_t at = 0;
  if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
  std::size_t digits = skipDigits(text, at);
  if (at < text.size() && text[at] == '.') {
    ++at;
    digits += skipDigits(text, at);
  }
  if (digits == 0) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
    if (skipDigits(text, at) == 0) return false;
  }
  return at == text.size();
}

std::string tenSignificantDigits(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace cosim
