// Input errors: bad files, keys and values. The command line turns these into
// a message on stderr and exit code 2; nothing that reads input may crash.
#pragma once

#include <stdexcept>
#include <string>

namespace handover {

/// Thrown for malformed or invalid input. what() is the full, user-facing
/// message and names the file, the key (dotted path) and the line when known.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace handover
