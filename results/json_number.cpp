#include "results/json_number.h"

#include <cmath>

namespace gib::results {

nlohmann::ordered_json numberToJson(double value) {
  if (std::isfinite(value)) return value;
  if (std::isnan(value)) return "nan";
  return value > 0 ? "inf" : "-inf";
}

}  // namespace gib::results
