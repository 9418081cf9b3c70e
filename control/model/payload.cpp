// Held object: merged into body 7's inertia (Data::body7_with_payload).
#include <cmath>
#include <string>

#include "config/input_error.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/rigid_inertia.hpp"

namespace handover::control {

void setPayload(const Model& model, Data& data, const Payload& payload) {
  if (!(payload.mass >= 0.0) || !std::isfinite(payload.mass) || !payload.com.allFinite() ||
      !payload.inertia_com.allFinite()) {
    throw InputError("setPayload: payload mass must be finite and >= 0 (got " + std::to_string(payload.mass) +
                     ") with a finite com and inertia");
  }
  const Frame& tcp = model.frames[model.frameId("tcp")];
  Inertia in;
  in.mass = payload.mass;
  in.com = payload.com;
  in.inertia_com = payload.inertia_com;
  // tcp axes -> body-7 axes; the tcp sits on body 7
  data.body7_with_payload = combineInertia(model.inertias[kArmDofs], transformInertia(in, tcp.placement));
  data.has_payload = true;
}

void clearPayload(const Model& model, Data& data) {
  data.body7_with_payload = model.inertias[kArmDofs];
  data.has_payload = false;
}

}  // namespace handover::control
