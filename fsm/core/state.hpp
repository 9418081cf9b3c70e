// A state of a hierarchical state machine (mc_rtc style):
//   configure(def)  once at load, with the state's YAML definition;
//   start(ctx)      when the state is entered;
//   run(ctx)        every cycle; returns true when done, after setOutput();
//   teardown(ctx)   when the state is left for any reason (done, timeout,
//                   preempted by an interrupt, parent left): it must remove
//                   whatever start/run added.
// Outputs are declared at configure time (declareOutput) so the transition
// table can be validated at load and run() never builds strings.
// Real-time: setOutput/output/elapsed are RT safe; start/run/teardown must
// be written RT safe by each state (no allocation, no I/O).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "config/yaml_reader.hpp"
#include "fsm/core/context.hpp"

namespace handover::fsm {

class State {
 public:
  virtual ~State() = default;

  /// Reads the state's own keys from its definition (`type` and `timeout`
  /// are already read by the loader; any key left unread is rejected after
  /// this call). Throws handover::InputError on bad values. Not RT safe.
  virtual void configure(const YamlReader& def) { (void)def; }
  virtual void start(Context& ctx) { (void)ctx; }
  /// One cycle. Return true when finished, after calling setOutput().
  virtual bool run(Context& ctx) = 0;
  virtual void teardown(Context& ctx) { (void)ctx; }

  /// Name in its machine (e.g. "Approach").
  const std::string& name() const { return name_; }
  /// Full path from the top machine (e.g. "Handover/HumanToRobot/Approach").
  const std::string& path() const { return path_; }
  /// Outputs this state may end with, in declaration order.
  const std::vector<std::string>& outputs() const { return outputs_; }
  /// Index of an output, -1 if not declared.
  int findOutput(const std::string& output) const;
  /// Index of the output set by the last run (-1 if none yet).
  int outputIndex() const { return output_; }
  /// Output set by the last run ("" if none yet). RT safe.
  const std::string& output() const;
  /// Time at which the state was last started, s.
  double startTime() const { return start_time_; }
  /// Seconds since start. RT safe.
  double elapsed(const Context& ctx) const { return ctx.time - start_time_; }
  /// Seconds after which the state ends with output "Timeout" (inf = never).
  double timeout() const { return timeout_; }

  static const char* timeoutOutput() { return "Timeout"; }

 protected:
  /// Declares an output (configure time or constructor; not RT safe).
  /// Declaring the same name twice returns the first index.
  int declareOutput(const std::string& output);
  /// Sets the output that picks the transition. RT safe.
  void setOutput(int index);

 private:
  friend class Machine;
  friend class MachineLoader;
  friend class StateMachine;
  std::string name_;
  std::string path_;
  std::vector<std::string> outputs_;
  int output_ = -1;
  double start_time_ = 0.0;
  double timeout_ = std::numeric_limits<double>::infinity();
};

}  // namespace handover::fsm
