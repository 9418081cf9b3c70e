// The physical bounds a scenario's values must keep (docs/scenarios.md,
// "Bounds"). Each is a property of the hardware or of the scene, not a guess:
// the Panda gripper's opening, the person's reach, the estimator's design.
#pragma once

namespace handover::scenario {

constexpr double kMinObjectSize = 0.005;   ///< m: below this MuJoCo's contact margins dominate
constexpr double kMinObjectMass = 0.01;    ///< kg: a real inertia for the simulator
constexpr double kMinDensity = 10.0;       ///< kg/m^3: lighter than any foam
constexpr double kMaxDensity = 20000.0;    ///< kg/m^3: denser than tungsten
constexpr double kMaxGraspToSurface = 0.02;   ///< m: the grasp frame lies inside the object or this close to it
constexpr double kMaxHoldToSurface = 0.03;    ///< m: the person's grip point lies inside the object or this close to it
constexpr double kStartQSafety = 0.01;        ///< fraction of each joint range kept free at start (controller's safety zone)
constexpr double kMinStandDistance = 0.4;     ///< m, the person's feet from the robot base: the chest (a 2 m person's trunk: 0.13 m half depth) stays 0.2 m clear of the base column
constexpr double kMaxStandDistance = 3.0;     ///< m
constexpr double kMaxNoisePos = 0.02;         ///< m per sample: above, the 2 cm grasp tolerance is noise
constexpr double kMaxNoiseRotDeg = 10.0;      ///< deg per sample
constexpr double kMaxOffsetPos = 0.10;        ///< m of calibration error
constexpr double kMaxOffsetRot = 0.2;         ///< rad of calibration error

}  // namespace handover::scenario
