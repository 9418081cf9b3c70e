// Gives the benchmark's contract allows that the robot used to miss for want
// of knowing its own geometry (issue 12), end to end in the simulator:
// - a small ball held from the top, put onto a palm high and to the side:
//   the planner preferred it tilted across the axis the fingers close along
//   to upright (the arm further from its limits), and one fingertip dipped
//   toward the palm; the constraint
//   that keeps the gripper off the hand held the ball 3 cm high, out of the
//   receiver's reach, until the give timed out. The presentation is now
//   scored with how far that keep holds it short (control/grasp/clearance.hpp
//   keepShortfall) and may tilt along the closing axis too
//   (runtime/grasp_planning.cpp).
#include <gtest/gtest.h>

#include "tests/app/run/run_repo_file.hpp"

namespace handover {
namespace {

TEST(GiveGeometry, ASmallBallIsPutOntoAHighPalmWithTheFingersLevel) {
  testing::expectSuccessAtTheFirstAttempt("ball_high_palm", "r2h_ball_on_high_palm.yaml", "/Present");
}

}  // namespace
}  // namespace handover
