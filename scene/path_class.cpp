#include "scene/path_class.h"

#include <fmt/format.h>

namespace gib::scene {

namespace {
std::string pathOfBounces(int bounces) {
  if (bounces == 0) return "LE";
  if (bounces == 1) return "LDE";
  return fmt::format("L(D|S){{{}}}E", bounces);
}
}  // namespace

std::string describePathClass(const PathClass& c) {
  if (c.max_bounces == PathClass::kUnlimited)
    return c.min_bounces == 0 ? "L(D|S)*E" : fmt::format("L(D|S){{{},}}E", c.min_bounces);
  if (c.max_bounces - c.min_bounces <= 2) {
    std::string out;
    for (int b = c.min_bounces; b <= c.max_bounces; ++b)
      out += (out.empty() ? "" : " + ") + pathOfBounces(b);
    return out;
  }
  return fmt::format("L(D|S){{{},{}}}E", c.min_bounces, c.max_bounces);
}

}  // namespace gib::scene
