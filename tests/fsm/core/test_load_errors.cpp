// Bad state machine files are rejected at load with the file, key and line.
#include <gtest/gtest.h>

#include "fsm/core/state_machine.hpp"
#include "tests/fsm/core/test_states.hpp"

namespace handover::fsm::test {
namespace {

std::string loadError(const std::string& yaml) {
  const Registry registry = testRegistry();
  try {
    StateMachine sm(YamlReader::loadString(yaml, "bad.yaml"), registry);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectError(const std::string& yaml, const std::string& location, const std::string& words) {
  const std::string msg = loadError(yaml);
  ASSERT_FALSE(msg.empty()) << "no error for:\n" << yaml;
  EXPECT_NE(msg.find(location), std::string::npos) << msg;
  EXPECT_NE(msg.find(words), std::string::npos) << msg;
}

const char* kHead = R"(states:
  A: {type: Scripted, outputs: [Go]}
  B: {type: Scripted, outputs: [Go]}
initial: A
)";

TEST(FsmLoadErrors, ValidFileLoads) {
  EXPECT_EQ(loadError(std::string(kHead) + "transitions: [[A, Go, B]]\n"), "");
}

TEST(FsmLoadErrors, UnknownStateInTable) {
  expectError(std::string(kHead) + "transitions:\n  - [A, Go, B]\n  - [B, Go, C]\n",
              "bad.yaml:7: key 'transitions[1][2]'", "unknown state 'C'");
}

TEST(FsmLoadErrors, UnknownOutput) {
  expectError(std::string(kHead) + "transitions:\n  - [A, Went, B]\n", "bad.yaml:6: key 'transitions[0][1]'",
              "state 'A' has no output 'Went' (outputs: Go)");
}

TEST(FsmLoadErrors, TimeoutOutputOnlyWithTimeout) {
  expectError(std::string(kHead) + "transitions:\n  - [A, Timeout, B]\n", "transitions[0][1]",
              "no output 'Timeout'");
}

TEST(FsmLoadErrors, DuplicateTransition) {
  expectError(std::string(kHead) + "transitions:\n  - [A, Go, B]\n  - [A, Go, A]\n", "bad.yaml:7",
              "duplicate transition for ('A', 'Go')");
}

TEST(FsmLoadErrors, UnknownInitial) {
  expectError("states:\n  A: {type: Scripted}\ninitial: Z\n", "bad.yaml:3: key 'initial'", "unknown state 'Z'");
}

TEST(FsmLoadErrors, UnknownType) {
  expectError("states:\n  A: {type: Scripted}\n  B:\n    type: Nope\ninitial: B\n", "bad.yaml:4: key 'states.B.type'",
              "unknown state type 'Nope' (known: Meta | Scripted)");
}

TEST(FsmLoadErrors, UnknownKeyInStateDefinition) {
  expectError("states:\n  A:\n    type: Scripted\n    cycels: 3\ninitial: A\n", "bad.yaml:4: key 'states.A.cycels'",
              "unknown key 'cycels'");
}

TEST(FsmLoadErrors, BadTimeout) {
  expectError("states:\n  A: {type: Scripted, timeout: -1}\ninitial: A\n", "key 'states.A.timeout'",
              "timeout must be > 0");
  expectError("states:\n  A: {type: Scripted, timeout: soon}\ninitial: A\n", "key 'states.A.timeout'",
              "expected a number");
}

TEST(FsmLoadErrors, MalformedRow) {
  expectError(std::string(kHead) + "transitions:\n  - [A, Go]\n", "bad.yaml:6: key 'transitions[0]'",
              "expected [from, output, to]");
}

TEST(FsmLoadErrors, UnknownKeyAtTop) {
  expectError(std::string(kHead) + "transitons: []\n", "bad.yaml:5: key 'transitons'", "unknown key");
}

TEST(FsmLoadErrors, InnerErrorsNameTheInnerKey) {
  expectError(R"(states:
  M:
    type: Meta
    states:
      X: {type: Scripted, outputs: [Go]}
    initial: X
    transitions:
      - [X, Go, Y]
initial: M
)",
              "bad.yaml:8: key 'states.M.transitions[0][2]'", "unknown state 'Y'");
}

TEST(FsmLoadErrors, RecursiveMetaIsRejected) {
  expectError("states:\n  M: {type: Meta, initial: M}\ninitial: M\n", "states.M", "nested too deep");
}

TEST(FsmLoadErrors, ExitUsedAsSource) {
  expectError(std::string(kHead) + "outputs: [End]\ntransitions:\n  - [End, Go, A]\n", "transitions[0][0]",
              "is an exit of this machine");
}

TEST(FsmLoadErrors, InterruptErrors) {
  const std::string base = std::string(kHead) + "interrupts:\n";
  expectError(base + "  - {name: s, condition: {type: Flag}, preempt: Zed}\n", "interrupts[0].preempt",
              "unknown state 'Zed'");
  expectError(base + "  - {name: s, condition: {type: Flog}, preempt: B}\n", "interrupts[0].condition.type",
              "unknown condition type 'Flog'");
  expectError(base + "  - {name: s, condition: {type: Flag, flag: 7}, preempt: B}\n",
              "interrupts[0].condition.flag", "out of range");
  expectError(base + "  - {name: s, condition: {type: Flag}, preempt: B, except: [Q]}\n",
              "interrupts[0].except[0]", "not a state of the top-level machine");
  expectError(base + "  - {name: s, condition: {type: Flag}}\n", "interrupts[0]", "exactly one of");
  expectError(base + "  - {name: s, condition: {type: Flag}, preempt: B, extra: 1}\n", "interrupts[0].extra",
              "unknown key");
}

}  // namespace
}  // namespace handover::fsm::test
