#include "config/bounded_file.hpp"

#include <filesystem>
#include <fstream>

#include "config/input_error.hpp"

namespace handover {

std::string readBoundedFile(const std::string& path, std::size_t max_bytes, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  // read at most one byte past the bound: enough to know the file is too
  // large without reading it (a device may never end)
  std::string text;
  text.resize(max_bytes + 1);
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  const std::size_t n = static_cast<std::size_t>(in.gcount());
  if (in.bad()) throw InputError(path + ": read error");
  if (n > max_bytes) {
    throw InputError(path + ": larger than " + std::to_string(max_bytes) + " bytes; not a " + what +
                     " (refused unread)");
  }
  text.resize(n);
  return text;
}

}  // namespace handover
