// Lists in error messages ("choose one of: a, b, c"), joined in one place.
#pragma once

#include <string>
#include <string_view>

namespace gib {

// Joins the projection of each element of `range` with `separator`.
template <typename Range, typename Projection>
std::string joinNames(const Range& range, std::string_view separator, Projection projection) {
  std::string joined;
  for (const auto& element : range) {
    if (!joined.empty()) joined += separator;
    joined += projection(element);
  }
  return joined;
}

// Joins strings with `separator`.
template <typename Range>
std::string joinNames(const Range& range, std::string_view separator) {
  return joinNames(
      range, separator, [](const auto& name) -> const auto& { return name; });
}

}  // namespace gib
