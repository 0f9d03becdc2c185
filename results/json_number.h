// Numbers in gibench's JSON output (results.json, `diff --json`, `history --json`): JSON has no
// NaN or infinity, so non-finite numbers are the strings "nan", "inf" and "-inf" (what
// `gibench compare --json` prints too), finite ones plain numbers.
#pragma once

#include <nlohmann/json.hpp>

namespace gib::results {

nlohmann::ordered_json numberToJson(double value);

}  // namespace gib::results
