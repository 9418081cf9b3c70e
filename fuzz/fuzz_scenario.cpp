// Scenario parser (YAML text -> Scenario, with every check of the parser).
// A relative `config:` resolves against the shipped tree, so seeds from
// scenes/scenarios exercise the controller-config path too.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/input_error.hpp"
#include "scenes/scenario/scenario_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    handover::scenario::parseScenarioString(text, std::string(HANDOVER_SOURCE_DIR) + "/scenes/scenarios/fuzz.yaml");
  } catch (const handover::InputError&) {
    // refused with a message: the expected outcome for most inputs
  }
  return 0;
}
