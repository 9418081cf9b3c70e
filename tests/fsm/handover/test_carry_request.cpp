// The carry request/answer channel (fsm/handover/carry_request.hpp): every
// request gets a new id, an answer is found only under the id of the request
// it answered, a newer request replaces one still waiting, and a withdrawn
// request is not answered.
#include <gtest/gtest.h>

#include "fsm/handover/carry_request.hpp"

namespace handover::fsm::test {
namespace {

ArmPlacement placementAt(double q_mark) {
  ArmPlacement p;
  p.found = true;
  p.q = Vector7::Constant(q_mark);
  p.tcp.translation() = Vector3(0.3, 0.0, q_mark);
  return p;
}

int postAt(CarryChannel& channel, double x) {
  Isometry object_in_tcp = Isometry::Identity();
  object_in_tcp.translation() = Vector3(0.0, 0.0, 0.08);
  return channel.post(object_in_tcp, Vector3::UnitZ(), Vector3(x, 0.0, 0.4), Vector7::Constant(x));
}

TEST(CarryChannel, AnAnswerIsFoundUnderItsRequestsIdOnly) {
  CarryChannel channel;
  EXPECT_FALSE(channel.pending());
  EXPECT_EQ(channel.answerTo(0), nullptr);
  const int a = postAt(channel, 0.3);
  EXPECT_GT(a, 0);
  EXPECT_TRUE(channel.pending());
  EXPECT_EQ(channel.request().id, a);
  EXPECT_TRUE(channel.request().object_position.isApprox(Vector3(0.3, 0.0, 0.4)));
  EXPECT_TRUE(channel.request().q.isApprox(Vector7::Constant(0.3)));
  EXPECT_EQ(channel.answerTo(a), nullptr);  // not answered yet
  channel.answer(placementAt(0.5));
  EXPECT_FALSE(channel.pending());
  ASSERT_NE(channel.answerTo(a), nullptr);
  EXPECT_TRUE(channel.answerTo(a)->q.isApprox(Vector7::Constant(0.5)));
  // the next request (another state, or the same one started again) does not see it
  const int b = postAt(channel, 0.4);
  EXPECT_NE(b, a);
  EXPECT_EQ(channel.answerTo(b), nullptr);
  channel.answer(placementAt(0.6));
  ASSERT_NE(channel.answerTo(b), nullptr);
  EXPECT_TRUE(channel.answerTo(b)->q.isApprox(Vector7::Constant(0.6)));
  EXPECT_EQ(channel.answerTo(a), nullptr);  // the old answer is gone with its id
}

TEST(CarryChannel, ANewerRequestReplacesOneStillWaiting) {
  CarryChannel channel;
  const int a = postAt(channel, 0.3);
  const int b = postAt(channel, 0.4);
  EXPECT_TRUE(channel.pending());
  EXPECT_EQ(channel.request().id, b);
  channel.answer(placementAt(0.6));  // answers b, the request now in the slot
  EXPECT_EQ(channel.answerTo(a), nullptr);
  EXPECT_NE(channel.answerTo(b), nullptr);
}

TEST(CarryChannel, AWithdrawnRequestIsNotAnswered) {
  CarryChannel channel;
  const int a = postAt(channel, 0.3);
  channel.withdraw(a + 1);  // not the request waiting: no effect
  EXPECT_TRUE(channel.pending());
  channel.withdraw(a);
  EXPECT_FALSE(channel.pending());
  channel.answer(placementAt(0.5));  // nothing to answer
  EXPECT_EQ(channel.answerTo(a), nullptr);
  // withdrawing an answered request keeps its answer (the id is spent anyway)
  const int b = postAt(channel, 0.4);
  channel.answer(placementAt(0.6));
  channel.withdraw(b);
  EXPECT_NE(channel.answerTo(b), nullptr);
}

}  // namespace
}  // namespace handover::fsm::test
