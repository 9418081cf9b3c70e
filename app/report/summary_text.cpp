#include "app/report/summary_text.hpp"

#include <cstdio>
#include <sstream>

namespace handover::app {

std::string formatSummary(const RunSummary& r) {
  std::ostringstream os;
  auto opt = [](const std::optional<double>& v, const char* unit) {
    if (!v) return std::string("-");
    char b[32];
    std::snprintf(b, sizeof b, "%.3f %s", *v, unit);
    return std::string(b);
  };
  char line[160];
  os << "scenario   " << r.scenario << " (" << r.mode << ")\n";
  os << "outcome    " << r.outcome << (r.error_message.empty() ? "" : ": " + r.error_message) << "\n";
  os << "counts     handovers " << r.handovers << ", aborts " << r.aborts << ", retries " << r.retries << "\n";
  os << "timing     grasp at " << opt(r.time_to_grasp, "s") << ", hand still to grasp "
     << opt(r.hand_still_to_grasp, "s") << ", total " << opt(r.total_time, "s") << "\n";
  std::snprintf(line, sizeof line, "safety     min distance to person %.3f m, contacts %d, dropped %s\n",
                r.min_human_distance, r.human_contacts, r.object_dropped ? "yes" : "no");
  os << line;
  if (r.tracker != "simulated" || r.rejected_samples > 0 || r.person_unseen_time > 0.0) {
    os << "tracker    " << r.tracker << ", " << r.rejected_samples << " samples rejected";
    bool first = true;
    for (const auto& [why, n] : r.rejected_by_reason) {
      if (n == 0) continue;
      os << (first ? " (" : ", ") << why << " " << n;
      first = false;
    }
    if (!first) os << ")";
    std::snprintf(line, sizeof line, "; person unseen %.2f s\n", r.person_unseen_time);
    os << line;
  }
  for (const auto& s : r.person_slowed) os << "person     " << s << "\n";
  std::snprintf(line, sizeof line,
                "limits     position %d, velocity %d, torque %d steps; QP failures %d, relaxed %d; limit guard %d\n",
                r.limit_violations.position, r.limit_violations.velocity, r.limit_violations.torque, r.qp_failures,
                r.qp_relaxed, r.limit_guard_steps);
  os << line;
  if (r.grasp_error_pos) {
    std::snprintf(line, sizeof line, "grasp      error %.1f mm, %.1f deg\n", *r.grasp_error_pos * 1000.0,
                  r.grasp_error_rot_deg.value_or(0.0));
    os << line;
  }
  std::snprintf(line, sizeof line, "compute    control step median %.1f us, p99 %.1f us, max %.1f us; %.1fx real time\n",
                r.control_step_us.median, r.control_step_us.p99, r.control_step_us.max, r.realtime_factor);
  os << line;
  os << "states     ";
  for (std::size_t i = 0; i < r.states.size(); ++i) os << (i ? " > " : "") << r.states[i];
  os << "\n";
  for (const auto& e : r.expectation_failures) os << "EXPECTED   " << e << "\n";
  return os.str();
}

}  // namespace handover::app
