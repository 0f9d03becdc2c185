#include "scene/path_class.h"

#include "scene/path_expression.h"

namespace gib::scene {

std::string describePathClass(const PathClass& c) {
  return c.expression.empty() ? bounceExpressionText(c.min_bounces, c.max_bounces) : c.expression;
}

}  // namespace gib::scene
