#pragma once
// A CSV file as a table of strings (RFC 4180 quoting: "a,b" and "" inside quotes), with the
// header row naming the columns. Used to chart experiment results.
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as long as the header

  // Index of a column; throws InputError(file, column, ...) naming the columns there are.
  std::size_t column(const std::string& name, const std::string& file) const;
};

// Throws InputError naming the file (and line) if it cannot be read or a row has the wrong
// number of fields.
CsvTable readCsvTable(const std::filesystem::path& path);
CsvTable parseCsvTable(const std::string& text, const std::string& file);

}  // namespace cosim
