// Simulated wearable pose sensor: samples the person's true hand, forearm and
// upper-arm poses at rate_hz, with latency, Gaussian noise, dropouts and a
// constant calibration offset (SensorSettings). Seeded: the same seed and
// inputs give the same samples.
//
// Sample k is measured at the first call of observe() with t >= k / rate_hz
// (stamp = that t) unless t lies in a dropout, and is delivered by poll()
// once now >= stamp + latency. Noise per sample: each position axis N(0,
// noise_pos^2); rotation by a rotation vector with each component
// N(0, noise_rot_deg^2) (in rad), applied in the body frame.
// observe() and poll() are real-time safe (the delay line is preallocated).
#pragma once

#include <random>
#include <vector>

#include "perception/pose_source.hpp"
#include "perception/sensor_settings.hpp"

namespace handover::perception {

class SimulatedPoseSensor : public PoseSource {
 public:
  SimulatedPoseSensor(const SensorSettings& settings, std::uint64_t seed);

  /// Feeds the true poses at simulated time t (s); call every simulation step.
  void observe(double t, const io::HumanBodyPoses& truth);
  bool poll(double now, PoseSample& out) override;

  const SensorSettings& settings() const { return settings_; }
  /// Samples measured so far (dropped ones excluded).
  long measured() const { return measured_; }
  /// Samples lost because the delay line was full (should stay 0).
  long overflowed() const { return overflowed_; }

 private:
  Pose corrupt(const Eigen::Isometry3d& truth);
  bool inDropout(double t) const;

  SensorSettings settings_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  double period_;
  long next_index_ = 0;  ///< index k of the next sample to measure
  long measured_ = 0;
  long overflowed_ = 0;
  // ring buffer of measured, not yet delivered samples
  std::vector<PoseSample> queue_;
  std::size_t head_ = 0, count_ = 0;
};

}  // namespace handover::perception
