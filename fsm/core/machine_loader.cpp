#include "fsm/core/machine_loader.hpp"

#include <algorithm>
#include <cmath>

#include "fsm/core/meta_state.hpp"

namespace handover::fsm {

namespace {

constexpr int kMaxDepth = 16;

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s.empty() ? "none" : s;
}

const YamlReader* lookup(const MachineLoader::Scope& scope, const std::string& name,
                         const MachineLoader::Scope** found) {
  for (const MachineLoader::Scope* s = &scope; s; s = s->parent) {
    auto it = s->defs.find(name);
    if (it != s->defs.end()) {
      *found = s;
      return &it->second;
    }
  }
  return nullptr;
}

std::vector<std::string> visibleNames(const MachineLoader::Scope& scope) {
  std::vector<std::string> names;
  for (const MachineLoader::Scope* s = &scope; s; s = s->parent) {
    for (const auto& kv : s->defs) {
      if (std::find(names.begin(), names.end(), kv.first) == names.end()) names.push_back(kv.first);
    }
  }
  return names;
}

void checkName(const YamlReader& where, const std::string& name) {
  if (name.empty() || name.find('/') != std::string::npos || name.find(' ') != std::string::npos) {
    where.fail("'" + name + "' is not a valid state name (no '/', no spaces, not empty)");
  }
}

}  // namespace

MachineLoader::Scope MachineLoader::makeScope(const YamlReader& def, const Scope* parent) {
  Scope scope;
  scope.parent = parent;
  if (auto states = def.optionalChild("states")) {
    if (!states->isMap()) states->fail("expected a map of state definitions");
    for (const std::string& name : states->keys()) {
      YamlReader d = states->child(name);
      checkName(d, name);
      if (!d.isMap()) d.fail("expected a map with at least 'type'");
      scope.defs.emplace(name, d);
    }
  }
  return scope;
}

std::unique_ptr<State> MachineLoader::instantiate(const std::string& name, const Scope& scope,
                                                  const std::string& prefix, const YamlReader& where,
                                                  int depth, const Machine** inner_out) {
  const Scope* found = nullptr;
  const YamlReader* def = lookup(scope, name, &found);
  if (!def) where.fail("unknown state '" + name + "' (defined: " + join(visibleNames(scope)) + ")");
  const std::string path = prefix.empty() ? name : prefix + "/" + name;
  const YamlReader type_key = def->child("type");
  const std::string type = type_key.asString();

  std::unique_ptr<State> state;
  *inner_out = nullptr;
  if (type == Registry::metaType()) {
    if (depth >= kMaxDepth) def->fail("meta states nested too deep (does '" + name + "' contain itself?)");
    Scope inner_scope = makeScope(*def, found);
    std::unique_ptr<Machine> inner = build(*def, inner_scope, path, {}, depth + 1);
    *inner_out = inner.get();
    state = std::make_unique<MetaState>(std::move(inner));
  } else {
    state = registry_.makeState(type);
    if (!state) type_key.fail("unknown state type '" + type + "' (known: " + registry_.stateTypes() + ")");
  }
  state->name_ = name;
  state->path_ = path;
  if (auto t = def->optionalChild("timeout")) {
    const double timeout = t->asDouble();
    if (!(timeout > 0.0)) t->fail("timeout must be > 0 s, got " + std::to_string(timeout));
    state->timeout_ = timeout;
  }
  if (type != Registry::metaType()) state->configure(*def);
  def->finish();
  return state;
}

