#include "cli/csv.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cli/output_file.h"

namespace radmesh::cli {

namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();  // a trailing empty field
  return out;
}

}  // namespace

const std::string& CsvTable::text(size_t row, const std::string& column) const {
  const auto it = std::find(columns.begin(), columns.end(), column);
  if (it == columns.end()) throw std::runtime_error(fmt::format("{}: no column '{}'", path, column));
  return rows.at(row)[it - columns.begin()];
}

double CsvTable::number(size_t row, const std::string& column) const {
  const std::string& field = text(row, column);
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (field.empty() || *end != '\0')
    throw std::runtime_error(
        fmt::format("{}, line {}: '{}' in column '{}' is not a number", path, row + 2, field, column));
  return value;
}

CsvTable readCsv(const std::string& path, const std::string& writtenBy) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw std::runtime_error(fmt::format("{}: is a folder, not a CSV file{}", path,
                                         writtenBy.empty() ? "" : "; " + writtenBy + " writes it"));
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(fmt::format("{}: cannot read ({}){}", path, std::strerror(errno),
                                         writtenBy.empty() ? "" : "; " + writtenBy + " writes it"));
  CsvTable table;
  table.path = path;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty, expected a header line");
  table.columns = fields(line);
  while (std::getline(in, line)) {
    table.rows.push_back(fields(line));
    if (table.rows.back().size() != table.columns.size())
      throw std::runtime_error(fmt::format("{}, line {}: {} fields under a header of {}", path, table.rows.size() + 1,
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
