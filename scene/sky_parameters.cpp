#include "scene/sky_parameters.h"

#include "common/input_error.h"
#include "scene/preetham_sky.h"

#include <fmt/format.h>

#include <utility>

namespace gib::scene {

ParameterTable skyParameters(const SkyDefaults& defaults) {
  return {
      textParameter("environment", "sky",
                    "the light: 'sky' (the Preetham clear sky with its sun, below) or the path "
                    "of a latitude-longitude EXR twice as wide as high"),
      numericParameter("sun_elevation", ParameterType::kNumber, defaults.sun_elevation_deg, 0, 90,
                       "degrees", "the sky's sun above the horizon"),
      numericParameter("sun_azimuth", ParameterType::kNumber, defaults.sun_azimuth_deg, 0, 360,
                       "degrees", "the sky's sun from +x towards +z " + defaults.azimuth_note),
      numericParameter("turbidity", ParameterType::kNumber, "3", 2, 10, "",
                       "the sky's haze, 2 (clear) to 10 (hazy), Preetham's fitted range"),
      integerChoiceParameter("sky_resolution", 128, {32, 64, 128, 256, 512, 1024}, "texels",
                             "the sky map's height (its width is twice that)"),
      numericParameter("environment_rotation", ParameterType::kNumber, "0", -360, 360, "degrees",
                       "turns the map about +y, from +x towards -z"),
      numericParameter("environment_intensity", ParameterType::kNumber, "1", 0, 1e6, "",
                       "scales the map's radiance (the sky's texels are taken in units of "
                       "20 kcd/m²)"),
      choiceParameter("sun", "disc", {"disc", "none"},
                      "the sky's sun: its disc's power in the texel that holds it, or none (the "
                      "disc left out, the map's ground still lit by it: a smooth environment, as "
                      "spherical harmonics and equal-power cells want)"),
  };
}

EnvironmentMap makeSkyEnvironment(const ParameterValues& parameters, std::string_view scene_name) {
  EnvironmentMap map;
  const std::string& source = parameters.text("environment");
  if (source == "sky") {
    SkyParameters sky;
    sky.sun_elevation_deg = float(parameters.number("sun_elevation"));
    sky.sun_azimuth_deg = float(parameters.number("sun_azimuth"));
    sky.turbidity = float(parameters.number("turbidity"));
    sky.height = parameters.integer("sky_resolution");
    map = makePreethamSky(
        sky, parameters.text("sun") == "disc" ? SunDisc::kIncluded : SunDisc::kOmitted);
    map.intensity = kSkyScale;
  } else {
    try {
      map = loadEnvironmentMap(source);
    } catch (const InputError& e) {
      throw InputError(fmt::format("scene '{}' parameter environment: {}", scene_name, e.what()));
    }
  }
  map.rotation_deg = float(parameters.number("environment_rotation"));
  map.intensity *= float(parameters.number("environment_intensity"));
  return map;
}

}  // namespace gib::scene
