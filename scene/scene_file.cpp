#include "scene/scene_file.h"

#include "common/input_error.h"
#include "common/join.h"
#include "scene/obj_mesh.h"
#include "scene/scene_file_materials.h"
#include "scene/scene_file_reader.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxImageSide = 32768;  // beyond any display or render target we would make

using ErrorReporter = TomlErrorReporter;

using TableReader = SceneTableReader;

const toml::table& requireTable(const ErrorReporter& errors, const toml::node& node,
                                const std::string& name, std::string_view fix) {
  return requireTomlTable(errors, node, name, fix);
}

// The thin lens of [camera]: lens_radius (default 0, the pinhole) and focus_distance (default
// look_at's distance, Camera::focus_distance).
void readLens(const TableReader& t, Camera& camera) {
  auto read = [&](std::string_view key, void (*check)(double, std::string_view)) {
    const toml::node* node = t.find(key);
    if (!node) return 0.0f;
    const double value = t.number(*node, key);
    try {
      check(value, fmt::format("camera.{}", key));
    } catch (const InputError& e) {
      t.errors().failWith(node->source(), e.what());
    }
    return static_cast<float>(value);
  };
  camera.lens_radius = read("lens_radius", checkLensRadius);
  camera.focus_distance = read("focus_distance", checkFocusDistance);
}

Camera readCamera(const TableReader& root) {
  const toml::node* node = root.find("camera");
  if (!node)
    root.errors().fail(root.table(), "missing table [camera]",
                       "add [camera] with position, look_at and vertical_fov_deg");
  const TableReader t(
      root.errors(), requireTable(root.errors(), *node, "camera", "write [camera]"), "camera",
      "[camera]",
      {"position", "look_at", "up", "vertical_fov_deg", "lens_radius", "focus_distance"});
  Camera camera;
  camera.position = t.vec3(t.require("position", "[x, y, z]"), "position");
  const toml::node& look_at = t.require("look_at", "[x, y, z]");
  camera.look_at = t.vec3(look_at, "look_at");
  camera.up = t.optional("up", &TableReader::vec3, glm::vec3(0, 1, 0));
  const toml::node& fov = t.require("vertical_fov_deg", "45.0");
  camera.vertical_fov_deg = static_cast<float>(t.number(fov, "vertical_fov_deg"));

  if (!(camera.vertical_fov_deg > 0 && camera.vertical_fov_deg < 180))
    t.errors().fail(
        fov,
        fmt::format("camera.vertical_fov_deg must be in (0, 180), got {}", camera.vertical_fov_deg),
        "give the full vertical field of view in degrees, e.g. 45.0");
  readLens(t, camera);
  const glm::vec3 forward = camera.look_at - camera.position;
  if (glm::length(forward) == 0)
    t.errors().fail(look_at, "camera.look_at equals camera.position",
                    "look at a point away from the camera");
  if (glm::length(glm::cross(forward, camera.up)) <=
      1e-6f * glm::length(forward) * glm::length(camera.up)) {
    if (const toml::node* up = t.find("up"))
      t.errors().fail(*up, "camera.up is zero or parallel to the viewing direction",
                      "choose an up vector across the viewing direction");
    t.errors().fail(look_at, "the default camera.up [0, 1, 0] is parallel to the viewing direction",
                    "add up = [x, y, z] across the viewing direction to [camera]");
  }
  return camera;
}

int readImageSide(const TableReader& t, std::string_view key, int fallback) {
  const toml::node* node = t.find(key);
  return node ? static_cast<int>(t.integer(*node, key, 1, kMaxImageSide, "512")) : fallback;
}

