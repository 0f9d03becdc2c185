#include "reference/reference_output.h"

#include "common/input_error.h"
#include "gib/version.h"
#include "image/display.h"
#include "reference/embree_scene.h"

#include <sys/resource.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

namespace gib::ref {

namespace fs = std::filesystem;

image::Metadata referenceMetadata(const scene::Scene& scene, const RenderSettings& s) {
  const bool unlimited = s.path_class.max_bounces == PathClass::kUnlimited;
  nlohmann::ordered_json parameters = {
      {"spp", s.spp},
      {"seed", s.seed},
      {"min_bounces", s.path_class.min_bounces},
      {"max_bounces", unlimited ? nlohmann::ordered_json("unlimited")
                                : nlohmann::ordered_json(s.path_class.max_bounces)}};
  image::Metadata m;
  m["gibench/program"] = kProgramName;
  m["gibench/version"] = kVersion;
  m["gibench/technique"] = "reference";
  m["gibench/parameters"] = parameters.dump();
  m["gibench/scene"] = scene.name;
  m["gibench/scene_hash"] = scene::hashScene(scene);
  m["gibench/scene_provenance"] = scene.provenance;
  nlohmann::ordered_json scene_parameters = nlohmann::ordered_json::object();
  for (const auto& [key, value] : scene.parameters) scene_parameters[key] = value;
  m["gibench/scene_parameters"] = scene_parameters.dump();
  m["gibench/width"] = std::to_string(s.width);
  m["gibench/height"] = std::to_string(s.height);
  m["gibench/spp"] = std::to_string(s.spp);
  m["gibench/seed"] = std::to_string(s.seed);
  m["gibench/min_bounces"] = std::to_string(s.path_class.min_bounces);
  m["gibench/max_bounces"] = unlimited ? "unlimited" : std::to_string(s.path_class.max_bounces);
  m["gibench/embree_version"] = embreeVersion();
  m["gibench/layers"] =
      "RGB: mean radiance (linear Rec.709); variance: variance of the per-pixel mean; direct: "
      "paths with at most 1 bounce; indirect: paths with 2 bounces or more";
  return m;
}

void addRunMetadata(image::Metadata& m, const RenderResult& result) {
  m["gibench/render_seconds"] = fmt::format("{:.3f}", result.seconds);
  m["gibench/rays_per_second"] = fmt::format("{:.0f}", result.raysPerSecond());
  m["gibench/peak_rss_mb"] = fmt::format("{:.1f}", peakResidentMegabytes());
}

double peakResidentMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
}

fs::path checkpointPath(const fs::path& exr_path, std::uint32_t spp) {
  return exr_path.parent_path() / fmt::format("{}.spp{:04d}.exr", exr_path.stem().string(), spp);
}

fs::path writeReferenceOutputs(const fs::path& exr_path, const RenderResult& result,
                               const image::Metadata& metadata) {
  std::vector<image::Layer> layers = {{"", result.mean}};
  if (result.variance.pixelCount() > 0) layers.push_back({"variance", result.variance});
  layers.push_back({"direct", result.direct});
  layers.push_back({"indirect", result.indirect});
  image::writeExr(exr_path, layers, metadata);
  fs::path png = fs::path(exr_path).replace_extension(".png");
  image::writePng(png, result.mean);
  return png;
}

void checkOutputPath(const fs::path& exr_path) {
  if (exr_path.extension() != ".exr")
    throw InputError(fmt::format("output '{}' must end in .exr; the PNG is written beside it",
                                 exr_path.string()));
  fs::path dir = exr_path.parent_path().empty() ? fs::path(".") : exr_path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(
        fmt::format("cannot write '{}': directory '{}' does not exist; create it first",
                    exr_path.string(), dir.string()));
  if (access(dir.c_str(), W_OK) != 0)
    throw InputError(
        fmt::format("cannot write '{}': directory '{}' is not writable; choose another "
                    "--out",
                    exr_path.string(), dir.string()));
}

}  // namespace gib::ref
