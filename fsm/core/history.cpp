#include "fsm/core/history.hpp"

#include "fsm/core/state.hpp"

namespace handover::fsm {

const std::string& HistoryEntry::path() const { return state->path(); }

void History::reserve(std::size_t capacity) { entries_.reserve(capacity); }

void History::record(double time, const State* state, bool interrupt) noexcept {
  if (entries_.size() < entries_.capacity()) {
    entries_.push_back(HistoryEntry{time, state, interrupt});
  } else {
    ++dropped_;
  }
}

void History::clear() noexcept {
  entries_.clear();
  dropped_ = 0;
}

std::vector<std::string> History::paths() const {
  std::vector<std::string> out;
  out.reserve(entries_.size());
  for (const auto& e : entries_) out.push_back(e.path());
  return out;
}

}  // namespace handover::fsm
