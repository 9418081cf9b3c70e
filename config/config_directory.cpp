#include "config/config_directory.hpp"

#include <filesystem>

#include "config/input_error.hpp"

namespace handover {
namespace {
std::string& directory() {
  static std::string dir = std::string(HANDOVER_SOURCE_DIR) + "/config";
  return dir;
}
}  // namespace

const std::string& configDirectory() { return directory(); }

void setConfigDirectory(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError("--config-dir '" + dir + "': not a folder");
  // the whole set, checked at once: a folder with only the tuned file would fall back to
  // nothing and fail later, in the middle of a batch, under another file's name
  for (const char* f : {"robot.yaml", "controller.yaml", "collision.yaml", "perception.yaml", "grasp_selection.yaml", "fsm.yaml"}) {
    if (!fs::is_regular_file(fs::path(dir) / f, ec))
      throw InputError("--config-dir '" + dir + "': no " + f + " (copy config/ and edit the copy)");
  }
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  directory() = d;
}

std::string configFile(const std::string& name) { return directory() + "/" + name; }

}  // namespace handover
