// MuJoCo's own warnings and errors, kept in the process: by default MuJoCo
// 2.2.2 prints them and appends them to MUJOCO_LOG.TXT in the current
// working folder (the user's), and exits the process on an error. Once
// installed (Simulation::load does it), a warning is only remembered (the
// last one, per thread: the run quotes it when it reports a divergence) and
// an error throws std::runtime_error("MuJoCo error: ..."), which a run
// reports as outcome `error`.
//
// The handlers are process-wide function pointers (mju_user_warning,
// mju_user_error); installing is idempotent and thread safe. The warning
// handler allocates nothing (a fixed per-thread buffer).
#pragma once

namespace handover::sim {

/// Installs the handlers (once per process; later calls do nothing).
void installMujocoMessageHandlers();

/// The last MuJoCo warning raised on this thread ("" if none since the last
/// clearMujocoWarning()).
const char* lastMujocoWarning();
void clearMujocoWarning();

}  // namespace handover::sim
