#include "solver/io/mgf_reader.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "solver/io/mgf_error.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

std::vector<std::string> splitWords(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

}  // namespace

std::vector<MgfEntity> readMgfEntities(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneError(path, "", "cannot be opened", "check that the file exists and is readable");
  // Lines end in LF, CR LF (Windows) or CR alone (classic Mac OS, which read as one line).
  const std::string raw{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw SceneError(path, "", "could not be read", "check the file system and permissions");
  std::string text;
  text.reserve(raw.size());
  for (size_t i = 0; i < raw.size(); ++i)
    if (raw[i] != '\r') text += raw[i];
    else if (i + 1 == raw.size() || raw[i + 1] != '\n') text += '\n';
  std::istringstream lines(text);
  std::vector<MgfEntity> entities;
  std::string pending;  // text of an entity continued over several lines
  int start = 0;
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);  // the byte-order mark some editors write
    if (pending.empty()) start = number;
    const bool continues = !line.empty() && line.back() == '\\';
    if (continues) line.back() = ' ';  // the escaped newline counts as a space
    pending += line;
    pending += ' ';
    if (continues) continue;
    std::vector<std::string> words = splitWords(pending);
    pending.clear();
    if (words.empty() || words[0][0] == '#') continue;
    entities.push_back({start, std::move(words)});
  }
  if (!pending.empty() && !splitWords(pending).empty())
    throw SceneError(path, "line " + std::to_string(start),
                     "the file ends inside an entity continued with a backslash (truncated file?)",
                     "restore the end of the file or remove the trailing backslash");
  return entities;
}

void requireMgfArguments(const MgfEntity& entity, size_t minimum, size_t maximum,
                         const std::string& usage) {
  const size_t count = entity.words.size() - 1;
  if (count >= minimum && count <= maximum) return;
  throw MgfError("wrong number of arguments (" + std::to_string(count) + ")",
                 "write it as: " + usage);
}

double parseMgfNumber(const std::string& word, const std::string& what) {
  // from_chars takes no leading '+', which MGF writers sometimes emit.
  const char* begin = word.data() + (!word.empty() && word[0] == '+' ? 1 : 0);
  const char* end = word.data() + word.size();
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  // Out of range is too large or too small: a number too small for a double is as good as 0, as
  // the reference parser's atof reads it.
  if (ec == std::errc::result_out_of_range && ptr == end) {
    const double tiny = std::strtod(std::string(begin, end).c_str(), nullptr);
    if (std::isfinite(tiny)) return tiny;
  }
  if (ec == std::errc::result_out_of_range || (ec == std::errc{} && ptr == end && !std::isfinite(value)))
    throw MgfError(what + " '" + word + "' is not a finite number",
                   "give " + what + " as a finite decimal number");
  if (ec != std::errc{} || ptr != end || begin == end)
    throw MgfError(what + " '" + word + "' is not a number", "give " + what + " as a decimal number");
  return value;
}

int parseMgfCount(const std::string& word, const std::string& what, int minimum) {
  int value = 0;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc{} || ptr != word.data() + word.size() || value < minimum)
    throw MgfError(what + " '" + word + "' is not a whole number of at least " +
                       std::to_string(minimum),
                   "give " + what + " as a whole number >= " + std::to_string(minimum));
  return value;
}

}  // namespace radmesh