std::unique_ptr<Machine> MachineLoader::build(const YamlReader& def, const Scope& scope, const std::string& prefix,
                                              const Extra& extra_states, int depth) {
  auto m = std::make_unique<Machine>();
  m->history_ = history_;

  // exits declared up front
  if (auto outs = def.optionalChild("outputs")) {
    if (!outs->isSequence()) outs->fail("expected a list of exit names");
    for (std::size_t i = 0; i < outs->size(); ++i) {
      const YamlReader o = outs->at(i);
      const std::string e = o.asString();
      checkName(o, e);
      if (std::find(m->exits_.begin(), m->exits_.end(), e) != m->exits_.end()) o.fail("duplicate exit '" + e + "'");
      const Scope* f = nullptr;
      if (lookup(scope, e, &f) && f == &scope) o.fail("'" + e + "' is both an exit and a state of this machine");
      m->exits_.push_back(e);
    }
  }
  auto isExit = [&](const std::string& n) {
    return std::find(m->exits_.begin(), m->exits_.end(), n) != m->exits_.end();
  };

  struct Row {
    std::string from, output, to;
    YamlReader entry;
  };
  std::vector<Row> rows;
  if (auto table = def.optionalChild("transitions")) {
    if (!table->isSequence()) table->fail("expected a list of [from, output, to] entries");
    for (std::size_t i = 0; i < table->size(); ++i) {
      const YamlReader e = table->at(i);
      if (!e.isSequence() || e.size() != 3) e.fail("expected [from, output, to]");
      rows.push_back(Row{e.at(0).asString(), e.at(1).asString(), e.at(2).asString(), e});
    }
  }

  // instantiate every state named, in order of first mention
  const YamlReader initial_key = def.child("initial");
  const std::string initial = initial_key.asString();
  std::vector<std::pair<std::string, YamlReader>> names;
  auto mention = [&](const std::string& n, const YamlReader& where) {
    for (const auto& p : names) {
      if (p.first == n) return;
    }
    names.emplace_back(n, where);
  };
  if (isExit(initial)) initial_key.fail("'" + initial + "' is an exit, not a state");
  mention(initial, initial_key);
  for (const Row& r : rows) {
    if (isExit(r.from)) r.entry.at(0).fail("'" + r.from + "' is an exit of this machine, not a state");
    mention(r.from, r.entry.at(0));
    if (!isExit(r.to)) mention(r.to, r.entry.at(2));
  }
  for (const auto& e : extra_states) mention(e.first, e.second);

  for (const auto& p : names) {
    Machine::Node node;
    node.state = instantiate(p.first, scope, prefix, p.second, depth, &node.inner);
    if (std::isfinite(node.state->timeout())) {
      node.timeout_output = node.state->declareOutput(State::timeoutOutput());
    }
    node.next.assign(node.state->outputs().size(), Machine::Target{});
    m->nodes_.push_back(std::move(node));
  }
  m->initial_ = 0;

  // resolve the table
  for (const Row& r : rows) {
    const int from = m->findState(r.from);
    Machine::Node& node = m->nodes_[static_cast<std::size_t>(from)];
    const int out = node.state->findOutput(r.output);
    if (out < 0) {
      r.entry.at(1).fail("state '" + r.from + "' has no output '" + r.output + "' (outputs: " +
                         join(node.state->outputs()) + ")");
    }
    Machine::Target& t = node.next[static_cast<std::size_t>(out)];
    if (t.state >= 0 || t.exit >= 0) {
      r.entry.fail("duplicate transition for ('" + r.from + "', '" + r.output + "')");
    }
    if (isExit(r.to)) {
      t.exit = static_cast<int>(std::find(m->exits_.begin(), m->exits_.end(), r.to) - m->exits_.begin());
    } else {
      t.state = m->findState(r.to);
    }
  }
  // outputs without a row leave the machine under their own name
  for (Machine::Node& node : m->nodes_) {
    for (std::size_t o = 0; o < node.next.size(); ++o) {
      Machine::Target& t = node.next[o];
      if (t.state >= 0 || t.exit >= 0) continue;
      const std::string& out = node.state->outputs()[o];
      auto it = std::find(m->exits_.begin(), m->exits_.end(), out);
      if (it == m->exits_.end()) {
        m->exits_.push_back(out);
        it = m->exits_.end() - 1;
      }
      t.exit = static_cast<int>(it - m->exits_.begin());
    }
  }
  return m;
}

}  // namespace handover::fsm
