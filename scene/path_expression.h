// Path-type classes as regular expressions in Heckbert's notation, read from the light to the
// eye as the book's §12.2 writes them: `L(D|S|P)*E` is every path, `LS+DE` caustics seen on a
// diffuse surface, `LDSE` a diffuse surface seen in a mirror. Compiled to two small deterministic
// automata: one read from the eye (what a path tracer extends), one from the light (what a light
// tracer extends). The notation, syntax and limits are in docs/rendering.md, "Path classes".
#pragma once

#include "scene/path_automaton.h"
#include "scene/path_class.h"
#include "scene/path_event.h"
#include "scene/path_expression_syntax.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gib::scene {

// Syntax: the letters L D S P E, concatenation, `|`, grouping `( )`, postfix `*`, `+`, `?` and
// counts `{n}`, `{n,}`, `{n,m}` (n, m ≤ kMaxPathCount), and the book's own forms: `[X]`, X
// optional, and `{X}`, X once or more, where X does not start with a digit. Whitespace is ignored.
// Only light paths count: a path matches when it is L, then D, S or P vertices, then E, and the
// expression matches it.
class PathExpression {
 public:
  static constexpr int kDead = PathAutomaton::kDead;

  // Throws InputError "path expression 'TEXT': column N: <problem>; <fix>" for a syntax error,
  // and "... matches no light path (every path is L, then D, S or P vertices, then E); ..." when
  // no string of the form L(D|S|P)*E matches. An expression whose automaton would exceed the
  // bounds of scene/path_automaton.h is refused too; one that reads as a bounce range
  // (bounceRangeOf: `L(D|S|P){0,1000000}E`) runs on a counter and has no such bound.
  static PathExpression parse(std::string_view text);
  // L(D|S|P){min,max}E (max = PathClass::kUnlimited: no upper limit), on a counter: constant
  // time and memory for any bounds. Throws InputError unless 0 ≤ min ≤ max.
  static PathExpression ofBounces(int min_bounces, int max_bounces);

  const std::string& text() const { return text_; }  // as given (whitespace removed)

  // Automaton read from the eye towards the light (what a path tracer builds): eyeStart() is the
  // state after reading E; eyeStep() reads one scattering vertex (D, S or P); eyeAcceptsLight()
  // says whether reading L now would accept. kDead in → kDead out; a state from which no
  // acceptance is reachable is kDead (so a tracer can stop).
  int eyeStart() const { return bounces_ ? 0 : eye_.start; }
  int eyeStep(int state, PathEvent vertex) const {
    return bounces_ ? countStep(state) : eye_.step(state, vertex);
  }
  bool eyeAcceptsLight(int state) const {
    return bounces_ ? countAccepts(state) : eye_.acceptsLast(state);
  }
  // The same read from the light towards the eye (what a light tracer builds).
  int lightStart() const { return bounces_ ? 0 : light_.start; }
  int lightStep(int state, PathEvent vertex) const {
    return bounces_ ? countStep(state) : light_.step(state, vertex);
  }
  bool lightAcceptsEye(int state) const {
    return bounces_ ? countAccepts(state) : light_.acceptsLast(state);
  }

  // Whether the whole path (events from light to eye, L first, E last) matches.
  bool matches(std::span<const PathEvent> path) const;

 private:
  PathExpression() = default;

  // A bounce range counts vertices; the count saturates at min when there is no upper limit.
  int countStep(int state) const {
    if (state == kDead || state >= bounces_->max) return kDead;
    return bounces_->max == kUnboundedCount && state >= bounces_->min ? state : state + 1;
  }
  bool countAccepts(int state) const { return state != kDead && state >= bounces_->min; }

  std::string text_;
  std::optional<BounceRange> bounces_;  // set: the counter runs, the tables are empty
  PathAutomaton light_, eye_;
};

// The text of L(D|S|P){min,max}E in its shortest form: "LE", "L(D|S|P)E", "L(D|S|P){2}E",
// "L(D|S|P){0,1}E", "L(D|S|P)+E", "L(D|S|P){3,}E", "L(D|S|P)*E".
std::string bounceExpressionText(int min_bounces, int max_bounces);

// The expression of a class: its own, else the bounce range's. Throws InputError when it gives
// both an expression and bounces other than the defaults.
PathExpression compilePathClass(const PathClass& path_class);

}  // namespace gib::scene
