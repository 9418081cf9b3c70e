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
// - a receiver who takes the object where the robot waits with it (a book
//   held by its top hanging into their reach at the ready pose) and pulls it
//   away: the robot held on, took the hand leaving with the book for a
//   withdrawal and lost it; it now lets go (fsm/handover/receiver_take.hpp).
// - a receiver who pulls the object toward themselves along the axis the
//   fingers close along: the open fingers held it, the person (who does not
//   yield) dragged the arm along and the wrist past its velocity limit as it
//   came free (unsafe). The presentation now turns the fingers across the
//   pull (control/grasp/grasp_score.hpp exitBlock), and the box, declared
//   deeper than the palm lets it sit, starts in front of the palm
//   (app/run/world_setup.hpp robotHeldObject).
// - a deck of cards 2 cm thick held from above near one end: presented with
//   its centre 5 cm above the receiver's grip point (a ball's height), its
//   underside floated 4 cm up, beyond the 3 cm a person closes a hand within;
//   nobody took it and the give timed out after two retries. It is now
//   seated with its underside 2 cm above the grip point
//   (fsm/handover/seated_in_hand.hpp).
#include <gtest/gtest.h>

#include "tests/app/run/run_repo_file.hpp"

namespace handover {
namespace {

/// Runs tests/app/run/data/<file>: one handover, at the first attempt, within every limit, nobody touched.
app::RunSummary expectOneCleanHandover(const std::string& scratch, const std::string& file) {
  const testing::ScratchDir dir(scratch);
  const app::RunSummary r = testing::runRepoFile(dir, "tests/app/run/data/" + file);
  EXPECT_EQ(r.outcome, "success") << file;
  EXPECT_EQ(r.handovers, 1) << file;
  EXPECT_EQ(r.aborts, 0) << file;
  EXPECT_EQ(r.human_contacts, 0) << file;
  EXPECT_EQ(r.limit_violations.position + r.limit_violations.velocity + r.limit_violations.torque, 0) << file;
  EXPECT_EQ(r.qp_failures, 0) << file;
  return r;
}

TEST(GiveGeometry, ASmallBallIsPutOntoAHighPalmWithTheFingersLevel) {
  testing::expectSuccessAtTheFirstAttempt("ball_high_palm", "r2h_ball_on_high_palm.yaml", "/Present");
}

TEST(GiveGeometry, AReceiverWhoTakesTheObjectWhereTheRobotWaitsWithItIsHandedIt) {
  const app::RunSummary r = expectOneCleanHandover("taken_while_waiting", "r2h_taken_while_waiting.yaml");
  EXPECT_EQ(testing::stateVisits(r, "/Present"), 0) << "taken before it was presented";
  EXPECT_EQ(testing::stateVisits(r, "/Release"), 1);
}

TEST(GiveGeometry, AReceiverWhoPullsTheObjectTowardThemselvesIsNotDraggingTheArm) {
  expectOneCleanHandover("pulled_toward_receiver", "r2h_pulled_toward_the_receiver.yaml");
}

TEST(GiveGeometry, AFlatObjectIsSeatedOnTheReceiversHand) {
  expectOneCleanHandover("flat_card_deck", "r2h_flat_card_deck.yaml");
}

}  // namespace
}  // namespace handover
