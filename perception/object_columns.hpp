// Optional object columns of the pose CSV (docs/perception.md): when the
// tracker follows the object as its own rigid body, each row carries 7 more
// numbers after the 22 of the arm, object_{x,y,z,qw,qx,qy,qz} (m, world;
// quaternion object-to-world, w first). Kept apart from the 22-field codec
// so that the UDP datagram and the arm-only CSV stay as they are.
#pragma once

#include <string>

#include "perception/pose_sample.hpp"

namespace handover::perception {

constexpr int kObjectFields = 7;

/// The CSV header with the object columns appended.
const std::string& poseCsvHeaderWithObject();

/// Splits `line` after its 22nd field: the 7 object numbers that follow are
/// parsed into `object` and `line` keeps the 22 arm fields. Returns nullptr
/// on success, else a static message (wrong count, not a number, not finite,
/// quaternion off unit length by more than 1e-3; a unit one is kept exactly).
const char* takeObjectColumns(std::string& line, char sep, Pose& object);

/// Appends the 7 object numbers (17 significant digits) to `line`.
void appendObjectColumns(const Pose& object, char sep, std::string& line);

}  // namespace handover::perception
