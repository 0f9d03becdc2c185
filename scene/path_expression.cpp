#include "scene/path_expression.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <cctype>

namespace gib::scene {

static_assert(kUnboundedCount == PathClass::kUnlimited,
              "a bounce class without an upper limit is a count without one");

namespace {

std::string withoutSpace(std::string_view text) {
  std::string kept;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) kept += c;
  return kept;
}

}  // namespace

PathExpression PathExpression::parse(std::string_view text) {
  const PathNode root = parsePathSyntax(text);
  PathExpression e;
  e.text_ = withoutSpace(text);
  // Step: a bounce range runs on a counter, whatever its counts.
  if ((e.bounces_ = bounceRangeOf(root))) return e;
  // Step: anything else compiles to tables, within bounds.
  std::optional<PathAutomata> automata = compilePathAutomata(root);
  if (!automata)
    throw InputError(fmt::format(
        "path expression '{}' is too large to compile (its automaton would exceed {} states); "
        "write smaller counts, or * and + for long paths (a count over (D|S|P) alone between L "
        "and E, as in L(D|S|P){{0,1000}}E, has no such limit)",
        text, kMaxDfaStates));
  // Step: refuse a class no light path belongs to (the empty class renders black, surely not
  // what was meant).
  if (automata->from_light.start == kDead)
    throw InputError(fmt::format(
        "path expression '{}' matches no light path (every path is L, then D, S or P vertices, "
        "then E); write e.g. LDE or L(D|S|P)*E",
        text));
  e.light_ = std::move(automata->from_light);
  e.eye_ = std::move(automata->from_eye);
  return e;
}

PathExpression PathExpression::ofBounces(int min_bounces, int max_bounces) {
  if (min_bounces < 0 || min_bounces > max_bounces)
    throw InputError(
        fmt::format("the bounce range {}..{} holds no path; give 0 <= min bounces <= max bounces",
                    min_bounces, max_bounces));
  PathExpression e;
  e.text_ = bounceExpressionText(min_bounces, max_bounces);
  e.bounces_ = BounceRange{min_bounces, max_bounces};
  return e;
}

bool PathExpression::matches(std::span<const PathEvent> path) const {
  if (path.size() < 2 || path.front() != PathEvent::kLight || path.back() != PathEvent::kEye)
    return false;
  int state = lightStart();
  for (PathEvent vertex : path.subspan(1, path.size() - 2)) {
    if (vertex == PathEvent::kLight || vertex == PathEvent::kEye) return false;
    state = lightStep(state, vertex);
  }
  return lightAcceptsEye(state);
}

std::string bounceExpressionText(int min_bounces, int max_bounces) {
  const char* kVertex = "(D|S|P)";
  if (max_bounces == PathClass::kUnlimited) {
    if (min_bounces <= 1) return fmt::format("L{}{}E", kVertex, min_bounces == 0 ? "*" : "+");
    return fmt::format("L{}{{{},}}E", kVertex, min_bounces);
  }
  if (min_bounces == max_bounces) {
    if (min_bounces == 0) return "LE";
    if (min_bounces == 1) return fmt::format("L{}E", kVertex);
    return fmt::format("L{}{{{}}}E", kVertex, min_bounces);
  }
  return fmt::format("L{}{{{},{}}}E", kVertex, min_bounces, max_bounces);
}

PathExpression compilePathClass(const PathClass& path_class) {
  if (path_class.expression.empty())
    return PathExpression::ofBounces(path_class.min_bounces, path_class.max_bounces);
  if (path_class.min_bounces != 0 || path_class.max_bounces != PathClass::kUnlimited)
    throw InputError(fmt::format(
        "the path class gives both the expression '{}' and bounces {}..{}; give one of them",
        path_class.expression, path_class.min_bounces, path_class.max_bounces));
  return PathExpression::parse(path_class.expression);
}

}  // namespace gib::scene
