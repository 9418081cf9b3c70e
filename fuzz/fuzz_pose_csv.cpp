// Tracker recording (CSV text -> samples): header, BOM, line bounds, numbers.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/input_error.hpp"
#include "perception/csv_pose_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    handover::perception::parsePoseCsv(text, "fuzz.csv");
  } catch (const handover::InputError&) {
  }
  return 0;
}
