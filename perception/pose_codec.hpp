// Text encoding of one PoseSample shared by the CSV log and the UDP stream:
// 22 numbers (t, then x y z qw qx qy qz for hand, forearm, upper arm)
// separated by one character. Real-time safe (no allocation).
#pragma once

#include <cstddef>

#include "perception/pose_sample.hpp"

namespace handover::perception {

constexpr int kSampleFields = 22;
constexpr std::size_t kMaxEncodedSample = 22 * 26 + 8;  ///< bytes a line may need
/// A CSV line may also carry the tracked object's pose (7 more numbers).
constexpr std::size_t kMaxCsvSampleLine = (22 + 7) * 26 + 8;

/// Writes the sample with 17 significant digits; returns the length.
int encodeSample(const PoseSample& s, char sep, char* buf, std::size_t size);

/// Parses exactly kSampleFields numbers separated by `sep` (spaces around
/// them allowed). Returns nullptr on success, else a static message. Rejects
/// non-finite numbers and quaternions whose norm is off 1 by more than 1e-3
/// (those within are normalised).
const char* decodeSample(const char* text, char sep, PoseSample& out);

/// Largest datagram of the UDP stream, bytes; longer ones are malformed.
constexpr std::size_t kMaxDatagram = 1024;

/// Decodes one UDP datagram of `n` bytes (not NUL-terminated; `n` may exceed
/// what was received when the datagram was truncated): "hpose " and the 22
/// comma-separated numbers. Returns nullptr or a static message (too long, a
/// NUL byte, a wrong prefix, or decodeSample's reasons). Real-time safe.
const char* decodeDatagram(const char* data, std::size_t n, PoseSample& out);

}  // namespace handover::perception
