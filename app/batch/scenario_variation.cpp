#include "app/batch/scenario_variation.hpp"

#include <random>

#include "config/input_error.hpp"
#include "scenes/scenario/scenario_check.hpp"

namespace handover::app {

std::uint64_t variantSeed(int base, int k) {
  // splitmix-style mixing so neighbouring variants get unrelated streams
  std::uint64_t z = (static_cast<std::uint64_t>(base) << 32) ^ static_cast<std::uint64_t>(k) ^ 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

scenario::Scenario makeVariant(const scenario::Scenario& base, int k, const VariationRanges& r) {
  std::mt19937_64 rng(variantSeed(base.seed, k));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int draw = 0; draw < r.max_draws; ++draw) {
    scenario::Scenario v = base;
    v.name = base.name + "#" + std::to_string(k);
    v.seed = static_cast<int>(variantSeed(base.seed, k) & 0x7fffffff);

    // where the person brings the object (one shift for the whole script, so
    // the motion keeps its shape)
    const Eigen::Vector3d shift(u(rng) * r.location.x(), u(rng) * r.location.y(), u(rng) * r.location.z());
    const double yaw = u(rng) * r.target_yaw;
    const double time_scale = 1.0 + u(rng) * r.timing;
    for (auto& step : v.human.script) {
      if (step.kind == scenario::StepKind::Reach) {
        step.pos += shift;
        if (step.rpy) step.rpy->z() += yaw;
      }
      if (step.kind == scenario::StepKind::Reach || step.kind == scenario::StepKind::Hold ||
          step.kind == scenario::StepKind::Withdraw) {
        step.duration *= time_scale;
      }
    }
    // how the object sits in the hand
    if (v.human.holds_object) {
      const double turn = u(rng) * r.object_yaw;
      Eigen::Isometry3d& h = *v.human.holds_object;
      h.linear() = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix() * h.linear();
    }
    // sensor noise
    const double noise = r.noise_min + (r.noise_max - r.noise_min) * 0.5 * (u(rng) + 1.0);
    v.sensor.noise_pos *= noise;
    v.sensor.noise_rot_deg *= noise;
    try {
      scenario::checkScenario(v);
      return v;
    } catch (const InputError&) {
      // unreachable for the person: draw again
    }
  }
  throw InputError(base.file + ": no reachable variant " + std::to_string(k) + " found in " +
                   std::to_string(r.max_draws) + " draws");
}

}  // namespace handover::app
