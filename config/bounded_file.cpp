#include "config/bounded_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "config/input_error.hpp"

namespace handover {

std::string readBoundedFile(const std::string& path, std::size_t max_bytes, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder, not a " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  // read in chunks up to one byte past the bound: enough to know the file is
  // too large without reading it all (a device may never end)
  std::string text;
  char chunk[64 * 1024];
  while (in && text.size() <= max_bytes) {
    in.read(chunk, static_cast<std::streamsize>(std::min(sizeof chunk, max_bytes + 1 - text.size())));
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw InputError(path + ": read error");
  if (text.size() > max_bytes) {
    throw InputError(path + ": larger than " + std::to_string(max_bytes) + " bytes; not a " + what +
                     " (refused unread)");
  }
  return text;
}

}  // namespace handover
