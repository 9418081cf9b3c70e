// Live tracker datagram ("hpose " + 22 numbers -> sample), the decoder
// UdpPoseSource::poll applies to every datagram it receives. A decoded
// sample must be finite with unit quaternions.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "perception/pose_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  handover::perception::PoseSample s;
  if (handover::perception::decodeDatagram(reinterpret_cast<const char*>(data), size, s) == nullptr) {
    const handover::perception::Pose* bodies[3] = {&s.hand, &s.forearm, &s.upper_arm};
    if (!std::isfinite(s.stamp)) std::abort();
    for (const auto* b : bodies) {
      if (!b->position.allFinite() || std::abs(b->orientation.norm() - 1.0) > 1e-9) std::abort();
    }
  }
  return 0;
}
