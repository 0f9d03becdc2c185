// The environment parameters of a scene lit by the built-in Preetham sky (scene/preetham_sky.h) or
// a latitude-longitude EXR: their declarations and the map they build, shared by `outdoor` and
// `chamber --scene-set sky=true` so that both take the same names, ranges and units.
#pragma once

#include "common/parameters.h"
#include "scene/environment_map.h"

#include <string>
#include <string_view>

namespace gib::scene {

// The sky's texels are in kcd/m² (scene/preetham_sky.h); scenes take them in units of 20 kcd/m²,
// so that sunlit ground of albedo 0.5 (about 40 kcd/m² under a sun 30° high) has a radiance of
// about 2 and the sky's zenith about 0.25: within the range the report's images show at exposure
// 0. `environment_intensity` scales further (and alone scales a map read from a file).
inline constexpr float kSkyScale = 1.0f / 20.0f;

// What differs between scenes: the sun's default position, and a sentence placing the azimuth
// in the scene (where the camera looks).
struct SkyDefaults {
  std::string sun_elevation_deg;  // default, as a parameter value
  std::string sun_azimuth_deg;
  std::string azimuth_note;  // appended to the sun_azimuth description
};

// environment, sun_elevation, sun_azimuth, turbidity, sky_resolution, environment_rotation,
// environment_intensity, sun, in that order.
ParameterTable skyParameters(const SkyDefaults& defaults);

// The map those parameters describe: the Preetham sky scaled by kSkyScale, or the EXR (an
// unreadable file is an InputError naming `scene_name`'s parameter), then rotated and scaled.
EnvironmentMap makeSkyEnvironment(const ParameterValues& parameters, std::string_view scene_name);

}  // namespace gib::scene
