// Live pose stream over UDP (format: docs/perception.md). Each datagram is
// one sample in ASCII:  "hpose " followed by the 22 comma-separated numbers
// of a CSV row (t, hand x y z qw qx qy qz, forearm ..., upper arm ...).
// Malformed datagrams (wrong prefix, field count, non-numbers, non-finite
// values, non-unit quaternions, oversize) are dropped and counted, never fatal.
// The socket is non-blocking; poll() never waits and is real-time safe (no
// allocation; one recv per call of the loop).
#pragma once

#include <cstdint>
#include <string>

#include "perception/pose_codec.hpp"
#include "perception/pose_source.hpp"

namespace handover::perception {

enum class UdpStamp {
  Arrival,  ///< stamp = the receiver's `now` when polled (sender clock ignored)
  Sender,   ///< stamp = the datagram's t (sender clock synchronised with ours)
};

class UdpPoseSource : public PoseSource {
 public:
  static constexpr std::size_t kMaxDatagram = perception::kMaxDatagram;  ///< bytes; longer ones are malformed

  /// Binds `bind_address`:`port` (port 0 = any free port, see port()).
  /// Throws InputError naming the address if the socket cannot be opened.
  UdpPoseSource(std::uint16_t port, const std::string& bind_address = "127.0.0.1",
                UdpStamp stamp = UdpStamp::Arrival);
  ~UdpPoseSource() override;
  UdpPoseSource(const UdpPoseSource&) = delete;
  UdpPoseSource& operator=(const UdpPoseSource&) = delete;

  bool poll(double now, PoseSample& out) override;

  std::uint16_t port() const { return port_; }
  long received() const { return received_; }    ///< valid samples delivered
  long malformed() const { return malformed_; }  ///< datagrams rejected
  /// Why the last malformed datagram was rejected (static string, "" if none).
  const char* lastError() const { return last_error_; }

 private:
  int fd_ = -1;
  std::uint16_t port_ = 0;
  UdpStamp stamp_;
  long received_ = 0;
  long malformed_ = 0;
  const char* last_error_ = "";
};

}  // namespace handover::perception
