// Object extent and signed distance against brute force over the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scenes/scenario/object_geometry.hpp"

using namespace handover::scenario;

namespace {

ObjectSpec make(Shape s, std::vector<double> size) {
  ObjectSpec o;
  o.shape = s;
  o.size = std::move(size);
  return o;
}

// a dense set of points on or in the object
std::vector<Eigen::Vector3d> samples(const ObjectSpec& o, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector3d p(u(rng), u(rng), u(rng));
    switch (o.shape) {
      case Shape::Sphere: p = p.normalized() * o.size[0]; break;
      case Shape::Box: {
        p = p.cwiseProduct(Eigen::Vector3d(o.size[0], o.size[1], o.size[2]) / 2.0);
        const int face = i % 3;
        p[face] = (p[face] >= 0 ? 0.5 : -0.5) * o.size[static_cast<std::size_t>(face)];
        break;
      }
      case Shape::Cylinder: {
        const double a = M_PI * u(rng);
        p = Eigen::Vector3d(o.size[0] * std::cos(a), o.size[0] * std::sin(a), u(rng) * o.size[1] / 2.0);
        if (i % 2) p.z() = (p.z() >= 0 ? 0.5 : -0.5) * o.size[1];
        break;
      }
    }
    pts.push_back(p);
  }
  return pts;
}

}  // namespace

TEST(ObjectGeometry, ExtentMatchesTheSpreadOfSurfacePoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const ObjectSpec& o : {make(Shape::Box, {0.05, 0.07, 0.15}), make(Shape::Cylinder, {0.03, 0.2}),
                              make(Shape::Sphere, {0.04})}) {
    const auto pts = samples(o, rng);
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d d = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& p : pts) {
        lo = std::min(lo, p.dot(d));
        hi = std::max(hi, p.dot(d));
      }
      // sampling approaches the true extent from below
      EXPECT_LE(hi - lo, objectExtent(o, d) + 1e-9);
      EXPECT_GT(hi - lo, objectExtent(o, d) - 2e-3);
    }
  }
}

TEST(ObjectGeometry, SignedDistanceIsNegativeInsideAndTheGapOutside) {
  const ObjectSpec cyl = make(Shape::Cylinder, {0.03, 0.2});
  EXPECT_NEAR(signedDistanceToObject(cyl, {0, 0, 0}), -0.03, 1e-12);
  EXPECT_NEAR(signedDistanceToObject(cyl, {0.05, 0, 0}), 0.02, 1e-12);
  EXPECT_NEAR(signedDistanceToObject(cyl, {0, 0, 0.13}), 0.03, 1e-12);
  EXPECT_NEAR(signedDistanceToObject(cyl, {0.06, 0, 0.14}), 0.05, 1e-12);  // past the rim: 3-4-5
  const ObjectSpec box = make(Shape::Box, {0.1, 0.2, 0.3});
  EXPECT_NEAR(signedDistanceToObject(box, {0.0, 0.0, 0.0}), -0.05, 1e-12);
  EXPECT_NEAR(signedDistanceToObject(box, {0.08, 0.0, 0.0}), 0.03, 1e-12);
  EXPECT_NEAR(signedDistanceToObject(make(Shape::Sphere, {0.04}), {0, 0.1, 0}), 0.06, 1e-12);
}

TEST(ObjectGeometry, WidthAcrossFingersFollowsTheGraspRotation) {
  ObjectSpec cyl = make(Shape::Cylinder, {0.03, 0.2});
  EXPECT_NEAR(objectWidthAcrossFingers(cyl), 0.06, 1e-12);
  cyl.grasp.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_NEAR(objectWidthAcrossFingers(cyl), 0.2, 1e-12);  // fingers along the axis
}
