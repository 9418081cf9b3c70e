// Helpers of the end-to-end run tests: scenario copies in a temporary
// folder, and readers for the files a run writes (log.csv, summary.json).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace handover::testing {

inline std::string readText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << text;
}

inline std::string repoPath(const std::string& rel) { return std::string(HANDOVER_SOURCE_DIR) + "/" + rel; }

/// A fresh folder below the system temp dir; removed by the destructor
/// unless HANDOVER_KEEP_TEST_OUTPUT is set (to look at plots of a failure).
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag) {
    std::string tmpl = (std::filesystem::temp_directory_path() / ("handover_" + tag + "_XXXXXX")).string();
    if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed for " + tmpl);
    path_ = tmpl;
  }
  ~ScratchDir() {
    if (std::getenv("HANDOVER_KEEP_TEST_OUTPUT")) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

/// log.csv: header and rows of text fields.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  }
  double number(std::size_t row, const std::string& name) const {
    const int c = column(name);
    if (c < 0) throw std::runtime_error("no column " + name);
    return std::strtod(rows.at(row).at(static_cast<std::size_t>(c)).c_str(), nullptr);
  }
};

inline std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',')
      out.emplace_back();
    else if (c != '\r')
      out.back() += c;
  }
  return out;
}

inline CsvTable readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  CsvTable t;
  std::string line;
  if (std::getline(in, line)) t.header = splitCsvLine(line);
  while (std::getline(in, line))
    if (!line.empty()) t.rows.push_back(splitCsvLine(line));
  return t;
}

}  // namespace handover::testing
