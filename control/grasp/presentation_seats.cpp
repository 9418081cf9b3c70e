#include "control/grasp/presentation_seats.hpp"

#include <cmath>
#include <limits>

namespace handover::control::grasp {

namespace {
double pointBoxDistance(const Vector3& p_in_box, const Vector3& half) {
  return (p_in_box.cwiseAbs() - half).cwiseMax(0.0).norm();
}
}  // namespace

double segmentBoxDistance(const Vector3& a, const Vector3& b, const Isometry& box, const Vector3& size) {
  const Isometry inv = box.inverse();
  const Vector3 pa = inv * a, pb = inv * b, half = 0.5 * size;
  // the distance to a convex set is convex along the segment: golden-section search
  auto at = [&](double t) { return pointBoxDistance(pa + t * (pb - pa), half); };
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = at(x1), f2 = at(x2);
  for (int i = 0; i < 60 && hi - lo > 1e-9; ++i) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = at(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = at(x2);
    }
  }
  return std::min({at(0.0), at(1.0), f1, f2});
}

std::vector<ObstacleCapsule> gripperCapsulesIn(const Model& model, const std::string& frame) {
  const Frame& f = model.frames[model.frameId(frame)];
  const Isometry inv = f.placement.inverse();
  std::vector<ObstacleCapsule> out;
  for (const Capsule& c : model.capsules) {
    if (c.role == CapsuleRole::kArm || c.body != f.body) continue;
    ObstacleCapsule o;
    o.a = inv * c.a;
    o.b = inv * c.b;
    o.radius = c.radius;
    out.push_back(o);
  }
  return out;
}

std::vector<Isometry> presentationSeats(const SeatGeometry& g, const SeatOptions& o) {
  struct Seat {
    Vector3 position;
    double tcp_height;
  };
  const Matrix3 R = g.object_in_hand.linear();
  const Vector3 nominal = g.object_in_hand.translation();
  const int n = static_cast<int>(std::lround(o.range / o.step));
  std::vector<Seat> clear;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      for (int k = -n; k <= n; ++k) {
        Isometry X = Isometry::Identity();
        X.linear() = R;
        X.translation() = o.step * Vector3(i, j, k);
        // the hand under or around the object's centre, bearing its weight: a box
        // hung 12 cm below the palm by its top was dragged over the table
        if (X.translation().z() < -1e-12) continue;
        // the grip point in (or at) the object
        if (io::signedDistance(g.object, X.inverse() * Vector3::Zero()) > o.reach) continue;
        const Isometry tcp = X * g.tcp_in_object;
        bool ok = true;
        for (const ObstacleCapsule& c : g.gripper_in_tcp) {
          if (segmentBoxDistance(tcp * c.a, tcp * c.b, g.hand_box_in_hand, g.hand_box_size) - c.radius <
              o.clearance) {
            ok = false;
            break;
          }
        }
        if (ok) clear.push_back({X.translation(), tcp.translation().z()});
      }
    }
  }
  std::vector<Isometry> seats;
  auto take = [&](const Seat* s) {
    if (s == nullptr || static_cast<int>(seats.size()) >= o.max_seats) return;
    for (const Isometry& t : seats) {
      if ((t.translation() - s->position).norm() < o.step + 1e-9) return;
    }
    Isometry X = Isometry::Identity();
    X.linear() = R;
    X.translation() = s->position;
    seats.push_back(X);
  };
  const Seat* nearest = nullptr;
  const Seat* lowest = nullptr;
  for (const Seat& s : clear) {
    if (!nearest || (s.position - nominal).norm() < (nearest->position - nominal).norm()) nearest = &s;
    if (!lowest || s.tcp_height < lowest->tcp_height - 1e-12 ||
        (std::abs(s.tcp_height - lowest->tcp_height) <= 1e-12 &&
         (s.position - nominal).norm() < (lowest->position - nominal).norm())) {
      lowest = &s;
    }
  }
  // the declared seat, when it is clear, is the presentation: a lower seat
  // offered beside it brought the object within a person's reach while the
  // wrist still turned, and they took hold mid-approach (r2h_angled_bottle)
  const bool declared_clear = nearest != nullptr && (nearest->position - nominal).norm() < 1e-9;
  take(nearest);
  if (!declared_clear) take(lowest);
  return seats;
}

}  // namespace handover::control::grasp
