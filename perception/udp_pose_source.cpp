#include "perception/udp_pose_source.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "config/input_error.hpp"
#include "perception/pose_codec.hpp"

namespace handover::perception {

UdpPoseSource::UdpPoseSource(std::uint16_t port, const std::string& bind_address, UdpStamp stamp)
    : stamp_(stamp) {
  const std::string where = "udp://" + bind_address + ":" + std::to_string(port);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  if (inet_pton(AF_INET, bind_address.c_str(), &addr.sin_addr) != 1) {
    throw InputError(where + ": not an IPv4 address");
  }
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw InputError(where + ": cannot open a UDP socket: " + std::strerror(errno));
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    throw InputError(where + ": cannot bind: " + std::strerror(e));
  }
  socklen_t len = sizeof addr;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
}

UdpPoseSource::~UdpPoseSource() {
  if (fd_ >= 0) ::close(fd_);
}

bool UdpPoseSource::poll(double now, PoseSample& out) {
  char buf[kMaxDatagram];
  for (;;) {
    // MSG_TRUNC returns the real length, so oversize datagrams are caught
    const ssize_t n = ::recv(fd_, buf, kMaxDatagram, MSG_DONTWAIT | MSG_TRUNC);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;  // EAGAIN: nothing pending (other errors: treat as nothing)
    }
    PoseSample s;
    const char* err = decodeDatagram(buf, static_cast<std::size_t>(n), s);
    if (err) {
      ++malformed_;
      last_error_ = err;
      continue;
    }
    if (stamp_ == UdpStamp::Arrival) s.stamp = now;
    out = s;
    ++received_;
    return true;
  }
}

}  // namespace handover::perception
