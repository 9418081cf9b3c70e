#include "fsm/core/state_machine.hpp"

#include <algorithm>

#include "fsm/core/machine_loader.hpp"

namespace handover::fsm {

StateMachine::~StateMachine() = default;

StateMachine::StateMachine(const YamlReader& def, const Registry& registry)
    : history_(std::make_unique<History>()) {
  if (!def.isMap()) def.fail("expected a state machine definition (a map)");
  const int capacity = def.getInt("history_capacity", 4096);
  if (capacity < 1 || capacity > 10000000) def.child("history_capacity").fail("must be in [1, 10000000]");
  history_->reserve(static_cast<std::size_t>(capacity));

  // interrupts first: their preempt targets must exist in the root machine
  struct Raw {
    YamlReader entry;
    std::string target;
    bool overlay;
  };
  std::vector<Raw> raws;
  MachineLoader::Extra targets;
  std::optional<YamlReader> list = def.optionalChild("interrupts");
  if (list) {
    if (!list->isSequence()) list->fail("expected a list of interrupts");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const YamlReader e = list->at(i);
      if (!e.isMap()) e.fail("expected a map with name, condition and preempt or overlay");
      const bool has_p = e.has("preempt"), has_o = e.has("overlay");
      if (has_p == has_o) e.fail("give exactly one of 'preempt' (a state) or 'overlay' (a state)");
      const std::string target = e.getString(has_p ? "preempt" : "overlay");
      if (has_p) targets.emplace_back(target, e.child("preempt"));
      raws.push_back(Raw{e, target, has_o});
    }
  }

  MachineLoader loader(registry, history_.get());
  MachineLoader::Scope scope = MachineLoader::makeScope(def, nullptr);
  root_ = loader.build(def, scope, "", targets);

  for (const Raw& r : raws) {
    Interrupt it;
    it.name = r.entry.getString("name");
    for (const Interrupt& other : interrupts_) {
      if (other.name == it.name) r.entry.child("name").fail("duplicate interrupt name '" + it.name + "'");
    }
    const YamlReader cdef = r.entry.child("condition");
    if (!cdef.isMap()) cdef.fail("expected a map with 'type'");
    const YamlReader ctype = cdef.child("type");
    it.condition = registry.makeCondition(ctype.asString());
    if (!it.condition) {
      ctype.fail("unknown condition type '" + ctype.asString() + "' (known: " + registry.conditionTypes() + ")");
    }
    it.condition->configure(cdef);
    cdef.finish();
    if (r.overlay) {
      const Machine* inner = nullptr;
      it.overlay = loader.instantiate(r.target, scope, "", r.entry.child("overlay"), 0, &inner);
      if (inner) r.entry.child("overlay").fail("an overlay must be a simple state, not a meta state");
    } else {
      it.preempt_target = root_->findState(r.target);
    }
    if (auto ex = r.entry.optionalChild("except")) {
      if (!ex->isSequence()) ex->fail("expected a list of top-level state names");
      for (std::size_t k = 0; k < ex->size(); ++k) {
        const std::string n = ex->at(k).asString();
        const int idx = root_->findState(n);
        if (idx < 0) ex->at(k).fail("'" + n + "' is not a state of the top-level machine");
        it.except.push_back(idx);
      }
    }
    r.entry.finish();
    interrupts_.push_back(std::move(it));
  }
  def.finish();
}

const std::string& StateMachine::activePath() const {
  static const std::string kNone;
  const State* s = root_->innermostActive();
  return s ? s->path() : kNone;
}

void StateMachine::start(Context& ctx) {
  history_->clear();
  started_ = true;
  root_->start(ctx);
}

bool StateMachine::excepted(const Interrupt& it) const {
  const int active = root_->activeIndex();
  return std::find(it.except.begin(), it.except.end(), active) != it.except.end();
}

void StateMachine::step(Context& ctx) {
  if (!started_) start(ctx);
  bool preempted = false;
  for (Interrupt& it : interrupts_) {
    // every condition is evaluated every cycle so filters inside stay current
    const bool holds = it.condition->evaluate(ctx) && root_->running() && !excepted(it);
    if (it.overlay) {
      if (holds && !it.active) {
        it.active = true;
        ++it.fired;
        it.overlay->start_time_ = ctx.time;
        history_->record(ctx.time, it.overlay.get(), true);
        it.overlay->start(ctx);
      } else if (!holds && it.active) {
        it.active = false;
        it.overlay->teardown(ctx);
      }
      if (it.active) it.overlay->run(ctx);
    } else {
      it.active = holds;
      if (holds && !preempted && root_->activeIndex() != it.preempt_target) {
        preempted = true;
        ++it.fired;
        root_->preempt(ctx, it.preempt_target);
      }
    }
  }
  if (!preempted) root_->step(ctx);
}

void StateMachine::stop(Context& ctx) {
  root_->stop(ctx);
  for (Interrupt& it : interrupts_) {
    if (it.overlay && it.active) {
      it.active = false;
      it.overlay->teardown(ctx);
    }
  }
}

}  // namespace handover::fsm
