#include "scene/path_automaton.h"

#include <algorithm>
#include <map>
#include <utility>

namespace gib::scene {

namespace {

constexpr int kEpsilon = -1;

struct Nfa {
  struct Edge {
    int symbol;  // a PathEvent, or kEpsilon
    int to;
  };
  std::vector<std::vector<Edge>> out;
  int start = 0, accept = 0;
};

struct TooLarge {};

// Thompson's construction: every fragment has one entry and one exit state; a counted part is
// built once per copy, so the state count is checked as it grows.
class NfaBuilder {
 public:
  Nfa build(const PathNode& root) {
    const Fragment f = fragment(root);
    nfa_.start = f.in;
    nfa_.accept = f.out;
    return std::move(nfa_);
  }

 private:
  struct Fragment {
    int in, out;
  };

  int newState() {
    if (static_cast<int>(nfa_.out.size()) >= kMaxNfaStates) throw TooLarge{};
    nfa_.out.emplace_back();
    return static_cast<int>(nfa_.out.size()) - 1;
  }
  void link(int from, int symbol, int to) { nfa_.out[from].push_back({symbol, to}); }

  Fragment fragment(const PathNode& node) {
    switch (node.kind) {
      case PathNode::Kind::kEvent: {
        const Fragment f{newState(), newState()};
        link(f.in, static_cast<int>(node.event), f.out);
        return f;
      }
      case PathNode::Kind::kConcatenation: {
        Fragment whole = fragment(node.children.front());
        for (std::size_t i = 1; i < node.children.size(); ++i) {
          const Fragment next = fragment(node.children[i]);
          link(whole.out, kEpsilon, next.in);
          whole.out = next.out;
        }
        return whole;
      }
      case PathNode::Kind::kAlternation: {
        const Fragment f{newState(), newState()};
        for (const PathNode& child : node.children) {
          const Fragment choice = fragment(child);
          link(f.in, kEpsilon, choice.in);
          link(choice.out, kEpsilon, f.out);
        }
        return f;
      }
      case PathNode::Kind::kRepetition:
        return repetition(node.children.front(), node.min_count, node.max_count);
    }
    return {};
  }

  // `min` copies of `child`, then a loop over it (no upper bound) or max − min optional copies.
  Fragment repetition(const PathNode& child, int min, int max) {
    const int first = newState();
    int last = first;
    for (int i = 0; i < min; ++i) {
      const Fragment copy = fragment(child);
      link(last, kEpsilon, copy.in);
      last = copy.out;
    }
    if (max == kUnboundedCount) {
      const Fragment body = fragment(child);
      link(last, kEpsilon, body.in);
      link(body.out, kEpsilon, last);
      return {first, last};
    }
    for (int i = min; i < max; ++i) {
      const Fragment copy = fragment(child);
      const int after = newState();
      link(last, kEpsilon, copy.in);
      link(copy.out, kEpsilon, after);
      link(last, kEpsilon, after);
      last = after;
    }
    return {first, last};
  }

  Nfa nfa_;
};

Nfa reversed(const Nfa& nfa) {
  Nfa r;
  r.out.resize(nfa.out.size());
  for (std::size_t from = 0; from < nfa.out.size(); ++from)
    for (const Nfa::Edge& e : nfa.out[from])
      r.out[e.to].push_back({e.symbol, static_cast<int>(from)});
  r.start = nfa.accept;
  r.accept = nfa.start;
  return r;
}

// The subset construction over the vertices D, S, P, between a first and a last event. A DFA
// state is the set of NFA states it may be in, kept to those that matter for what follows (a
// state with a symbol edge, or the accepting one), sorted.
class SubsetConstruction {
 public:
  explicit SubsetConstruction(const Nfa& nfa) : nfa_(nfa), mark_(nfa.out.size(), 0) {}

