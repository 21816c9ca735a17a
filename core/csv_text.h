#pragma once
// CSV fields as RFC 4180 writes them: a field with a comma, a quote or a line break is quoted,
// its quotes doubled. Every CSV cosim writes goes through csvField wherever text from the user
// (a vehicle name, a message) can appear, and is read back with splitCsvRecord.
#include <string>
#include <vector>

namespace cosim {

std::string csvField(const std::string& s);

// The fields of one record that lies on one line (cosim's own files never quote a line break:
// the names they hold cannot contain one). Returns false, with `fields` incomplete, if a quoted
// field does not end on the line or a quote stands inside an unquoted field.
bool splitCsvRecord(const std::string& line, std::vector<std::string>& fields);

// The lines of a text, one at a time: the last one too when it has no line break, a '\r' before
// the break dropped (files written on Windows). number() is the line last read, from 1.
class TextLines {
 public:
  explicit TextLines(const std::string& text) : text_(text) {}
  bool next(std::string& line);
  std::size_t number() const { return number_; }

 private:
  const std::string& text_;
  std::size_t pos_ = 0, number_ = 0;
};

}  // namespace cosim
