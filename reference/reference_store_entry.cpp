#include "reference/reference_store_entry.h"

#include "common/input_error.h"
#include "gib/reference_renderer_version.h"

#include <fmt/format.h>

#include <fstream>

namespace gib::ref {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

// Bounce limits as the EXR metadata writes them: "unlimited" rather than INT_MAX.
ordered_json bounceLimit(int bounces) {
  return bounces == scene::PathClass::kUnlimited ? ordered_json("unlimited")
                                                 : ordered_json(bounces);
}

int readBounceLimit(const ordered_json& value) {
  if (value.is_string() && value.get<std::string>() == "unlimited")
    return scene::PathClass::kUnlimited;
  return value.get<int>();
}

StoreEntry entryFromJson(const ordered_json& j) {
  const std::string format = j.at("format").get<std::string>();
  if (format != kStoreEntryFormat && format != kStoreEntryFormatWithoutHash)
    throw std::runtime_error(
        fmt::format("format '{}' is not {}", j.at("format").dump(), kStoreEntryFormat));
  StoreEntry e;
  if (format == kStoreEntryFormat) e.exr_hash = j.at("reference_exr_hash").get<std::string>();
  e.key = j.at("key").get<std::string>();
  const ordered_json& spec = j.at("spec");
  e.spec.scene = spec.at("scene").get<std::string>();
  e.spec.scene_parameters = spec.at("scene_parameters").get<std::vector<std::string>>();
  e.spec.width = spec.at("width").get<int>();
  e.spec.height = spec.at("height").get<int>();
  e.spec.spp = spec.at("spp").get<std::uint32_t>();
  e.spec.seed = spec.at("seed").get<std::uint64_t>();
  e.spec.path_class.min_bounces = readBounceLimit(spec.at("min_bounces"));
  e.spec.path_class.max_bounces = readBounceLimit(spec.at("max_bounces"));
  // Recorded for an expression class only; an entry without it is a class of bounces.
  e.spec.path_class.expression = spec.value("paths", std::string());
  // Recorded since pixel-centre references exist; an entry without it is box-filtered.
  e.spec.pixel_sampling = parsePixelSampling(spec.value("pixel_sampling", std::string("area")));
  // Recorded without the environment's occlusion only; an entry without it has it.
  e.spec.environment_occlusion = spec.value("environment_occlusion", true);
  // Recorded when a lens was given over the scene's camera; an entry without one took the scene's.
  if (const auto it = spec.find("lens"); it != spec.end()) {
    if (it->contains("radius")) e.spec.lens.radius = it->at("radius").get<double>();
    if (it->contains("focus_distance"))
      e.spec.lens.focus_distance = it->at("focus_distance").get<double>();
  }
  // Recorded for an obscurance reference only; an entry without it is of radiance.
  if (const auto it = spec.find("obscurance"); it != spec.end()) {
    scene::ObscuranceDefinition obscurance;
    obscurance.falloff = scene::parseObscuranceFalloff(it->at("falloff").get<std::string>());
    obscurance.mode = scene::parseObscuranceMode(it->at("mode").get<std::string>());
    obscurance.d_max_fraction = it->at("d_max_fraction").get<float>();
    scene::validateObscuranceDistanceFraction(obscurance.d_max_fraction);
    e.spec.obscurance = obscurance;
  }
  e.scene_name = j.at("scene_name").get<std::string>();
  e.scene_hash = j.at("scene_hash").get<std::string>();
  e.renderer_version = j.at("renderer_version").get<std::string>();
  e.gibench_version = j.at("gibench_version").get<std::string>();
  e.created = j.at("created").get<std::string>();
  e.render_seconds = j.at("render_seconds").get<double>();
  return e;
}

}  // namespace

ordered_json entryToJson(const StoreEntry& e) {
  ordered_json j = {{"format", kStoreEntryFormat},
                    {"key", e.key},
                    {"spec",
                     {{"scene", e.spec.scene},
                      {"scene_parameters", e.spec.scene_parameters},
                      {"width", e.spec.width},
                      {"height", e.spec.height},
                      {"spp", e.spec.spp},
                      {"seed", e.spec.seed},
                      {"min_bounces", bounceLimit(e.spec.path_class.min_bounces)},
                      {"max_bounces", bounceLimit(e.spec.path_class.max_bounces)},
                      {"pixel_sampling", pixelSamplingName(e.spec.pixel_sampling)}}},
                    {"scene_name", e.scene_name},
                    {"scene_hash", e.scene_hash},
                    {"renderer_version", e.renderer_version},
                    {"gibench_version", e.gibench_version},
                    {"created", e.created},
                    {"render_seconds", e.render_seconds},
                    {"reference_exr_hash", e.exr_hash}};
  if (!e.spec.path_class.expression.empty()) j["spec"]["paths"] = e.spec.path_class.expression;
  if (!e.spec.environment_occlusion) j["spec"]["environment_occlusion"] = false;
  if (e.spec.lens.radius) j["spec"]["lens"]["radius"] = *e.spec.lens.radius;
  if (e.spec.lens.focus_distance) j["spec"]["lens"]["focus_distance"] = *e.spec.lens.focus_distance;
  if (e.spec.obscurance)
    j["spec"]["obscurance"] = {
        {"falloff", std::string(scene::obscuranceFalloffName(e.spec.obscurance->falloff))},
        {"mode", std::string(scene::obscuranceModeName(e.spec.obscurance->mode))},
        {"d_max_fraction", e.spec.obscurance->d_max_fraction}};
  return j;
}

StoreEntry readStoreEntry(const fs::path& dir) {
  const fs::path file = dir / "entry.json";
  StoreEntry entry;
  try {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot open it");
    entry = entryFromJson(ordered_json::parse(in));
  } catch (const std::exception& e) {
    throw InputError(fmt::format(
        "'{}' is not a readable store entry ({}); `gibench store gc` removes damaged entries",
        file.string(), e.what()));
  }
  if (entry.key != dir.filename().string())
    throw InputError(fmt::format(
        "'{}' describes key {} but lies in directory {}; `gibench store gc` removes damaged "
        "entries",
        file.string(), entry.key, dir.filename().string()));
  entry.dir = dir;
  entry.size_bytes = directoryBytes(dir);
  entry.current = entry.renderer_version == kReferenceRendererVersion && !entry.exr_hash.empty();
  return entry;
}

std::uint64_t directoryBytes(const fs::path& dir) {
  std::uint64_t bytes = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code size_ec;
    const std::uintmax_t size = it->is_regular_file(size_ec) ? it->file_size(size_ec) : 0;
    if (!size_ec) bytes += size;
  }
  return bytes;
}

RenderSettings renderSettingsOf(const ReferenceSpec& spec, bool progress) {
  RenderSettings settings;
  settings.width = spec.width;
  settings.height = spec.height;
  settings.spp = spec.spp;
  settings.seed = spec.seed;
  settings.path_class = spec.path_class;
  settings.pixel_sampling = spec.pixel_sampling;
  settings.obscurance = spec.obscurance;
  settings.environment_occlusion = spec.environment_occlusion;
  settings.progress = progress;
  return settings;
}

}  // namespace gib::ref
