// Choosing the abstract camera a view renders from.
#pragma once

#include <mujoco/mujoco.h>

#include <string>

namespace handover::render {

/// Name of the scene's fixed camera that frames the whole handover.
inline constexpr const char* kOverviewCamera = "overview";

/// Geometry capacity of a view's abstract scene: the arm's meshes, the person
/// and the decorations fit with room to spare.
inline constexpr int kSceneMaxGeoms = 4000;

/// A free camera that looks at the handover workspace (world frame, design
/// notes 1: robot at the origin, person at x ~ 1 m): from the side (-y),
/// slightly above, robot on the left, person on the right.
mjvCamera workspaceCamera();

/// The camera called `name` as an mjvCamera of type mjCAMERA_FIXED. If the
/// model has no such camera: the workspace camera when `name` is empty or
/// the default "overview" (small test models have none), otherwise
/// handover::InputError listing the cameras the model has. `note` (optional)
/// receives a sentence saying which camera was chosen and why.
mjvCamera cameraByName(const mjModel* m, const std::string& name, std::string* note = nullptr);

}  // namespace handover::render
