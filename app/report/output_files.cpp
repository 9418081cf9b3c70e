#include "app/report/output_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace handover::app {

namespace fs = std::filesystem;

std::string safeFileName(const std::string& name) {
  std::string s = name.substr(0, kMaxSafeNameBytes);
  for (char& c : s) {
    const unsigned char u = static_cast<unsigned char>(c);
    const bool ok = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || u == '-' ||
                    u == '_' || u == '.';
    if (!ok) c = '_';
  }
  if (!s.empty() && s[0] == '.') s[0] = '_';
  return s.empty() ? "unnamed" : s;
}

void prepareOutputDir(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir + ": cannot create the output folder: " + ec.message());
  if (!fs::is_directory(dir, ec)) throw OutputError(dir + ": not a folder");
  const std::string probe = (fs::path(dir) / ".handover_write_probe").string();
  std::FILE* f = std::fopen(probe.c_str(), "w");
  if (!f) throw OutputError(dir + ": output folder not writable: " + std::strerror(errno));
  const bool ok = std::fputs("probe\n", f) >= 0;
  const bool closed = std::fclose(f) == 0;
  std::remove(probe.c_str());
  if (!ok || !closed) throw OutputError(dir + ": cannot write into the output folder (disk full?)");
}

void checkVideoPath(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  const fs::path dir = parent.empty() ? fs::path(".") : parent;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw OutputError(path + ": the video's folder " + dir.string() + " does not exist (create it first)");
  }
  prepareOutputDir(dir.string());
}

void writeFileChecked(const std::string& path, const std::string& content) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw OutputError(path + ": cannot open for writing: " + std::strerror(errno));
  const std::size_t n = content.empty() ? 0 : std::fwrite(content.data(), 1, content.size(), f);
  int err = n == content.size() ? 0 : errno;
  if (std::fflush(f) != 0 && err == 0) err = errno;
  if (std::fclose(f) != 0 && err == 0) err = errno;
  if (n != content.size() || err != 0) {
    std::remove(path.c_str());
    throw OutputError(path + ": write failed: " + std::strerror(err ? err : EIO));
  }
}

}  // namespace handover::app
