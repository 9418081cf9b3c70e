// Where the configuration files (controller.yaml, fsm.yaml, ...) are read
// from: the source tree's config/ folder unless the command line names
// another (`handover --config-dir DIR ...`), so a user compares a set of
// tuned files against the shipped ones without rebuilding.
//
// Start-up only, not thread-safe: set the folder before anything loads a
// configuration (a batch's runs read it from their threads).
#pragma once

#include <string>

namespace handover {

/// The folder every default configuration path is under (no trailing slash).
const std::string& configDirectory();

/// Reads configurations from `dir` from now on. Throws InputError naming the
/// folder when it is not a folder or lacks one of the files the default paths
/// name (robot, controller, collision, perception, grasp selection, fsm).
void setConfigDirectory(const std::string& dir);

/// `configDirectory()/name`, e.g. configFile("fsm.yaml").
std::string configFile(const std::string& name);

}  // namespace handover
