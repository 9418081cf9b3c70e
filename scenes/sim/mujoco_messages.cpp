#include "scenes/sim/mujoco_messages.hpp"

#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include <mujoco/mujoco.h>

namespace handover::sim {
namespace {

thread_local char last_warning[512] = "";

void onWarning(const char* msg) {
  // remembered, not printed and not written to MUJOCO_LOG.TXT
  std::strncpy(last_warning, msg ? msg : "", sizeof(last_warning) - 1);
  last_warning[sizeof(last_warning) - 1] = '\0';
}

[[noreturn]] void onError(const char* msg) {
  // MuJoCo's default ends the process (exit 1) after writing MUJOCO_LOG.TXT
  throw std::runtime_error(std::string("MuJoCo error: ") + (msg ? msg : "(no message)"));
}

}  // namespace

void installMujocoMessageHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_warning = onWarning;
    mju_user_error = onError;
  });
}

const char* lastMujocoWarning() { return last_warning; }

void clearMujocoWarning() { last_warning[0] = '\0'; }

}  // namespace handover::sim
