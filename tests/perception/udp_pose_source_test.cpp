#include "perception/udp_pose_source.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "config/input_error.hpp"
#include "perception/pose_codec.hpp"

using namespace handover::perception;

namespace {

class Sender {
 public:
  explicit Sender(std::uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    addr_.sin_family = AF_INET;
    addr_.sin_port = htons(port);
    inet_pton(AF_INET, "127.0.0.1", &addr_.sin_addr);
  }
  ~Sender() { ::close(fd_); }
  void send(const std::string& d) {
    ASSERT_EQ(::sendto(fd_, d.data(), d.size(), 0, reinterpret_cast<sockaddr*>(&addr_), sizeof addr_),
              static_cast<ssize_t>(d.size()));
  }

 private:
  int fd_;
  sockaddr_in addr_{};
};

PoseSample sample(double t, double x) {
  PoseSample s;
  s.stamp = t;
  s.hand.position = {x, 0.1, 0.3};
  s.hand.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
  s.forearm.position = {x + 0.25, 0.1, 0.35};
  s.upper_arm.position = {x + 0.5, 0.15, 0.6};
  return s;
}

std::string encode(const PoseSample& s) {
  char buf[kMaxEncodedSample];
  encodeSample(s, ',', buf, sizeof buf);
  return std::string("hpose ") + buf;
}

}  // namespace

TEST(UdpPoseSource, ValidArriveMalformedAreCountedAndDropped) {
  UdpPoseSource src(0, "127.0.0.1", UdpStamp::Sender);
  ASSERT_NE(src.port(), 0);
  PoseSample got;
  EXPECT_FALSE(src.poll(0.0, got));  // nothing yet, and it does not block

  Sender tx(src.port());
  tx.send(encode(sample(1.25, 0.5)));
  tx.send("hello");                                    // wrong prefix
  tx.send("hpose 1,2,3");                              // too few fields
  tx.send("hpose " + std::string(30, ','));            // empty fields
  std::string nan = encode(sample(1.3, 0.5));
  nan.replace(nan.find(',') + 1, 3, "nan");            // a non-finite field
  tx.send(nan);
  tx.send(std::string(3000, 'x'));                     // oversize
  PoseSample bad_q = sample(1.4, 0.5);
  bad_q.hand.orientation.coeffs() *= 2.0;              // not a unit quaternion
  tx.send(encode(bad_q));
  tx.send(encode(sample(1.5, 0.6)));

  std::vector<PoseSample> valid;
  // loopback delivery is quick but not instantaneous: poll for up to 5 s
  for (int i = 0; i < 500 && (valid.size() < 2 || src.malformed() < 6); ++i) {
    while (src.poll(2.0, got)) valid.push_back(got);
    if (valid.size() < 2 || src.malformed() < 6) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(valid.size(), 2u);
  EXPECT_EQ(src.malformed(), 6);
  EXPECT_EQ(src.received(), 2);
  EXPECT_DOUBLE_EQ(valid[0].stamp, 1.25);
  EXPECT_EQ(valid[0].hand.position, sample(1.25, 0.5).hand.position);
  EXPECT_EQ(valid[0].hand.orientation.coeffs(), sample(1.25, 0.5).hand.orientation.coeffs());
  EXPECT_EQ(valid[1].forearm.position, sample(1.5, 0.6).forearm.position);
  EXPECT_STRNE(src.lastError(), "");
}

TEST(UdpPoseSource, ArrivalStampUsesReceiverClock) {
  UdpPoseSource src(0);
  Sender tx(src.port());
  tx.send(encode(sample(123.0, 0.5)));
  PoseSample got;
  bool ok = false;
  for (int i = 0; i < 500 && !ok; ++i) {
    ok = src.poll(7.5, got);
    if (!ok) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(ok);
  EXPECT_DOUBLE_EQ(got.stamp, 7.5);
}

TEST(UdpPoseSource, BadAddressIsAnInputError) {
  EXPECT_THROW(UdpPoseSource(0, "not-an-address"), handover::InputError);
}
