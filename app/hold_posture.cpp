#include "app/hold_posture.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>

#include "config/input_error.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "control/model/robot_description.hpp"
#include "scenes/sim/simulation.hpp"

namespace handover::app {

HoldSummary holdPosture(const HoldOptions& options) {
  if (!std::isfinite(options.duration) || options.duration <= 0.0) {
    throw InputError("hold: --duration must be a positive number of seconds");
  }
  // the robot description's URDF unless --urdf names another (with the description's names)
  const control::RobotDescription robot = control::defaultRobotDescription();
  const control::Model model =
      control::loadModel(options.urdf.empty() ? robot.urdf : options.urdf, robot, control::Model{}.finger_opening);
  control::Data data(model);
  const int tcp = model.frameId("tcp");

  sim::Simulation sim;
  sim.load(options.sim);
  sim.reset(options.q_ref, model.finger_opening);  // fingers where the model merged their mass

  control::forwardKinematics(model, data, options.q_ref, control::Vector7::Zero());
  const control::Vector3 tcp0 = control::framePlacement(model, data, tcp).translation();

  HoldSummary s;
  sim::ArmCommand command;
  command.gripper_width = model.finger_opening;
  const long steps = std::lround(options.duration / sim.timestep());
  const auto wall0 = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) {
    // read, compute once, command, step
    const sim::ArmState state = sim.armState();
    control::computeAll(model, data, state.q, state.qd);
    command.tau = options.kp.cwiseProduct(options.q_ref - state.q) - options.kd.cwiseProduct(state.qd) + data.g;
    sim.applyCommand(command);
    sim.step();

    s.max_joint_error = std::max(s.max_joint_error, (options.q_ref - state.q).cwiseAbs().maxCoeff());
    s.max_tcp_drift =
        std::max(s.max_tcp_drift, (control::framePlacement(model, data, tcp).translation() - tcp0).norm());
  }
  const auto wall1 = std::chrono::steady_clock::now();
  // the state after the last step counts too
  const sim::ArmState last = sim.armState();
  control::forwardKinematics(model, data, last.q, last.qd);
  s.max_joint_error = std::max(s.max_joint_error, (options.q_ref - last.q).cwiseAbs().maxCoeff());
  s.max_tcp_drift = std::max(s.max_tcp_drift, (control::framePlacement(model, data, tcp).translation() - tcp0).norm());

  s.steps = steps;
  s.simulated_time = sim.time();
  s.wall_time = std::chrono::duration<double>(wall1 - wall0).count();
  s.realtime_factor = s.wall_time > 0.0 ? s.simulated_time / s.wall_time : 0.0;
  return s;
}

void printHoldSummary(std::ostream& out, const HoldSummary& s) {
  const auto flags = out.flags();
  out << std::fixed << "hold: ready posture, gravity from our model, " << s.steps << " steps of 1 ms\n"
      << "  final time        " << std::setprecision(3) << s.simulated_time << " s\n"
      << std::defaultfloat << std::setprecision(3)
      << "  max TCP drift     " << s.max_tcp_drift * 1e3 << " mm\n"
      << "  max joint error   " << s.max_joint_error << " rad\n" << std::fixed
      << "  realtime factor   " << std::setprecision(1) << s.realtime_factor << "x (" << std::setprecision(3)
      << s.wall_time << " s wall, unpaced)\n";
  out.flags(flags);
}

}  // namespace handover::app
