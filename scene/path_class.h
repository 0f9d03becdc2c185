// Path classes (book Ch. 12): which light paths a renderer accounts for. Shared by the reference
// (which can render exactly one class) and the techniques (which declare the class they model), so
// that a report can separate a technique's error within its class from what it leaves out.
#pragma once

#include <limits>
#include <string>
#include <utility>

namespace gib::scene {

// A class is a range of bounces or a path expression (scene/path_expression.h, which compiles
// either: compilePathClass). Bounces are the scattering vertices between the light and the eye,
// on surfaces or in the medium: an emitter seen directly has 0 bounces, direct lighting (L D E)
// and single scattering have 1. The range min..max is the expression L(D|S|P){min,max}E.
struct PathClass {
  static constexpr int kUnlimited = std::numeric_limits<int>::max();
  PathClass() = default;
  // The bounce range: what techniques declare (`return {0, 1};`).
  PathClass(int min, int max) : min_bounces(min), max_bounces(max) {}
  // An expression class; `text` as PathExpression::text() gives it.
  static PathClass ofExpression(std::string text) {
    PathClass c;
    c.expression = std::move(text);
    return c;
  }

  int min_bounces = 0;
  int max_bounces = kUnlimited;
  // Heckbert's notation (`LS+DE`), whitespace removed; empty: the class is the bounce range.
  // With an expression, the bounces keep their defaults.
  std::string expression;

  // For a class of bounces: whether a path with this many belongs to it.
  bool contains(int bounces) const { return bounces >= min_bounces && bounces <= max_bounces; }
  bool operator==(const PathClass&) const = default;
};

// The class in Heckbert's notation, an expression PathExpression::parse reads back to the same
// class: the expression as given, or the bounce range's (bounceExpressionText: "L(D|S|P){0,1}E"
// for bounces 0..1, "L(D|S|P)*E" for all paths).
std::string describePathClass(const PathClass& path_class);

}  // namespace gib::scene
