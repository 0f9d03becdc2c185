#include "reference/reference_output.h"

#include "common/input_error.h"
#include "image/display.h"
#include "image/output_files.h"
#include "reference/embree_scene.h"
#include "scene/output_metadata.h"

#include <sys/resource.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

namespace gib::ref {

namespace fs = std::filesystem;

image::Metadata referenceMetadata(const scene::Scene& scene, const RenderSettings& s) {
  const bool unlimited = s.path_class.max_bounces == PathClass::kUnlimited;
  nlohmann::ordered_json parameters = {
      {"spp", s.spp},
      {"seed", s.seed},
      {"sampler", samplerName(s.sampler)},
      {"replicas", replicasOf(s)},
      {"pixel_sampling", pixelSamplingName(s.pixel_sampling)},
      {"min_bounces", s.path_class.min_bounces},
      {"max_bounces", unlimited ? nlohmann::ordered_json("unlimited")
                                : nlohmann::ordered_json(s.path_class.max_bounces)}};
  if (s.obscurance) parameters["obscurance"] = scene::describeObscurance(*s.obscurance);
  // Only without it, so that the metadata of every other reference stays as it was.
  if (!s.environment_occlusion) parameters["environment_occlusion"] = "off";
  image::Metadata m =
      scene::outputMetadata(scene, "reference", parameters.dump(), s.width, s.height, s.path_class);
  m["gibench/spp"] = std::to_string(s.spp);
  m["gibench/seed"] = std::to_string(s.seed);
  m["gibench/sampler"] = samplerName(s.sampler);
  m["gibench/replicas"] = std::to_string(replicasOf(s));
  m["gibench/pixel_sampling"] = pixelSamplingName(s.pixel_sampling);
  // Whether light paths joined the camera paths (docs/rendering.md, "Caustics: light tracing").
  m["gibench/light_paths"] = tracesLightPaths(scene, s) ? "traced" : "none";
  if (!s.environment_occlusion)
    m["gibench/environment_occlusion"] =
        "off: the environment lights diffuse and glossy surfaces unblocked";
  m["gibench/embree_version"] = embreeVersion();
  constexpr const char* kVarianceLayer =
      "variance: variance of the per-pixel mean, from the spread of the replicas' means "
      "(Student's t with replicas - 1 degrees of freedom)";
  if (s.obscurance) {
    // What the image is of, instead of radiance (docs/rendering.md, "Obscurances").
    m["gibench/obscurance"] = scene::describeObscurance(*s.obscurance);
    m["gibench/layers"] = fmt::format(
        "RGB: mean obscurance W at the camera ray's first hit (0 where it hits nothing); {}; "
        "direct: the same as RGB; indirect: zero",
        kVarianceLayer);
  } else {
    m["gibench/layers"] = fmt::format(
        "RGB: mean radiance (linear Rec.709); {}; direct: paths with at most 1 bounce; indirect: "
        "paths with 2 bounces or more",
        kVarianceLayer);
  }
  return m;
}

std::uint32_t varianceDegreesOfFreedom(const image::Metadata& metadata) {
  const auto it = metadata.find("gibench/replicas");
  if (it == metadata.end()) return 0;
  try {
    const unsigned long replicas = std::stoul(it->second);
    return replicas > 1 ? std::uint32_t(replicas - 1) : 0;
  } catch (const std::exception&) {
    return 0;
  }
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
  image::checkOutputFile(exr_path);
}

}  // namespace gib::ref
