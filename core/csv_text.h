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

}  // namespace cosim
