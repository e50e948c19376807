#pragma once
// The CSV tables the benches write and the docs' figures are drawn from: a header line, then a line
// per row; fields hold no commas, quotes or line breaks.
#include <string>
#include <vector>

namespace radmesh::cli {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows{};
  std::string path{};  // where it was read from, for messages
  std::vector<size_t> lineOfRow{};  // each row's line in that file (blank lines are skipped)

  // Throw std::runtime_error naming the file, the column and the line when it is missing or not a number.
  const std::string& text(size_t row, const std::string& column) const;
  double number(size_t row, const std::string& column) const;
};

// Throws naming the file and the line of a row of the wrong width, or of a header naming a column
// twice; reads a spreadsheet's save as ours (a byte-order mark, Windows line ends, spaces around
// fields, blank lines); a file it cannot open, with
// why and `writtenBy` (the command that writes it), when given.
CsvTable readCsv(const std::string& path, const std::string& writtenBy = "");
void writeCsv(const std::string& path, const CsvTable& table);

}  // namespace radmesh::cli
