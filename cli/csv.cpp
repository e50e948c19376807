#include "cli/csv.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cli/output_file.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

namespace {

// A spreadsheet's save is read as ours: spaces around fields and a Windows line end are dropped.
std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  return first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) out.push_back(trimmed(field));
  if (const std::string whole = trimmed(line); !whole.empty() && whole.back() == ',') out.emplace_back();  // a trailing empty field
  return out;
}

}  // namespace

const std::string& CsvTable::text(size_t row, const std::string& column) const {
  const auto it = std::find(columns.begin(), columns.end(), column);
  if (it == columns.end()) throw OptionError(fmt::format("{}: no column '{}'", path, column));
  return rows.at(row)[it - columns.begin()];
}

double CsvTable::number(size_t row, const std::string& column) const {
  const std::string& field = text(row, column);
  const size_t line = row < lineOfRow.size() ? lineOfRow[row] : row + 2;
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (field.empty() || *end != '\0')
    throw OptionError(
        fmt::format("{}, line {}: '{}' in column '{}' is not a number", path, line, field, column));
  if (!std::isfinite(value))  // a figure no measurement gives: drawn, it would vanish without a word
    throw OptionError(fmt::format("{}, line {}: '{}' in column '{}' is not a finite number", path, line,
                                         field, column));
  return value;
}

CsvTable readCsv(const std::string& path, const std::string& writtenBy) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw OptionError(fmt::format("{}: is a folder, not a CSV file{}", path,
                                         writtenBy.empty() ? "" : "; " + writtenBy + " writes it"));
  std::ifstream in(path);
  if (!in)
    throw OptionError(fmt::format("{}: cannot read ({}){}", path, std::strerror(errno),
                                         writtenBy.empty() ? "" : "; " + writtenBy + " writes it"));
  CsvTable table;
  table.path = path;
  std::string line;
  if (!std::getline(in, line)) throw OptionError(path + ": empty, expected a header line");
  if (line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);  // the byte-order mark some editors write
  table.columns = fields(line);
  for (size_t c = 0; c < table.columns.size(); ++c)
    if (std::count(table.columns.begin(), table.columns.begin() + c, table.columns[c]))
      throw OptionError(fmt::format("{}: column '{}' appears twice in the header", path, table.columns[c]));
  size_t lineNumber = 1;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (trimmed(line).empty()) continue;  // blank lines (an editor's last one) hold no row
    table.rows.push_back(fields(line));
    table.lineOfRow.push_back(lineNumber);
    if (table.rows.back().size() != table.columns.size())
      throw OptionError(fmt::format("{}, line {}: {} fields under a header of {}", path, lineNumber,
                                           table.rows.back().size(), table.columns.size()));
  }
  return table;
}

void writeCsv(const std::string& path, const CsvTable& table) {
  std::ofstream out = openOutput(path);
  fmt::print(out, "{}\n", fmt::join(table.columns, ","));
  for (const auto& row : table.rows) fmt::print(out, "{}\n", fmt::join(row, ","));
  if (!out) throw std::runtime_error(path + ": write failed (disk full?)");
}

}  // namespace radmesh::cli
