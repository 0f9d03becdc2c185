// The syntax of path expressions (scene/path_expression.h): the parser from text to a tree, with
// errors that point at a column, and the recognition of a tree that is a bounce range, which
// PathExpression runs with a counter instead of a table. Used by PathExpression's implementation
// (scene/path_expression.cpp, scene/path_automaton.cpp); its header includes this one only for the
// BounceRange it holds.
#pragma once

#include "scene/path_event.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace gib::scene {

// The largest count a user may write in {n}, {n,} or {n,m}: the suites' limit on max_bounces,
// so that every bounce class has a text (describePathClass) the parser reads back.
inline constexpr int kMaxPathCount = 1000000;
// The upper bound of `*`, `+`, `{n,}`.
inline constexpr int kUnboundedCount = std::numeric_limits<int>::max();

struct PathNode {
  enum class Kind : std::uint8_t { kEvent, kConcatenation, kAlternation, kRepetition };
  Kind kind = Kind::kEvent;
  PathEvent event = PathEvent::kLight;  // kEvent
  std::vector<PathNode> children;       // kConcatenation, kAlternation: ≥ 2; kRepetition: 1
  int min_count = 0, max_count = 0;     // kRepetition; max_count may be kUnboundedCount
};

// Parses `text` (whitespace ignored). Throws InputError
// "path expression 'TEXT': column N: <problem>; <fix>", N counted in `text` from 1.
PathNode parsePathSyntax(std::string_view text);

// A count of scattering vertices, whatever their kind: the class L(D|S|P){min,max}E.
struct BounceRange {
  int min = 0;
  int max = 0;  // kUnboundedCount: no upper limit
  bool operator==(const BounceRange&) const = default;
};

// The range when `root` is L, then a part that matches exactly the strings over {D, S, P} of
// min..max letters, then E (`L(D|S|P){2,5}E`, the book's `L[{D|S|P}]E`, `L(S|D|P)(D|S|P)*E`);
// nullopt for anything else, which the general automaton then handles. Sound, not complete: an
// expression that means a bounce range but is written otherwise (`LE|L(D|S|P)E`) gets nullopt.
std::optional<BounceRange> bounceRangeOf(const PathNode& root);

}  // namespace gib::scene
