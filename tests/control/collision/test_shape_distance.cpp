// FCL core distances against independent geometry: closed-form
// segment-segment and a convex line search for segment-box.
#include <gtest/gtest.h>

#include <random>

#include "control/collision/shape_distance.hpp"

using namespace handover::control;

namespace {

Isometry segmentPose(const Vector3& a, const Vector3& b) {
  Isometry X = Isometry::Identity();
  X.translation() = 0.5 * (a + b);
  X.linear() = Quaternion::FromTwoVectors(Vector3::UnitZ(), b - a).toRotationMatrix();
  return X;
}

double pointSegment(const Vector3& p, const Vector3& a, const Vector3& b) {
  const Vector3 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * d)).norm();
}

// Closed form: the interior stationary point of |P(s) - Q(t)|^2 if it lies in
// the unit square, else the best of the four edge cases (endpoint to segment).
double segmentSegment(const Vector3& p0, const Vector3& p1, const Vector3& q0, const Vector3& q1) {
  const Vector3 u = p1 - p0, v = q1 - q0, w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  const double den = a * c - b * b;
  double best = std::min({pointSegment(p0, q0, q1), pointSegment(p1, q0, q1), pointSegment(q0, p0, p1),
                          pointSegment(q1, p0, p1)});
  if (den > 1e-14) {
    const double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, (w + s * u - t * v).norm());
  }
  return best;
}

double pointBox(const Vector3& p, const Isometry& X, const Vector3& size) {
  const Vector3 q = X.inverse() * p;
  return (q.cwiseAbs() - 0.5 * size).cwiseMax(0.0).norm();
}

// distance to a convex set along a segment is convex in t: ternary search
double segmentBox(const Vector3& a, const Vector3& b, const Isometry& X, const Vector3& size) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (pointBox(a + m1 * (b - a), X, size) < pointBox(a + m2 * (b - a), X, size)) hi = m2; else lo = m1;
  }
  return pointBox(a + 0.5 * (lo + hi) * (b - a), X, size);
}

ShapeSpec segment() {
  ShapeSpec s;
  s.kind = ShapeSpec::Kind::kSegment;
  s.length = 1.0;
  return s;
}

ShapeSpec box(const Vector3& size) {
  ShapeSpec s;
  s.kind = ShapeSpec::Kind::kBox;
  s.size = size;
  return s;
}

Isometry randomPose(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Isometry X = Isometry::Identity();
  X.linear() = Quaternion(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
  X.translation() = Vector3(u(rng), u(rng), u(rng)) * 0.3;
  return X;
}

}  // namespace

TEST(ShapeDistance, SegmentSegmentMatchesClosedForm) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  ShapeDistance sd({segment(), segment()});
  int checked = 0;
  for (int i = 0; i < 500; ++i) {
    const Vector3 p0(u(rng), u(rng), u(rng)), p1(u(rng), u(rng), u(rng));
    const Vector3 q0(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng));
    sd.setSegmentLength(0, (p1 - p0).norm());
    sd.setSegmentLength(1, (q1 - q0).norm());
    ShapeDistanceResult r;
    sd.compute(0, segmentPose(p0, p1), 1, segmentPose(q0, q1), r);
    const double expected = segmentSegment(p0, p1, q0, q1);
    EXPECT_NEAR(r.distance, expected, 1e-9) << "case " << i;
    if (expected > 1e-6) {
      ASSERT_TRUE(r.separated);
      // witness points lie on their segments and realise the distance
      EXPECT_NEAR(pointSegment(r.p1, p0, p1), 0.0, 1e-9);
      EXPECT_NEAR(pointSegment(r.p2, q0, q1), 0.0, 1e-9);
      EXPECT_NEAR((r.p1 - r.p2).norm(), expected, 1e-9);
      ++checked;
    }
  }
  EXPECT_GT(checked, 400);
}

TEST(ShapeDistance, SegmentBoxMatchesLineSearch) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const Vector3 size(0.3, 0.2, 0.1);
  ShapeDistance sd({segment(), box(size)});
  int separated = 0, close = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vector3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const Isometry box = randomPose(rng);
    sd.setSegmentLength(0, (b - a).norm());
    ShapeDistanceResult r;
    sd.compute(0, segmentPose(a, b), 1, box, r);
    const double expected = segmentBox(a, b, box, size);
    if (expected < 1e-4) {
      EXPECT_LT(r.distance, 1e-4);  // overlapping or touching
      continue;
    }
    ASSERT_TRUE(r.separated) << "case " << i;
    // GJK alone can stall ~1e-4 short here; the polished answer may not
    const double tol = 1e-9;
    (expected > 0.04 ? separated : close)++;
    EXPECT_NEAR(r.distance, expected, tol) << "case " << i;
    EXPECT_NEAR(pointSegment(r.p1, a, b), 0.0, tol);
    EXPECT_NEAR(pointBox(r.p2, box, size), 0.0, tol);
    EXPECT_NEAR((r.p1 - r.p2).norm(), r.distance, tol);
  }
  EXPECT_GT(separated, 100);
  EXPECT_GT(close, 3);
}

TEST(ShapeDistance, OverlapIsReportedNotCrashed) {
  ShapeDistance sd({segment(), box(Vector3(1, 1, 1))});
  ShapeDistanceResult r;
  sd.compute(0, Isometry::Identity(), 1, Isometry::Identity(), r);
  EXPECT_FALSE(r.separated);
  EXPECT_EQ(r.distance, 0.0);
}