Mesh readMesh(const TableReader& t, const fs::path& base_dir,
              const std::map<std::string, std::uint32_t>& materials) {
  const toml::node& file = t.require("file", "\"mesh.obj\"");
  const std::string file_name = t.string(file, "file");
  const toml::node& material = t.require("material", "\"<material name>\"");
  const std::string material_name = t.string(material, "material");
  const auto found = materials.find(material_name);
  if (found == materials.end()) {
    std::vector<std::string> names;
    for (const auto& entry : materials) names.push_back(entry.first);
    t.errors().fail(material,
                    fmt::format("{} '{}' is not defined", t.path("material"), material_name),
                    names.empty() ? "define it in a [materials.<name>] table"
                                  : fmt::format("defined materials: {}", joinKeys(names)));
  }

  const glm::vec3 translate = t.optional("translate", &TableReader::vec3, glm::vec3(0.0f));
  glm::vec3 scale(1.0f);
  if (const toml::node* node = t.find("scale")) {
    if (!node->is_number() && !node->is_array())
      t.errors().fail(*node,
                      fmt::format("{} must be a number or an array of 3 numbers", t.path("scale")),
                      "write scale = 2.0 or scale = [x, y, z]");
    scale = node->is_number() ? glm::vec3(static_cast<float>(t.number(*node, "scale")))
                              : t.vec3(*node, "scale");
    if (scale.x <= 0 || scale.y <= 0 || scale.z <= 0)
      t.errors().fail(*node, fmt::format("{} must be > 0", t.path("scale")),
                      "give a positive number or [x, y, z] of positive numbers; use flip_normals "
                      "to turn a mesh's front side around");
  }
  const bool flip = t.optional("flip_normals", &TableReader::boolean, false);
  const bool smooth = t.optional("smooth", &TableReader::boolean, true);

  const fs::path path = (base_dir / fs::path(file_name)).lexically_normal();
  Mesh mesh = loadObjMesh(t, file, path, smooth);
  mesh.name = file_name;
  mesh.material = found->second;
  for (glm::vec3& p : mesh.positions) p = p * scale + translate;
  // Normals transform with the inverse transpose of the scale; they keep pointing to the front
  // side, so they turn around with it.
  for (glm::vec3& n : mesh.normals) n = glm::normalize(n / scale) * (flip ? -1.0f : 1.0f);
  if (flip)
    for (glm::uvec3& triangle : mesh.triangles) std::swap(triangle.y, triangle.z);
  return mesh;
}

// [environment]: a latitude–longitude EXR (its path relative to the scene file), turned by
// `rotation` degrees about +y and scaled by `intensity` (scene/environment_map.h).
EnvironmentMap readEnvironment(const TableReader& t, const fs::path& base_dir) {
  const toml::node& file = t.require("file", "\"sky.exr\"");
  const fs::path path = (base_dir / fs::path(t.string(file, "file"))).lexically_normal();
  EnvironmentMap map;
  try {
    map = loadEnvironmentMap(path);
  } catch (const InputError& e) {
    t.errors().fail(file, e.what(),
                    "give a latitude-longitude EXR twice as wide as high (`gibench sky` writes "
                    "one)");
  }
  map.rotation_deg = static_cast<float>(t.optional("rotation", &TableReader::number, 0.0));
  map.intensity = static_cast<float>(t.optional("intensity", &TableReader::number, 1.0));
  if (map.intensity < 0)
    t.errors().fail(*t.find("intensity"), fmt::format("{} must be >= 0", t.path("intensity")),
                    "give a scale of the map's radiance, e.g. intensity = 1");
  return map;
}

glm::vec3 readDirection(const TableReader& t) {
  const toml::node& node = t.require("direction", "[x, y, z]");
  const glm::vec3 direction = t.vec3(node, "direction");
  if (!(glm::length(direction) > 0))
    t.errors().fail(node, fmt::format("{} must not be zero", t.path("direction")),
                    "give the direction the light travels, e.g. [0, -1, 0]");
  return glm::normalize(direction);
}

