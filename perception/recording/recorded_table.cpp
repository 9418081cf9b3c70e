#include "perception/recording/recorded_table.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "config/input_error.hpp"

namespace handover::perception::recording {

namespace {

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (true) {
    const std::size_t to = line.find(sep, from);
    std::string f = line.substr(from, to == std::string::npos ? std::string::npos : to - from);
    const auto a = f.find_first_not_of(" \t\""), b = f.find_last_not_of(" \t\"");
    out.push_back(a == std::string::npos ? std::string() : f.substr(a, b - a + 1));
    if (to == std::string::npos) return out;
    from = to + 1;
  }
}

}  // namespace

const std::vector<double>& RecordedTable::column(const std::string& name, const std::string& context) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return columns[i];
  }
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  throw InputError(path + ": no column '" + name + "' (asked for by " + context + "); the header has: " + known);
}

RecordedTable readRecordedTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the recording file");
  RecordedTable t;
  t.path = path;
  std::string line;
  int lineno = 0;
  char sep = ',';
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (t.names.empty()) {
      const std::size_t s = line.find_first_of(",;\t");
      if (s != std::string::npos) sep = line[s];
      t.names = split(line, sep);
      t.columns.assign(t.names.size(), {});
      continue;
    }
    const std::vector<std::string> fields = split(line, sep);
    if (fields.size() != t.names.size()) {
      throw InputError(path + ":" + std::to_string(lineno) + ": " + std::to_string(fields.size()) +
                       " fields, the header has " + std::to_string(t.names.size()));
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(fields[c].c_str(), &end);
      if (fields[c].empty() || *end != '\0' || !std::isfinite(v)) {
        throw InputError(path + ":" + std::to_string(lineno) + ": column '" + t.names[c] + "': '" + fields[c] +
                         "' is not a finite number");
      }
      t.columns[c].push_back(v);
    }
  }
  if (t.rows() == 0) throw InputError(path + ": no data rows (expected a header line, then one row per sample)");
  return t;
}

}  // namespace handover::perception::recording
