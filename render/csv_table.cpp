#include "render/csv_table.h"

#include <fstream>
#include <sstream>

#include "core/input_error.h"

namespace cosim {

std::size_t CsvTable::column(const std::string& name, const std::string& file) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  std::string have;
  for (const auto& h : header) have += (have.empty() ? "" : ", ") + h;
  throw InputError(file, "column " + name, "no such column (the header has: " + have + ")");
}

CsvTable parseCsvTable(const std::string& text, const std::string& file) {
  CsvTable t;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, any = false;
  int line = 1, row_line = 1;
  const auto endRow = [&] {
    row.push_back(field);
    field.clear();
    if (t.header.empty()) {
      t.header = row;
    } else if (!(row.size() == 1 && row[0].empty())) {  // blank lines are skipped
      if (row.size() != t.header.size())
        throw InputError(file, "line " + std::to_string(row_line),
                         std::to_string(row.size()) + " fields where the header has " +
                             std::to_string(t.header.size()));
      t.rows.push_back(row);
    }
    row.clear();
    any = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        field += c;
      }
      continue;
    }
    if (!any) row_line = line;
    any = true;
    if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(field);
      field.clear();
    } else if (c == '\n') {
      endRow();
      ++line;
    } else if (c != '\r') {
      field += c;
    }
  }
  if (quoted)
    throw InputError(file, "line " + std::to_string(row_line), "unterminated quoted field");
  if (any) endRow();
  if (t.header.empty()) throw InputError(file, "", "empty CSV file (no header row)");
  return t;
}

CsvTable readCsvTable(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open");
  std::ostringstream s;
  s << in.rdbuf();
  return parseCsvTable(s.str(), path.string());
}

}  // namespace cosim
