// The deterministic automata of a path expression (scene/path_expression.h), one per reading
// direction, compiled from its syntax tree: a Thompson NFA, reversed for the eye's direction,
// then the subset construction, with the states from which no acceptance is reachable removed.
// Internal to scene/path_expression.cpp.
#pragma once

#include "scene/path_event.h"
#include "scene/path_expression_syntax.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace gib::scene {

// What follows the first event of a light path: D, S and P vertices, then the last event. A
// state is an index; -1 is dead (no acceptance reachable).
struct PathAutomaton {
  static constexpr int kDead = -1;
  int start = kDead;                       // after the first event (L, or E for the eye)
  std::vector<std::array<int, 3>> next;    // per state, after D, S, P
  std::vector<std::uint8_t> accepts_last;  // per state: reading the last event now accepts

  int step(int state, PathEvent vertex) const {
    return state == kDead ? kDead : next[state][static_cast<int>(vertex) - 1];
  }
  bool acceptsLast(int state) const { return state != kDead && accepts_last[state] != 0; }
};

struct PathAutomata {
  PathAutomaton from_light;  // L first, E last
  PathAutomaton from_eye;    // E first, L last
};

// Bounds on what an expression may compile to, so that a user's counts cannot exhaust memory or
// time: NFA states (each copy of a counted part adds its own), DFA states per direction, and the
// NFA states visited by the subset construction in all.
inline constexpr int kMaxNfaStates = 50000;
inline constexpr int kMaxDfaStates = 10000;
inline constexpr long long kMaxSubsetWork = 50000000;

// The automata of `root`, or nullopt when they would exceed the bounds above.
std::optional<PathAutomata> compilePathAutomata(const PathNode& root);

}  // namespace gib::scene
