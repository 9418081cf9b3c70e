// Unit factors the tests share (one definition, so that test files can be
// compiled together in a unity build).
#pragma once

#include <cmath>

namespace handover::test {

inline constexpr double kDeg = M_PI / 180.0;  ///< rad per degree

}  // namespace handover::test