  PathAutomaton run(PathEvent first, PathEvent last) {
    PathAutomaton a;
    const std::vector<int> after_first =
        closure(moved(closure({nfa_.start}), static_cast<int>(first)));
    if (after_first.empty()) return a;
    std::map<std::vector<int>, int> ids;
    std::vector<const std::vector<int>*> sets;
    auto idOf = [&](std::vector<int> set) {
      if (set.empty()) return PathAutomaton::kDead;
      const auto [it, inserted] = ids.emplace(std::move(set), static_cast<int>(sets.size()));
      if (inserted) {
        if (static_cast<int>(sets.size()) >= kMaxDfaStates) throw TooLarge{};
        sets.push_back(&it->first);
      }
      return it->second;
    };
    a.start = idOf(after_first);
    for (std::size_t i = 0; i < sets.size(); ++i) {
      std::array<int, 3> next{};
      for (int v = 0; v < 3; ++v) next[v] = idOf(closure(moved(*sets[i], v + 1)));
      const std::vector<int> ending = closure(moved(*sets[i], static_cast<int>(last)));
      a.next.push_back(next);
      a.accepts_last.push_back(std::binary_search(ending.begin(), ending.end(), nfa_.accept));
    }
    return withoutDeadStates(a);
  }

 private:
  std::vector<int> moved(const std::vector<int>& set, int symbol) const {
    std::vector<int> to;
    for (int s : set)
      for (const Nfa::Edge& e : nfa_.out[s])
        if (e.symbol == symbol) to.push_back(e.to);
    return to;
  }

  bool matters(int s) const {
    if (s == nfa_.accept) return true;
    for (const Nfa::Edge& e : nfa_.out[s])
      if (e.symbol != kEpsilon) return true;
    return false;
  }

  std::vector<int> closure(const std::vector<int>& seeds) {
    ++generation_;
    std::vector<int> kept, stack;
    for (int s : seeds)
      if (mark_[s] != generation_) {
        mark_[s] = generation_;
        stack.push_back(s);
      }
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      if (matters(s)) kept.push_back(s);
      for (const Nfa::Edge& e : nfa_.out[s])
        if (e.symbol == kEpsilon && mark_[e.to] != generation_) {
          mark_[e.to] = generation_;
          stack.push_back(e.to);
        }
    }
    work_ += static_cast<long long>(kept.size());
    if (work_ > kMaxSubsetWork) throw TooLarge{};
    std::sort(kept.begin(), kept.end());
    return kept;
  }

  // Keeps the states from which an accepting one is reachable, renumbered in order; a step into
  // any other state becomes kDead, so that a tracer can stop there.
  static PathAutomaton withoutDeadStates(const PathAutomaton& a) {
    const std::size_t n = a.next.size();
    std::vector<std::vector<int>> into(n);
    for (std::size_t s = 0; s < n; ++s)
      for (int t : a.next[s])
        if (t != PathAutomaton::kDead) into[t].push_back(static_cast<int>(s));
    std::vector<char> live(n, 0);
    std::vector<int> stack;
    for (std::size_t s = 0; s < n; ++s)
      if (a.accepts_last[s]) {
        live[s] = 1;
        stack.push_back(static_cast<int>(s));
      }
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      for (int from : into[s])
        if (!live[from]) {
          live[from] = 1;
          stack.push_back(from);
        }
    }
    std::vector<int> renumbered(n, PathAutomaton::kDead);
    PathAutomaton kept;
    for (std::size_t s = 0; s < n; ++s)
      if (live[s]) {
        renumbered[s] = static_cast<int>(kept.next.size());
        kept.next.emplace_back();
      }
    for (std::size_t s = 0; s < n; ++s) {
      if (!live[s]) continue;
      for (int v = 0; v < 3; ++v)
        kept.next[renumbered[s]][v] =
            a.next[s][v] == PathAutomaton::kDead ? PathAutomaton::kDead : renumbered[a.next[s][v]];
      kept.accepts_last.push_back(a.accepts_last[s]);
    }
    kept.start = renumbered[a.start];
    return kept;
  }

  const Nfa& nfa_;
  std::vector<int> mark_;
  int generation_ = 0;
  long long work_ = 0;
};

}  // namespace

std::optional<PathAutomata> compilePathAutomata(const PathNode& root) {
  try {
    const Nfa forward = NfaBuilder().build(root);
    const Nfa backward = reversed(forward);
    PathAutomata automata;
    automata.from_light = SubsetConstruction(forward).run(PathEvent::kLight, PathEvent::kEye);
    automata.from_eye = SubsetConstruction(backward).run(PathEvent::kEye, PathEvent::kLight);
    return automata;
  } catch (const TooLarge&) {
    return std::nullopt;
  }
}

}  // namespace gib::scene
