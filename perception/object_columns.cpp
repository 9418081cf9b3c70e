#include "perception/object_columns.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "perception/csv_pose_source.hpp"
#include "perception/pose_codec.hpp"

namespace handover::perception {

const std::string& poseCsvHeaderWithObject() {
  static const std::string header =
      std::string(poseCsvHeader()) + ",object_x,object_y,object_z,object_qw,object_qx,object_qy,object_qz";
  return header;
}

const char* takeObjectColumns(std::string& line, char sep, Pose& object) {
  // the arm's fields end at the 22nd separator
  std::size_t cut = std::string::npos, pos = 0;
  for (int n = 0; n < kSampleFields; ++n) {
    pos = line.find(sep, pos);
    if (pos == std::string::npos) return "too few fields (expected 29 numbers with the object columns)";
    cut = pos++;
  }
  double v[kObjectFields];
  const char* p = line.c_str() + cut + 1;
  for (int i = 0; i < kObjectFields; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(p, &end);
    if (end == p) return "an object field is not a number";
    if (!std::isfinite(v[i])) return "an object field is not finite";
    p = end;
    while (*p == ' ' || *p == '\t') ++p;
    if (i + 1 < kObjectFields) {
      if (*p != sep) return "too few fields (expected 29 numbers with the object columns)";
      ++p;
    }
  }
  while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
  if (*p != '\0') return "too many fields (expected 29 numbers with the object columns)";

  Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
  const double n = q.norm();
  if (std::abs(n - 1.0) > 1e-3) return "the object quaternion is not of unit length";
  if (n != 1.0) q.coeffs() /= n;
  object.position = Eigen::Vector3d(v[0], v[1], v[2]);
  object.orientation = q;
  line.resize(cut);
  return nullptr;
}

void appendObjectColumns(const Pose& o, char sep, std::string& line) {
  const double v[kObjectFields] = {o.position.x(),    o.position.y(),    o.position.z(),   o.orientation.w(),
                                   o.orientation.x(), o.orientation.y(), o.orientation.z()};
  char buf[32];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, "%c%.17g", sep, x);
    line += buf;
  }
}

}  // namespace handover::perception
