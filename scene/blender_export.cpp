#include "scene/blender_export.h"

#include "common/embedded_file.h"
#include "common/input_error.h"
#include "common/join.h"
#include "scene/camera.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <span>

namespace gib::scene {

// The builder's text, compiled in by scene/CMakeLists.txt (cmake/EmbedFiles.cmake).
std::span<const EmbeddedFile> embeddedBlenderBuilder();

namespace {

constexpr std::uint64_t kCyclesMaxSeed = 2147483647;
// Cycles' largest bounce limit: GI Bench's paths end only by Russian roulette, so every limit is
// set as high as Cycles allows and no path is cut short where GI Bench would continue it.
constexpr int kCyclesMaxBounces = 1024;
// The exponent k of the cos^k fall-off of Blender's spot lamps.
constexpr float kBlenderSpotFalloffExponent = 1.0f;
// Blender's spot lamps open to at most a hemisphere.
constexpr float kBlenderMaxConeHalfAngleDeg = 90.0f;

// The shortest decimal text that reads back as the same float: Python reads it as a double,
// Blender stores it as the same float again, so nothing is rounded on the way. Adding 0 turns −0
// (a cross product's) into 0, the same value, so equal numbers are written alike.
std::string number(float value) {
  return fmt::format("{}", value + 0.0f);
}

std::string vec(const glm::vec3& v) {
  return fmt::format("({}, {}, {})", number(v.x), number(v.y), number(v.z));
}

// A JSON string with non-ASCII escaped is also a Python string literal.
std::string text(const std::string& value) {
  return nlohmann::json(value).dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
}

float largest(const Rgb& c) {
  return std::max({c.r, c.g, c.b});
}

void checkSettings(const BlenderExportSettings& s) {
  if (s.width < 1 || s.height < 1)
    throw InputError(
        fmt::format("image size {}x{} is empty; give --width and --height of at "
                    "least 1",
                    s.width, s.height));
  if (s.spp < 1)
    throw InputError(
        fmt::format("--spp {} renders nothing; give at least 1 sample per pixel", s.spp));
  if (s.seed > kCyclesMaxSeed)
    throw InputError(fmt::format("--seed {} is beyond Cycles' seeds; give one from 0 to {}", s.seed,
                                 kCyclesMaxSeed));
}

// A mirror is Cycles' Sharp Glossy BSDF, whose colour the builder computes per shading point from
// the conductor's n and κ (scene/blender_scene.py, conductor_fresnel); a perfect mirror's is white.
std::string mirrorEntry(const Material& m) {
  if (m.type != MaterialType::kMirror) return "None";
  if (m.perfect_mirror) return "\"perfect\"";
  return fmt::format("{{\"n\": {}, \"k\": {}}}", vec(m.conductor_n), vec(m.conductor_k));
}

std::string glassEntry(const Material& m) {
  if (m.type != MaterialType::kGlass) return "None";
  std::string absorption = "None";
  if (largest(m.absorption) > 0) {
    const CyclesAbsorption a = cyclesAbsorption(m.absorption);
    absorption = fmt::format("{{\"color\": {}, \"density\": {}}}", vec(a.color), number(a.density));
  }
  return fmt::format("{{\"ior\": {}, \"absorption\": {}}}", number(m.ior), absorption);
}

std::string materialEntry(const Material& m) {
  // Mirrors and glass have no diffuse part.
  const bool lambert = m.type == MaterialType::kLambert || m.type == MaterialType::kPhong;
  const std::string diffuse = lambert ? vec(m.diffuse) : "None";
  std::string glossy = "None";
  if (m.type == MaterialType::kPhong && largest(m.specular) > 0)
    glossy = fmt::format("{{\"color\": {}, \"roughness\": {}}}", vec(m.specular),
                         number(float(phongToBeckmannRoughness(m.exponent))));
  const std::string emission = m.isEmissive() ? vec(m.emission) : "None";
  return fmt::format(
      "        {{\"name\": {}, \"diffuse\": {}, \"glossy\": {}, \"mirror\": {}, \"glass\": {}, "
      "\"emission\": {}}},\n",
      text(m.name), diffuse, glossy, mirrorEntry(m), glassEntry(m), emission);
}

// A list of triples (points, normals, triangles) written flat, as Blender's foreach_set takes them.
template <typename T, typename Write>
std::string flatList(const std::vector<T>& values, Write write) {
  std::string out;
  for (const T& v : values)
    fmt::format_to(std::back_inserter(out), "{}{}", out.empty() ? "" : ", ", write(v));
  return "[" + out + "]";
}

std::string meshEntry(const Mesh& mesh) {
  const auto point = [](const glm::vec3& p) {
    return fmt::format("{}, {}, {}", number(p.x), number(p.y), number(p.z));
  };
  const auto triangle = [](const glm::uvec3& t) {
    return fmt::format("{}, {}, {}", t[0], t[1], t[2]);
  };
  return fmt::format(
      "        {{\"name\": {}, \"material\": {},\n         \"positions\": {},\n         "
      "\"normals\": {},\n         \"triangles\": {}}},\n",
      text(mesh.name), mesh.material, flatList(mesh.positions, point),
      mesh.normals.empty() ? "None" : flatList(mesh.normals, point),
      flatList(mesh.triangles, triangle));
}

// Camera rays must reach the farthest vertex; the near plane is as close as Blender allows
// relative to the scene's size, as GI Bench's rays start at the eye.
std::string cameraEntry(const Scene& scene, const BlenderExportSettings& s) {
  const CameraFrame frame = makeCameraFrame(scene.camera, s.width, s.height);
  float farthest = 0;
  for (const Mesh& mesh : scene.meshes)
    for (const glm::vec3& p : mesh.positions)
      farthest = std::max(farthest, glm::length(p - frame.origin));
  const float clip_end = farthest > 0 ? 2 * farthest : 1.0f;
  const float clip_start = std::max(1e-6f, 1e-6f * clip_end);
  // The thin lens only when there is one, so that a pinhole's export stays as it was.
  const std::string lens =
      frame.lens_radius > 0
          ? fmt::format(",\n               \"lens_radius\": {}, \"focus_distance\": {}",
                        number(frame.lens_radius), number(frame.focus_distance))
          : "";
  return fmt::format(
      "    \"camera\": {{\"position\": {}, \"forward\": {}, \"right\": {}, \"up\": {},\n"
      "               \"vertical_fov_deg\": {}, \"clip_start\": {}, \"clip_end\": {}{}}},\n",
      vec(frame.origin), vec(frame.forward), vec(frame.right), vec(frame.up),
      number(scene.camera.vertical_fov_deg), number(clip_start), number(clip_end), lens);
}

std::string spotEntries(const Scene& scene, std::vector<std::string>& warnings) {
  std::string out;
  for (std::size_t i = 0; i < scene.spot_lights.size(); ++i) {
    const SpotLight& l = scene.spot_lights[i];
    const float peak = largest(l.intensity);
    if (peak <= 0) continue;  // a black lamp adds nothing
    // Blender 3.4's spot lamp falls off as cos θ inside its cone (Cycles' spot_attenuation
    // returns the cosine), which is GI Bench's spot light of exponent 1 exactly; blend 0 keeps
    // the cone's edge sharp.
    if (l.falloff_exponent != kBlenderSpotFalloffExponent)
      warnings.push_back(fmt::format(
          "spot light {} falls off as cos^k with k = {}, Blender's spot lamp as cos (k = 1); it is "
          "exported with Blender's fall-off, {} off its axis than in GI Bench",
          i, l.falloff_exponent, l.falloff_exponent > 1 ? "brighter" : "darker"));
    float half_angle = l.cone_angle_deg;
    if (half_angle > kBlenderMaxConeHalfAngleDeg) {
      warnings.push_back(fmt::format(
          "spot light {}'s cone half-angle {}° is wider than Blender's 90° limit; it is "
          "exported as a 90° cone",
          i, half_angle));
      half_angle = kBlenderMaxConeHalfAngleDeg;
    }
    fmt::format_to(std::back_inserter(out),
                   "        {{\"position\": {}, \"direction\": {}, \"color\": {}, \"watts\": {},\n"
                   "         \"spot_size\": {}, \"spot_blend\": 0.0}},\n",
                   vec(l.position), vec(glm::normalize(l.direction)), vec(l.intensity / peak),
                   number(float(blenderLampWatts(peak))),
                   number(float(2 * half_angle * std::numbers::pi / 180)));
  }
  return out;
}

std::string sunEntries(const Scene& scene) {
  std::string out;
  for (const DirectionalLight& l : scene.directional_lights) {
    const float peak = largest(l.irradiance);
    if (peak <= 0) continue;
    fmt::format_to(std::back_inserter(out),
                   "        {{\"direction\": {}, \"color\": {}, \"strength\": {}}},\n",
                   vec(glm::normalize(l.direction)), vec(l.irradiance / peak), number(peak));
  }
  return out;
}

std::vector<std::string> phongWarnings(const Scene& scene) {
  std::vector<std::string> names;
  for (const Material& m : scene.materials)
    if (m.type == MaterialType::kPhong && largest(m.specular) > 0) names.push_back(m.name);
  if (names.empty()) return {};
  return {fmt::format(
      "Phong material{} {} {} no exact Cycles equivalent; the diffuse part is exact, the glossy "
      "lobe is a Beckmann Glossy BSDF of matching roughness",
      names.size() > 1 ? "s" : "", joinNames(names, ", "), names.size() > 1 ? "have" : "has")};
}

// A path tracer finds light only by hitting an emitter or by a shadow ray to it; from a spot or
// sun lamp of zero size, light that a mirror or glass reflected or refracted onto a surface (a
// caustic, L S+ D E) arrives by neither: Cycles cannot render it, GI Bench's light tracing can.
// The environment map: its texels bottom row first (a Blender image's first row is its bottom),
// RGBA, and the rotation that turns a world direction w into the vector Blender's equirectangular
// lookup needs. Blender reads u = ½ − atan2(D.y, D.x)/2π and v = ½ + asin(D.z)/π (z up, v = 0 at
// the bottom; Cycles' direction_to_equirectangular); GI Bench reads u = atan2(m.z, m.x)/2π and
// θ = acos(m.y) from the top (scene/environment_map.h) of the map direction
// m = R_y(−rotation) w. The two agree for D = (−m.x, m.z, m.y), a half turn about z after a
// quarter turn about x. Looked up at the nearest texel ("Closest"), the
// map is the piecewise-constant light the reference integrates.
std::string environmentEntry(const Scene& scene) {
  const EnvironmentMap& map = scene.environment;
  if (map.empty()) return "None";
  const glm::vec3 ex = map.toMap({1, 0, 0}), ey = map.toMap({0, 1, 0}), ez = map.toMap({0, 0, 1});
  // Columns: the images of the world's axes.
  const auto row = [&](auto component) {
    return fmt::format("[{}, {}, {}]", number(component(ex)), number(component(ey)),
                       number(component(ez)));
  };
  std::string texels;
  texels.reserve(std::size_t(map.width) * std::size_t(map.height) * 4 * 12);
  for (int y = map.height - 1; y >= 0; --y)
    for (int x = 0; x < map.width; ++x) {
      const Rgb t = map.texel(x, y);
      texels += fmt::format("{},{},{},1,", number(t.r), number(t.g), number(t.b));
    }
  return fmt::format(
      "{{\"width\": {}, \"height\": {}, \"strength\": {},\n"
      "        \"matrix\": [{}, {}, {}],\n        \"pixels\": [{}]}}",
      map.width, map.height, number(map.intensity), row([](glm::vec3 v) { return -v.x; }),
      row([](glm::vec3 v) { return v.z; }), row([](glm::vec3 v) { return v.y; }), texels);
}

std::vector<std::string> deltaCausticWarnings(const Scene& scene) {
  const auto lit = [](const auto& lights, auto power) {
    return std::any_of(lights.begin(), lights.end(),
                       [&](const auto& l) { return largest(power(l)) > 0; });
  };
  const bool spot = lit(scene.spot_lights, [](const SpotLight& l) { return l.intensity; });
  const bool sun =
      lit(scene.directional_lights, [](const DirectionalLight& l) { return l.irradiance; });
  if (!(spot || sun) || !scene.hasIdealSpecular()) return {};
  return {fmt::format(
      "the {} lamps' caustics (their light reflected or refracted by mirrors or glass onto other "
      "surfaces, L S+ D E) are missing from the Cycles image: a path tracer cannot reach a lamp "
      "of zero size through a specular bounce",
      spot && sun ? "spot and sun"
      : spot      ? "spot"
                  : "sun")};
}

std::string header(const Scene& scene, const BlenderExportSettings& s,
                   const std::vector<std::string>& warnings) {
  std::vector<std::string> parameters;
  for (const auto& [key, value] : scene.parameters) parameters.push_back(key + "=" + value);
  std::string out = fmt::format(
      "# Written by `gibench export-blender`: GI Bench scene '{}' (hash {}{}{}) at {}x{}, {} spp,\n"
      "# seed {}, for Cycles (Blender 3.4). Run it in an empty Blender:\n"
      "#   blender -b --factory-startup --python-exit-code 3 --python THIS.py -- OUT.exr "
      "[--spp N] [--seed S]\n",
      scene.name, hashScene(scene), parameters.empty() ? "" : ", ", joinNames(parameters, ", "),
      s.width, s.height, s.spp, s.seed);
  if (warnings.empty())
    out += "# Every part of the scene maps exactly onto Cycles.\n";
  else
    for (const std::string& warning : warnings) out += "# Not exact: " + warning + ".\n";
  return out;
}

}  // namespace

double blenderLampWatts(double intensity_w_per_sr) {
  return 4 * std::numbers::pi * intensity_w_per_sr;
}

CyclesAbsorption cyclesAbsorption(const Rgb& absorption) {
  CyclesAbsorption out;
  out.density = largest(absorption);
  if (!(out.density > 0))
    throw std::logic_error("cyclesAbsorption needs an absorption with a positive channel");
  for (int c = 0; c < 3; ++c) out.color[c] = float(1.0 - double(absorption[c]) / out.density);
  return out;
}

double phongToBeckmannRoughness(double exponent) {
  return std::pow(2.0 / (exponent + 2.0), 0.25);
}

BlenderExport exportBlenderScript(const Scene& scene, const BlenderExportSettings& settings) {
  checkSettings(settings);
  BlenderExport result;
  result.warnings = phongWarnings(scene);
  const std::string spots = spotEntries(scene, result.warnings);
  for (std::string& warning : deltaCausticWarnings(scene)) result.warnings.push_back(warning);
  if (!scene.medium.empty())
    result.warnings.push_back(fmt::format(
        "the participating medium ({} particles) is left out; the Cycles image has surfaces and "
        "lights only",
        scene.medium.particles.size()));

  std::string data = fmt::format(
      "SCENE = {{\n    \"render\": {{\"width\": {}, \"height\": {}, \"spp\": {}, \"seed\": {}, "
      "\"max_bounces\": {}}},\n",
      settings.width, settings.height, settings.spp, settings.seed, kCyclesMaxBounces);
  data += cameraEntry(scene, settings);
  data += "    \"materials\": [\n";
  for (const Material& m : scene.materials) data += materialEntry(m);
  data += "    ],\n    \"meshes\": [\n";
  for (const Mesh& mesh : scene.meshes) data += meshEntry(mesh);
  data += "    ],\n    \"spot_lamps\": [\n" + spots + "    ],\n    \"sun_lamps\": [\n";
  data += sunEntries(scene);
  data += fmt::format("    ],\n    \"sky\": {},\n    \"environment\": {},\n}}\n\n",
                      vec(scene.sky_radiance), environmentEntry(scene));

  const EmbeddedFile* builder =
      findEmbeddedFile(embeddedBlenderBuilder(), "scene/blender_scene.py");
  if (!builder) throw std::logic_error("scene/blender_scene.py is not compiled in");
  result.script =
      header(scene, settings, result.warnings) + "\n" + data + std::string(builder->text);
  return result;
}

}  // namespace gib::scene
