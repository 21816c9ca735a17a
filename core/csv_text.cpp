#include "core/csv_text.h"

namespace cosim {

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

bool splitCsvRecord(const std::string& line, std::vector<std::string>& fields) {
  fields.clear();
  std::string field;
  std::size_t i = 0;
  for (;;) {
    field.clear();
    if (i < line.size() && line[i] == '"') {
      // Quoted: up to the closing quote; "" is a quote.
      for (++i;; ++i) {
        if (i >= line.size()) return false;
        if (line[i] != '"') {
          field += line[i];
        } else if (i + 1 < line.size() && line[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          ++i;
          break;
        }
      }
      if (i < line.size() && line[i] != ',') return false;
    } else {
      for (; i < line.size() && line[i] != ','; ++i) {
        if (line[i] == '"') return false;
        field += line[i];
      }
    }
    fields.push_back(field);
    if (i >= line.size()) return true;
    ++i;  // the comma
  }
}

bool TextLines::next(std::string& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t stop = text_.find('\n', pos_);
  if (stop == std::string::npos) stop = text_.size();
  line = text_.substr(pos_, stop - pos_);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  pos_ = stop + 1;
  ++number_;
  return true;
}

}  // namespace cosim
