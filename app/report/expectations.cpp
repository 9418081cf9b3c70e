#include "app/report/expectations.hpp"

#include <sstream>

namespace handover::app {

std::vector<std::string> checkExpectations(const scenario::Scenario& sc, const RunSummary& r) {
  std::vector<std::string> bad;
  const auto& e = sc.expect;
  auto fmt = [](double v) {
    std::ostringstream os;
    os << v;
    return os.str();
  };
  if (e.outcome && *e.outcome != r.outcome) bad.push_back("outcome: expected " + *e.outcome + ", got " + r.outcome);
  if (e.aborts && *e.aborts != r.aborts)
    bad.push_back("aborts: expected " + std::to_string(*e.aborts) + ", got " + std::to_string(r.aborts));
  if (e.retries && *e.retries != r.retries)
    bad.push_back("retries: expected " + std::to_string(*e.retries) + ", got " + std::to_string(r.retries));
  if (e.handovers && *e.handovers != r.handovers)
    bad.push_back("handovers: expected " + std::to_string(*e.handovers) + ", got " + std::to_string(r.handovers));
  if (e.max_total_time && !(r.total_time && *r.total_time <= *e.max_total_time))
    bad.push_back("max_total_time: expected <= " + fmt(*e.max_total_time) + " s, got " +
                  (r.total_time ? fmt(*r.total_time) + " s" : std::string("none")));
  if (e.min_human_distance && !(r.min_human_distance >= *e.min_human_distance))
    bad.push_back("min_human_distance: expected >= " + fmt(*e.min_human_distance) + " m, got " +
                  fmt(r.min_human_distance) + " m");
  if (e.max_time_to_grasp && !(r.time_to_grasp && *r.time_to_grasp <= *e.max_time_to_grasp))
    bad.push_back("max_time_to_grasp: expected <= " + fmt(*e.max_time_to_grasp) + " s, got " +
                  (r.time_to_grasp ? fmt(*r.time_to_grasp) + " s" : std::string("none")));
  if (e.max_human_contacts && r.human_contacts > *e.max_human_contacts)
    bad.push_back("max_human_contacts: expected <= " + std::to_string(*e.max_human_contacts) + ", got " +
                  std::to_string(r.human_contacts));
  if (e.object_dropped && *e.object_dropped != r.object_dropped)
    bad.push_back(std::string("object_dropped: expected ") + (*e.object_dropped ? "true" : "false"));
  return bad;
}

}  // namespace handover::app
