// The states entered, in order, with the time of entry. Capacity is reserved
// at load; when it is full further entries are counted but not kept, so
// record() never allocates (RT safe).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace handover::fsm {

class State;

struct HistoryEntry {
  double time = 0.0;             ///< s, when the state started
  const State* state = nullptr;  ///< owned by the machine
  bool interrupt = false;        ///< entered because an interrupt preempted the active path
  const std::string& path() const;
};

class History {
 public:
  void reserve(std::size_t capacity);
  void record(double time, const State* state, bool interrupt) noexcept;
  void clear() noexcept;
  const std::vector<HistoryEntry>& entries() const { return entries_; }
  std::size_t dropped() const { return dropped_; }
  /// Full paths in order (copies; not RT safe; for reports and tests).
  std::vector<std::string> paths() const;

 private:
  std::vector<HistoryEntry> entries_;
  std::size_t dropped_ = 0;
};

}  // namespace handover::fsm
