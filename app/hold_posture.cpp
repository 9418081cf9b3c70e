#include "app/hold_posture.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>

#include "app/joint_reference.hpp"
#include "config/input_error.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "perception/pose_source.hpp"
#include "runtime/handover_cycle.hpp"
#include "scenes/sim/simulation.hpp"
#include "config/config_directory.hpp"

namespace handover::app {

namespace {
/// The hold senses no person.
class NoPoseSamples : public perception::PoseSource {
 public:
  bool poll(double, perception::PoseSample&) override { return false; }
};
}  // namespace

HoldSummary holdPosture(const HoldOptions& options) {
  if (!std::isfinite(options.duration) || options.duration <= 0.0) {
    throw InputError("hold: --duration must be a positive number of seconds");
  }
  // the handover's cycle with the hold's state table; the robot description's
  // URDF unless --urdf names another (with the description's names)
  runtime::CycleSettings cs = runtime::defaultCycleSettings();
  if (!options.urdf.empty()) cs.robot.urdf = options.urdf;
  cs.fsm_config_path = configFile("fsm_hold.yaml");
  runtime::HandoverCycle cycle(cs);
  const control::Model& model = cycle.controller().model();
  control::Data data(model);  // the judge's own forward kinematics
  const int tcp = model.frameId("tcp");
  const control::Vector7 q_ref = cs.controller.posture.target;  // what the Hold state holds

  sim::Simulation sim;
  sim.load(options.sim);
  sim.reset(q_ref, model.finger_opening);  // fingers where the model merged their mass
  {
    io::ArmState arm0;
    arm0.q = q_ref;
    cycle.start(arm0, false);
  }
  JointReferenceExecution reference(q_ref, options.kp, options.kd);
  NoPoseSamples no_samples;

  control::forwardKinematics(model, data, q_ref, control::Vector7::Zero());
  const control::Vector3 tcp0 = control::framePlacement(model, data, tcp).translation();

  HoldSummary s;
  const double dt = sim.timestep();
  const long steps = std::lround(options.duration / dt);
  const auto wall0 = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) {
    // read, one control cycle, command, step
    const io::ArmState state = sim.state();
    const io::ArmCommand& out = cycle.step(state.time, reference.seen(state), no_samples);
    sim.apply(reference.command(out, state, cycle.controller().lastQdd(), dt));
    sim.step();

    control::forwardKinematics(model, data, state.q, state.qd);
    s.max_joint_error = std::max(s.max_joint_error, (q_ref - state.q).cwiseAbs().maxCoeff());
    s.max_tcp_drift =
        std::max(s.max_tcp_drift, (control::framePlacement(model, data, tcp).translation() - tcp0).norm());
  }
  const auto wall1 = std::chrono::steady_clock::now();
  cycle.stop();
  // the state after the last step counts too
  const io::ArmState last = sim.state();
  control::forwardKinematics(model, data, last.q, last.qd);
  s.max_joint_error = std::max(s.max_joint_error, (q_ref - last.q).cwiseAbs().maxCoeff());
  s.max_tcp_drift = std::max(s.max_tcp_drift, (control::framePlacement(model, data, tcp).translation() - tcp0).norm());

  s.steps = steps;
  s.simulated_time = sim.time();
  s.wall_time = std::chrono::duration<double>(wall1 - wall0).count();
  s.realtime_factor = s.wall_time > 0.0 ? s.simulated_time / s.wall_time : 0.0;
  return s;
}

void printHoldSummary(std::ostream& out, const HoldSummary& s) {
  const auto flags = out.flags();
  out << std::fixed << "hold: ready posture, handover cycle + joint PD, gravity from our model, " << s.steps << " steps of 1 ms\n"
      << "  final time        " << std::setprecision(3) << s.simulated_time << " s\n"
      << std::defaultfloat << std::setprecision(3)
      << "  max TCP drift     " << s.max_tcp_drift * 1e3 << " mm\n"
      << "  max joint error   " << s.max_joint_error << " rad\n" << std::fixed
      << "  realtime factor   " << std::setprecision(1) << s.realtime_factor << "x (" << std::setprecision(3)
      << s.wall_time << " s wall, unpaced)\n";
  out.flags(flags);
}

}  // namespace handover::app
