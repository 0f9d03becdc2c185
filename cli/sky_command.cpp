// gibench sky --out FILE.exr [--sun-elevation DEG] [--sun-azimuth DEG] [--turbidity T]
//             [--height N]
// Writes Preetham, Shirley & Smits' analytic clear sky (scene/preetham_sky.h) as a
// latitude–longitude EXR that a scene's environment map can read.
#include "cli/commands.h"
#include "common/input_error.h"
#include "gib/version.h"
#include "image/exr_io.h"
#include "scene/preetham_sky.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

namespace gib::cli {

namespace {

struct SkyOptions {
  std::string out;
  scene::SkyParameters sky;
};

image::Metadata skyMetadata(const scene::EnvironmentMap& map, const scene::SkyParameters& p) {
  nlohmann::ordered_json parameters = {{"sun_elevation_deg", p.sun_elevation_deg},
                                       {"sun_azimuth_deg", p.sun_azimuth_deg},
                                       {"turbidity", p.turbidity},
                                       {"height", p.height}};
  return {{"gibench/program", kProgramName},
          {"gibench/version", kVersion},
          {"gibench/environment", "preetham_sky"},
          {"gibench/parameters", parameters.dump()},
          {"gibench/source", map.source},
          {"gibench/units", fmt::format("1 = {} cd/m² of luminance", scene::kSkyCandelasPerUnit)},
          {"gibench/width", std::to_string(map.width)},
          {"gibench/height", std::to_string(map.height)}};
}

int runSky(const SkyOptions& o) {
  if (std::filesystem::path(o.out).extension() != ".exr")
    throw InputError(
        fmt::format("--out '{}' is not an .exr file; give a path ending in .exr", o.out));
  // Validates before anything is written: bad input leaves no file.
  const scene::EnvironmentMap map = scene::makePreethamSky(o.sky);
  image::Image rgb(map.width, map.height, 3);
  std::copy(map.texels->begin(), map.texels->end(), rgb.data().begin());
  image::writeExr(o.out, {{"", rgb}}, skyMetadata(map, o.sky));
  fmt::print("wrote {} ({}×{}, {})\n", o.out, map.width, map.height, map.source);
  return 0;
}

}  // namespace

CommandRunner addSkyCommand(CLI::App& app) {
  auto o = std::make_shared<SkyOptions>();
  CLI::App* command = app.add_subcommand(
      "sky",
      "Write an analytic clear sky (Preetham, Shirley & Smits 1999) as a latitude-longitude "
      "EXR environment map");
  command->add_option("--out", o->out, "the EXR file to write")->required();
  command
      ->add_option("--sun-elevation", o->sky.sun_elevation_deg,
                   "sun above the horizon, degrees [0, 90]")
      ->capture_default_str();
  command
      ->add_option("--sun-azimuth", o->sky.sun_azimuth_deg,
                   "sun azimuth, degrees from +x towards +z")
      ->capture_default_str();
  command->add_option("--turbidity", o->sky.turbidity, "atmospheric turbidity [2, 10]")
      ->capture_default_str();
  command->add_option("--height", o->sky.height, "map rows, even [4, 4096]; width = 2 × height")
      ->capture_default_str();
  return [o] { return runSky(*o); };
}

}  // namespace gib::cli
