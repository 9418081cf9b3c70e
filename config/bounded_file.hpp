// Reading an input file whole, with a size bound: a scenario, a config or a
// tracker recording that is larger than any real one (or a device such as
// /dev/zero that never ends) is refused at once with a message naming the
// file, instead of growing memory until the process dies. Start-up only.
#pragma once

#include <cstddef>
#include <string>

namespace handover {

/// Size bound of YAML inputs (scenarios, configs): 1 MiB, about 100x the
/// largest shipped file.
constexpr std::size_t kMaxYamlBytes = std::size_t{1} << 20;

/// Returns the whole content of `path`. Throws InputError naming the file when
/// it cannot be opened, is a folder, or holds more than `max_bytes` bytes
/// (`what` says what kind of file it should have been).
std::string readBoundedFile(const std::string& path, std::size_t max_bytes, const std::string& what);

}  // namespace handover
