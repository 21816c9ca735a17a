#include "render/json_flatten.h"

#include <cctype>
#include <stdexcept>

namespace cosim {

namespace {

class Flattener {
 public:
  explicit Flattener(const std::string& s) : s_(s) {}

  std::vector<std::pair<std::string, std::string>> run() {
    value("");
    skipSpace();
    if (i_ != s_.size()) fail("trailing characters");
    return out_;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("malformed JSON at offset " + std::to_string(i_) + ": " + what);
  }
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  char peek() {
    skipSpace();
    if (i_ >= s_.size()) fail("unexpected end");
    return s_[i_];
  }
  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++i_;
  }
  std::string string() {
    expect('"');
    std::string r;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c == '\\') {
        if (i_ >= s_.size()) fail("bad escape");
        const char e = s_[i_++];
        switch (e) {
          case 'n':
            c = '\n';
            break;
          case 't':
            c = '\t';
            break;
          case 'r':
            c = '\r';
            break;
          case 'b':
            c = '\b';
            break;
          case 'f':
            c = '\f';
            break;
          case 'u': {
            if (i_ + 4 > s_.size()) fail("bad \\u escape");
            const unsigned code = static_cast<unsigned>(std::stoul(s_.substr(i_, 4), nullptr, 16));
            i_ += 4;
            c = code < 0x80 ? static_cast<char>(code) : '?';  // metrics are ASCII
            break;
          }
          default:
            c = e;
        }
      }
      r += c;
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return r;
  }
  void value(const std::string& key) {
    const char c = peek();
    if (c == '{') {
      ++i_;
      if (peek() == '}') {
        ++i_;
        return;
      }
      for (;;) {
        const std::string k = string();
        expect(':');
        value(key.empty() ? k : key + "." + k);
        if (peek() == ',') {
          ++i_;
          continue;
        }
        expect('}');
        return;
      }
    }
    if (c == '[') {
      ++i_;
      if (peek() == ']') {
        ++i_;
        return;
      }
      for (int n = 0;; ++n) {
        value(key + "[" + std::to_string(n) + "]");
        if (peek() == ',') {
          ++i_;
          continue;
        }
        expect(']');
        return;
      }
    }
    if (c == '"') {
      out_.emplace_back(key, string());
      return;
    }
    const std::size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.' ||
                              s_[i_] == '-' || s_[i_] == '+'))
      ++i_;
    if (i_ == start) fail("expected a value");
    out_.emplace_back(key, s_.substr(start, i_ - start));
  }

  const std::string& s_;
  std::size_t i_ = 0;
  std::vector<std::pair<std::string, std::string>> out_;
};

}  // namespace

std::vector<std::pair<std::string, std::string>> flattenJson(const std::string& json) {
  return Flattener(json).run();
}

}  // namespace cosim
