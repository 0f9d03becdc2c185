#include "realtime/irradiance_cache/irradiance_cache_parameters.h"

#include "common/input_error.h"

#include <fmt/format.h>

namespace gib::rt {

ParameterTable irradianceCacheParameters() {
  return {
      numericParameter("accuracy", ParameterType::kNumber, "0.2", 0.01, 2, "",
                       "Ward's a: a record contributes where its weight exceeds 1/a; smaller "
                       "means more records and less interpolation error"),
      choiceParameter("traversal", "rounds", {"rounds", "scanline"},
                      "record placement: coarse-to-fine rounds of records computed together, or "
                      "the notes' scan-order traversal, one record at a time"),
      numericParameter("coarsest_spacing", ParameterType::kInteger, "32", 1, 1024, "pixels",
                       "the record traversal's first grid; it halves each round down to 1"),
      numericParameter("min_zone_pixels", ParameterType::kNumber, "2", 0.5, 64, "pixels",
                       "smallest zone of influence a·R, in pixel footprints at the record"),
      numericParameter("max_zone_pixels", ParameterType::kNumber, "64", 1, 4096, "pixels",
                       "largest zone of influence a·R, in pixel footprints at the record"),
      booleanParameter("reuse_records", true,
                       "keep the records across frames (a static scene and camera), or rebuild "
                       "them every frame"),
  };
}

std::vector<DeclaredOutput> irradianceCacheStatistics(std::vector<DeclaredOutput> own) {
  std::vector<DeclaredOutput> statistics = {
      {"records", "records in the cache"},
      {"record_rounds", "rounds of the record traversal"},
      {"records_ms", "time to compute the records"},
      {"records_per_second", "records computed per second"},
  };
  statistics.insert(statistics.end(), own.begin(), own.end());
  return statistics;
}

RecordPlacementSettings recordPlacementSettings(const ParameterValues& p) {
  RecordPlacementSettings settings;
  settings.accuracy = float(p.number("accuracy"));
  settings.coarsest_spacing = p.integer("coarsest_spacing");
  settings.scanline = p.text("traversal") == "scanline";
  settings.min_zone_pixels = float(p.number("min_zone_pixels"));
  settings.max_zone_pixels = float(p.number("max_zone_pixels"));
  if (settings.min_zone_pixels > settings.max_zone_pixels)
    throw InputError(fmt::format(
        "irradiance cache: min_zone_pixels={} exceeds max_zone_pixels={}; give a minimum no "
        "larger than the maximum",
        p.text("min_zone_pixels"), p.text("max_zone_pixels")));
  return settings;
}

}  // namespace gib::rt