void readLight(const TableReader& root, const toml::table& table, std::size_t i, Scene& scene) {
  const std::string name = fmt::format("lights[{}]", i);
  const std::string header = fmt::format("[[lights]] entry {}", i + 1);
  const toml::node* type = table.get("type");
  if (!type)
    root.errors().fail(table, fmt::format("missing key '{}.type'", name),
                       fmt::format("add type = \"spot\" or type = \"directional\" to {}", header));
  const std::string type_name = type->is_string() ? type->as_string()->get() : "";
  if (type_name == "spot") {
    const TableReader t(
        root.errors(), table, name, header + " (type \"spot\")",
        {"type", "position", "direction", "intensity", "cone_angle_deg", "falloff_exponent"});
    SpotLight light;
    light.position = t.vec3(t.require("position", "[x, y, z]"), "position");
    light.direction = readDirection(t);
    light.intensity = t.rgb(t.require("intensity", "[r, g, b]"), "intensity");
    const toml::node& cone = t.require("cone_angle_deg", "30.0");
    light.cone_angle_deg = static_cast<float>(t.number(cone, "cone_angle_deg"));
    if (!(light.cone_angle_deg > 0 && light.cone_angle_deg <= 180))
      t.errors().fail(cone,
                      fmt::format("{} must be in (0, 180], got {}", t.path("cone_angle_deg"),
                                  light.cone_angle_deg),
                      "give the cone's half angle in degrees");
    if (const toml::node* falloff = t.find("falloff_exponent")) {
      light.falloff_exponent = static_cast<float>(t.number(*falloff, "falloff_exponent"));
      if (light.falloff_exponent < 0)
        t.errors().fail(*falloff, fmt::format("{} must be >= 0", t.path("falloff_exponent")),
                        "use 0 for a constant intensity inside the cone");
    }
    scene.spot_lights.push_back(light);
  } else if (type_name == "directional") {
    const TableReader t(root.errors(), table, name, header + " (type \"directional\")",
                        {"type", "direction", "irradiance"});
    DirectionalLight light;
    light.direction = readDirection(t);
    light.irradiance = t.rgb(t.require("irradiance", "[r, g, b]"), "irradiance");
    scene.directional_lights.push_back(light);
  } else {
    root.errors().fail(*type, fmt::format("{}.type must be \"spot\" or \"directional\"", name),
                       "write type = \"spot\" or type = \"directional\"");
  }
}

}  // namespace

Scene loadSceneFile(const std::filesystem::path& toml_path) {
  const ErrorReporter errors(toml_path.string());
  const toml::table document = parseTomlFile(errors, toml_path, "scene file");
  const TableReader root(
      errors, document, "", "the top level of the scene file",
      {"name", "camera", "image", "materials", "meshes", "lights", "sky", "environment"});

  Scene scene;
  scene.name = root.optional("name", &TableReader::string, toml_path.stem().string());
  scene.provenance = "scene file " + fs::absolute(toml_path).lexically_normal().string();
  scene.camera = readCamera(root);
  if (const toml::node* node = root.find("image")) {
    const TableReader t(errors, requireTable(errors, *node, "image", "write [image]"), "image",
                        "[image]", {"width", "height"});
    scene.default_width = readImageSide(t, "width", scene.default_width);
    scene.default_height = readImageSide(t, "height", scene.default_height);
  }

  std::map<std::string, std::uint32_t> material_indices;
  scene.materials = readSceneFileMaterials(root, material_indices);
  const fs::path base_dir = fs::absolute(toml_path).parent_path();
  const std::vector<const toml::table*> meshes = tomlTableArray(root, "meshes");
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const TableReader t(errors, *meshes[i], fmt::format("meshes[{}]", i),
                        fmt::format("[[meshes]] entry {}", i + 1),
                        {"file", "material", "translate", "scale", "flip_normals", "smooth"});
    scene.meshes.push_back(readMesh(t, base_dir, material_indices));
  }
  const std::vector<const toml::table*> lights = tomlTableArray(root, "lights");
  for (std::size_t i = 0; i < lights.size(); ++i) readLight(root, *lights[i], i, scene);
  if (const toml::node* node = root.find("sky")) {
    const TableReader t(errors, requireTable(errors, *node, "sky", "write [sky]"), "sky", "[sky]",
                        {"radiance"});
    scene.sky_radiance = t.optional("radiance", &TableReader::rgb, Rgb(0.0f));
  }
  if (const toml::node* node = root.find("environment"))
    scene.environment = readEnvironment(
        TableReader(errors, requireTable(errors, *node, "environment", "write [environment]"),
                    "environment", "[environment]", {"file", "rotation", "intensity"}),
        base_dir);

  // The model's own checks; the ones above already give positions for what a file can get wrong.
  try {
    validateScene(scene);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", errors.file(), e.what()));
  }
  return scene;
}

}  // namespace gib::scene
