#include "app/report/run_summary.hpp"

#include "app/report/json_writer.hpp"

namespace handover::app {

int runExitCode(const RunSummary& r, bool outcome_expected) {
  if (r.outcome == "error") return 2;
  if (!r.expectation_failures.empty()) return 1;
  if (!outcome_expected && (r.outcome == "unsafe" || r.outcome == "no_perception")) return 1;
  return 0;
}

std::string RunSummary::toJson() const {
  JsonWriter w;
  w.beginObject();
  w.value("scenario", scenario).value("mode", mode).value("outcome", outcome).value("success", success());
  if (!error_message.empty()) w.value("error", error_message);
  w.value("handovers", handovers).value("aborts", aborts).value("retries", retries);
  w.value("time_to_grasp", time_to_grasp).value("hand_still_to_grasp", hand_still_to_grasp);
  w.value("total_time", total_time).value("min_human_distance", min_human_distance);
  w.value("human_contacts", human_contacts).value("penetration_time", penetration_time);
  w.value("object_dropped", object_dropped);
  w.value("drop_time", drop_time);
  w.value("drop_reason", drop_reason);  // "" when nothing dropped
  w.beginObject("limit_violations")
      .value("position", limit_violations.position)
      .value("velocity", limit_violations.velocity)
      .value("torque", limit_violations.torque)
      .endObject();
  w.value("qp_failures", qp_failures);
  w.value("qp_relaxed", qp_relaxed);
  w.value("limit_guard_steps", limit_guard_steps);
  w.beginObject("tracker").value("source", tracker).value("rejected_samples", static_cast<double>(rejected_samples));
  w.beginObject("rejected");
  for (const auto& [why, n] : rejected_by_reason) w.value(why, static_cast<double>(n));
  w.endObject();
  w.value("unseen_time", person_unseen_time).endObject();
  w.beginArray("person_slowed");
  for (const auto& s : person_slowed) w.element(s);
  w.endArray();
  if (grasp_error_pos) {
    w.beginObject("grasp_error").value("pos", grasp_error_pos).value("rot_deg", grasp_error_rot_deg).endObject();
  } else {
    w.value("grasp_error", std::optional<double>());
  }
  w.beginArray("states");
  for (const auto& s : states) w.element(s);
  w.endArray();
  w.beginObject("control_step_us")
      .value("median", control_step_us.median)
      .value("p99", control_step_us.p99)
      .value("max", control_step_us.max)
      .endObject();
  w.value("realtime_factor", realtime_factor).value("simulated_time", simulated_time);
  w.beginArray("expectation_failures");
  for (const auto& s : expectation_failures) w.element(s);
  w.endArray();
  w.endObject();
  return w.str() + "\n";
}

}  // namespace handover::app
