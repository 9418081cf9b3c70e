#include "perception/pose_codec.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace handover::perception {

namespace {

void fieldsOf(const PoseSample& s, double* v) {
  v[0] = s.stamp;
  const Pose* bodies[3] = {&s.hand, &s.forearm, &s.upper_arm};
  for (int b = 0; b < 3; ++b) {
    double* w = v + 1 + 7 * b;
    w[0] = bodies[b]->position.x();
    w[1] = bodies[b]->position.y();
    w[2] = bodies[b]->position.z();
    w[3] = bodies[b]->orientation.w();
    w[4] = bodies[b]->orientation.x();
    w[5] = bodies[b]->orientation.y();
    w[6] = bodies[b]->orientation.z();
  }
}

}  // namespace

int encodeSample(const PoseSample& s, char sep, char* buf, std::size_t size) {
  double v[kSampleFields];
  fieldsOf(s, v);
  std::size_t n = 0;
  for (int i = 0; i < kSampleFields && n < size; ++i) {
    const int w = i == 0 ? std::snprintf(buf + n, size - n, "%.17g", v[i])
                         : std::snprintf(buf + n, size - n, "%c%.17g", sep, v[i]);
    if (w < 0) break;
    n += static_cast<std::size_t>(w);
  }
  if (n >= size) n = size - 1;
  buf[n] = '\0';
  return static_cast<int>(n);
}

const char* decodeSample(const char* text, char sep, PoseSample& out) {
  double v[kSampleFields];
  const char* p = text;
  for (int i = 0; i < kSampleFields; ++i) {
    while (*p == ' ' || *p == '\t') ++p;
    if (*p == '\0' || *p == '\n') return "too few fields (expected 22 numbers)";
    char* end = nullptr;
    errno = 0;
    v[i] = std::strtod(p, &end);
    if (end == p) return "a field is not a number";
    if (!std::isfinite(v[i])) return "a field is not finite";
    p = end;
    while (*p == ' ' || *p == '\t') ++p;
    if (i + 1 < kSampleFields) {
      if (*p != sep) return *p == '\0' || *p == '\n' || *p == '\r' ? "too few fields (expected 22 numbers)"
                                                                  : "unexpected character between fields";
      ++p;
    }
  }
  while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') ++p;
  if (*p != '\0') return "too many fields or trailing characters (expected 22 numbers)";

  PoseSample s;
  s.stamp = v[0];
  Pose* bodies[3] = {&s.hand, &s.forearm, &s.upper_arm};
  for (int b = 0; b < 3; ++b) {
    const double* w = v + 1 + 7 * b;
    bodies[b]->position = Eigen::Vector3d(w[0], w[1], w[2]);
    Eigen::Quaterniond q(w[3], w[4], w[5], w[6]);
    const double n = q.norm();
    if (std::abs(n - 1.0) > 1e-3) return "a quaternion is not of unit length";
    // keep exact values when already unit, so logs round-trip bit for bit
    if (n != 1.0) q.coeffs() /= n;
    bodies[b]->orientation = q;
  }
  out = s;
  return nullptr;
}

const char* decodeDatagram(const char* data, std::size_t n, PoseSample& out) {
  static constexpr char kPrefix[] = "hpose ";
  if (n >= kMaxDatagram) return "datagram too long";
  if (std::memchr(data, '\0', n) != nullptr) return "datagram contains a NUL byte";
  if (n < sizeof kPrefix - 1 || std::memcmp(data, kPrefix, sizeof kPrefix - 1) != 0) {
    return "datagram does not start with 'hpose '";
  }
  char text[kMaxDatagram];
  std::memcpy(text, data + sizeof kPrefix - 1, n - (sizeof kPrefix - 1));
  text[n - (sizeof kPrefix - 1)] = '\0';
  return decodeSample(text, ',', out);
}

}  // namespace handover::perception
