#include "perception/reach_predictor.hpp"
#include "interfaces/minimum_jerk.hpp"

#include <algorithm>
#include <cmath>

namespace handover::perception {

ReachPredictor::ReachPredictor(const ReachPredictorSettings& settings)
    : settings_(settings),
      buf_(static_cast<std::size_t>(std::ceil(settings.window / std::max(settings.sample_period, 1e-3))) + 1) {
  reset();
}

void ReachPredictor::reset() {
  head_ = count_ = 0;
  rest_time_ = onset_time_ = resume_time_ = -1.0;
  awaiting_rest_ = false;
  pred_ = ReachPrediction{};
}

void ReachPredictor::add(double t, const Eigen::Isometry3d& pose, double speed) {
  if (count_ > 0) {
    const double last = at(count_ - 1).t;
    if (t < last + settings_.sample_period) return;
    if (t - last > std::min(settings_.window, settings_.restart_gap)) {
      reset();
      awaiting_rest_ = true;
      resume_time_ = t + settings_.restart_settle;
    }
  }
  const int cap = static_cast<int>(buf_.size());
  if (count_ == cap) {
    head_ = (head_ + 1) % cap;
    --count_;
  }
  buf_[(head_ + count_) % cap] = Sample{t, pose.translation(), Eigen::Quaterniond(pose.linear())};
  ++count_;

  if (awaiting_rest_) {
    // after a gap: no reach until the hand rests (the restarted track's speed
    // is its own motion model's, 0 at first, until restart_settle has passed)
    if (t >= resume_time_ && speed < settings_.rest_speed) {
      awaiting_rest_ = false;
    } else {
      pred_.reaching = false;
      pred_.lead = pred_.phase = pred_.residual = 0.0;
      pred_.end = pose;
      return;
    }
  }
  if (rest_time_ < 0.0 || speed < settings_.rest_speed) {
    // at rest (or the first sample): the end is where the hand is (end_trusted
    // tells whether a trusted reach ended here)
    rest_time_ = t;
    onset_time_ = -1.0;
    pred_.reaching = false;
    pred_.lead = pred_.phase = pred_.residual = 0.0;
    pred_.end = pose;
    return;
  }
  if (onset_time_ < 0.0) {
    if (speed < settings_.onset_speed) return;  // drifting, not reaching (yet)
    onset_time_ = t;
    pred_.reaching = true;
    pred_.end_trusted = false;
  }
  fit(speed);
}

namespace {
// A local minimum of f over the plane: Nelder-Mead from `x0` with a simplex of `step`.
template <class F>
Eigen::Vector2d nelderMead(const F& f, const Eigen::Vector2d& x0, const Eigen::Vector2d& step, int iterations) {
  Eigen::Vector2d x[3] = {x0, x0 + Eigen::Vector2d(step.x(), 0.0), x0 + Eigen::Vector2d(0.0, step.y())};
  double c[3] = {f(x[0]), f(x[1]), f(x[2])};
  for (int it = 0; it < iterations; ++it) {
    // order: x[0] best, x[2] worst
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2 - i; ++j)
        if (c[j + 1] < c[j]) {
          std::swap(c[j], c[j + 1]);
          std::swap(x[j], x[j + 1]);
        }
    const Eigen::Vector2d mid = 0.5 * (x[0] + x[1]);
    const Eigen::Vector2d r = mid + (mid - x[2]);
    const double cr = f(r);
    if (cr < c[0]) {
      const Eigen::Vector2d e = mid + 2.0 * (mid - x[2]);
      const double ce = f(e);
      if (ce < cr) x[2] = e, c[2] = ce;
      else x[2] = r, c[2] = cr;
    } else if (cr < c[1]) {
      x[2] = r, c[2] = cr;
    } else {
      const Eigen::Vector2d k = mid + 0.5 * (x[2] - mid);
      const double ck = f(k);
      if (ck < c[2]) {
        x[2] = k, c[2] = ck;
      } else {  // shrink toward the best
        for (int i = 1; i < 3; ++i) {
          x[i] = x[0] + 0.5 * (x[i] - x[0]);
          c[i] = f(x[i]);
        }
      }
    }
  }
  int b = 0;
  for (int i = 1; i < 3; ++i)
    if (c[i] < c[b]) b = i;
  return x[b];
}
}  // namespace

double ReachPredictor::cost(int first, double t0, double T, Eigen::Vector3d* pa, Eigen::Vector3d* d) const {
  const Eigen::Vector3d ref = at(first).p;
  double n = 0.0, s1 = 0.0, s2 = 0.0, pp = 0.0;
  Eigen::Vector3d p1 = Eigen::Vector3d::Zero(), sp = Eigen::Vector3d::Zero();
  for (int i = first; i < count_; ++i) {
    const Sample& x = at(i);
    const double s = minimumJerkPhase((x.t - t0) / T);
    const Eigen::Vector3d p = x.p - ref;
    n += 1.0;
    s1 += s;
    s2 += s * s;
    p1 += p;
    sp += s * p;
    pp += p.squaredNorm();
  }
  const double det = n * s2 - s1 * s1;
  Eigen::Vector3d a, b;
  if (det <= 1e-9 * n * n) {  // no progress inside the samples: a constant fits
    a = p1 / n;
    b.setZero();
  } else {
    a = (s2 * p1 - s1 * sp) / det;
    b = (n * sp - s1 * p1) / det;
  }
  if (pa) *pa = a + ref;
  if (d) *d = b;
  return std::max(0.0, pp - a.dot(p1) - b.dot(sp));
}

