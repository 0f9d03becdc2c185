// Path classes (book Ch. 12): which light paths a renderer accounts for. Shared by the reference
// (which can render exactly one class) and the techniques (which declare the class they model), so
// that a report can separate a technique's error within its class from what it leaves out.
#pragma once

#include <limits>
#include <string>

namespace gib::scene {

// Bounces are the scattering vertices between the light and the eye, on surfaces or in the
// medium: an emitter seen directly has 0 bounces, direct lighting (L D E) and single scattering
// have 1. Only paths with min ≤ bounces ≤ max contribute.
struct PathClass {
  static constexpr int kUnlimited = std::numeric_limits<int>::max();
  int min_bounces = 0;
  int max_bounces = kUnlimited;

  bool contains(int bounces) const { return bounces >= min_bounces && bounces <= max_bounces; }
  bool operator==(const PathClass&) const = default;
};

// Heckbert's notation of the class: "L(D|S){0,1}E" style, e.g. "LE + LDE" for bounces 0..1,
// "L(D|S)*E" for all paths.
std::string describePathClass(const PathClass& path_class);

}  // namespace gib::scene