void ReachPredictor::fit(double speed) {
  // the samples from well before the last rest on (they pin down p_a): a slow reach
  // stays below rest_speed for a tenth of its duration
  const double lookback = 0.15 * settings_.max_duration;
  int first = 0;
  while (first < count_ - 1 && at(first).t < rest_time_ - lookback - 0.1) ++first;
  if (count_ - first < 6) return;
  const double t_last = at(count_ - 1).t;

  // grid: the start between a slow reach's onset before the last rest and the onset
  // speed's crossing, the duration log-spaced; then each refined by golden sections
  const double t0_lo = rest_time_ - lookback, t0_hi = onset_time_;
  constexpr int kStarts = 12, kDurations = 24;
  const double ratio = std::pow(settings_.max_duration / settings_.min_duration, 1.0 / (kDurations - 1));
  double best = 1e300, best_t0 = t0_hi, best_T = settings_.min_duration;
  for (int j = 0; j < kStarts; ++j) {
    const double t0 = t0_lo + (t0_hi - t0_lo) * j / (kStarts - 1);
    double T = settings_.min_duration;
    for (int k = 0; k < kDurations; ++k, T *= ratio) {
      const double c = cost(first, t0, T, nullptr, nullptr);
      if (c < best) {
        best = c;
        best_t0 = t0;
        best_T = T;
      }
    }
  }
  // t0 and T trade off early in a reach (a narrow valley): a simplex search from the grid's best
  {
    const double t0_step = (t0_hi - t0_lo) / (kStarts - 1);
    const auto f = [&](const Eigen::Vector2d& x) {
      const double T = std::exp(x.y());
      if (T < settings_.min_duration || T > settings_.max_duration) return 1e300;
      return cost(first, x.x(), T, nullptr, nullptr);
    };
    const Eigen::Vector2d x = nelderMead(f, Eigen::Vector2d(best_t0, std::log(best_T)),
                                         Eigen::Vector2d(t0_step, std::log(ratio)), 80);
    if (f(x) < best) {
      best_t0 = x.x();
      best_T = std::exp(x.y());
    }
  }

  Eigen::Vector3d pa, d;
  best = cost(first, best_t0, best_T, &pa, &d);
  pred_.start = best_t0;
  pred_.duration = best_T;
  pred_.phase = (t_last - best_t0) / best_T;
  pred_.residual = std::sqrt(best / (count_ - first));
  pred_.end.translation() = pa + d;

  // the rotation so far, continued along the same phase
  int i0 = first;
  while (i0 < count_ - 1 && at(i0).t < best_t0) ++i0;
  const Eigen::Quaterniond q0 = at(i0).q, q_now = at(count_ - 1).q;
  const double progress = minimumJerkPhase(pred_.phase);
  Eigen::Quaterniond q_end = q_now;
  if (progress >= 0.3) {
    const Eigen::AngleAxisd turned(q0.inverse() * q_now);
    const double angle = std::min(turned.angle() / progress, M_PI);
    q_end = q0 * Eigen::Quaterniond(Eigen::AngleAxisd(angle, turned.axis()));
  }
  pred_.end.linear() = q_end.normalized().toRotationMatrix();

  const double span = std::max(settings_.lead_full - settings_.lead_start, 1e-6);
  const double ramp = std::clamp((pred_.phase - settings_.lead_start) / span, 0.0, 1.0);
  // a hand faster than the fitted reach allows is going on, not stopping there (lag and noise: 1.5 v + 0.1)
  const double u = std::clamp(pred_.phase, 0.0, 1.0);
  const double fitted_speed = d.norm() / best_T * 30.0 * u * u * (1.0 - u) * (1.0 - u);
  // a best duration within a grid step of the range's edge is no minimum the range brackets
  const bool bracketed = best_T > settings_.min_duration * ratio && best_T < settings_.max_duration / ratio;
  const bool consistent =
      bracketed && pred_.residual <= settings_.max_residual && speed <= 1.5 * fitted_speed + 0.1;
  pred_.lead = consistent ? ramp : 0.0;
  pred_.end_trusted = pred_.lead >= 1.0;
}

Eigen::Isometry3d ReachPredictor::ledPose(const Eigen::Isometry3d& hand, const Eigen::Isometry3d& pose) const {
  if (pred_.lead <= 0.0) return pose;
  // the hand's pose partway to its end, then the rigid motion that takes it there
  const Eigen::Isometry3d& from = hand;
  Eigen::Isometry3d to = Eigen::Isometry3d::Identity();
  to.translation() = from.translation() + pred_.lead * (pred_.end.translation() - from.translation());
  to.linear() = Eigen::Quaterniond(from.linear())
                    .slerp(pred_.lead, Eigen::Quaterniond(pred_.end.linear()))
                    .normalized()
                    .toRotationMatrix();
  return to * from.inverse() * pose;
}

}  // namespace handover::perception
