#include "scene/scene_file.h"

#include "common/input_error.h"
#include "common/join.h"
#include "common/toml_reader.h"

#include <fmt/format.h>
#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxImageSide = 32768;  // beyond any display or render target we would make

using ErrorReporter = TomlErrorReporter;

bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The shared reader (common/toml_reader.h) plus the vectors and colours of scene files.
class TableReader : public TomlTableReader {
 public:
  using TomlTableReader::TomlTableReader;

  glm::vec3 vec3(const toml::node& node, std::string_view key) const {
    const toml::array* array = node.as_array();
    glm::vec3 v(NAN);
    if (array && array->size() == 3) {
      for (int i = 0; i < 3; ++i)
        v[i] = static_cast<float>(tomlNumber(*array->get(static_cast<std::size_t>(i))));
    }
    if (!isFinite(v))
      errors().fail(node, fmt::format("{} must be an array of 3 numbers", path(key)),
                    "write it as [x, y, z] with finite values");
    return v;
  }

  // An RGB quantity: reflectance, radiance, intensity or irradiance, never negative.
  Rgb rgb(const toml::node& node, std::string_view key) const {
    const glm::vec3 v = vec3(node, key);
    if (v.r < 0 || v.g < 0 || v.b < 0)
      errors().fail(
          node, fmt::format("{} must not be negative, got [{}, {}, {}]", path(key), v.r, v.g, v.b),
          "use values >= 0");
    return v;
  }

  template <typename Read, typename T>
  T optional(std::string_view key, Read read, T fallback) const {
    const toml::node* node = find(key);
    return node ? (this->*read)(*node, key) : fallback;
  }
};

const toml::table& requireTable(const ErrorReporter& errors, const toml::node& node,
                                const std::string& name, std::string_view fix) {
  return requireTomlTable(errors, node, name, fix);
}

Camera readCamera(const TableReader& root) {
  const toml::node* node = root.find("camera");
  if (!node)
    root.errors().fail(root.table(), "missing table [camera]",
                       "add [camera] with position, look_at and vertical_fov_deg");
  const TableReader t(root.errors(), requireTable(root.errors(), *node, "camera", "write [camera]"),
                      "camera", "[camera]", {"position", "look_at", "up", "vertical_fov_deg"});
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

// Reads [materials.*] in the order of the file; `indices` maps names to Scene::materials indices.
std::vector<Material> readMaterials(const TableReader& root,
                                    std::map<std::string, std::uint32_t>& indices) {
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  if (const toml::node* node = root.find("materials")) {
    const toml::table& table = requireTable(root.errors(), *node, "materials",
                                            "write each material as a [materials.<name>] table");
    entries = entriesInFileOrder(table);
  }

  std::vector<Material> materials;
  for (const auto& [key, node] : entries) {
    const std::string name = "materials." + std::string(key->str());
    const std::string header = "[" + name + "]";
    const toml::table& table =
        requireTable(root.errors(), *node, name, "write it as a [materials.<name>] table");
    Material m;
    m.name = std::string(key->str());
    const toml::node* type = table.get("type");
    const std::string type_name = type && type->is_string() ? type->as_string()->get() : "";
    if (!type)
      root.errors().fail(table, fmt::format("missing key '{}.type'", name),
                         fmt::format("add type = \"lambert\" or type = \"phong\" to {}", header));
    if (type_name != "lambert" && type_name != "phong")
      root.errors().fail(*type, fmt::format("{}.type must be \"lambert\" or \"phong\"", name),
                         "write type = \"lambert\" or type = \"phong\"");
    const bool phong = type_name == "phong";
    std::vector<std::string> allowed = {"type", "diffuse", "emission"};
    if (phong) allowed.insert(allowed.end(), {"specular", "exponent"});
    const TableReader t(root.errors(), table, name, header + " (type \"" + type_name + "\")",
                        allowed);

    m.type = phong ? MaterialType::kPhong : MaterialType::kLambert;
    const toml::node& diffuse = t.require("diffuse", "[r, g, b]");
    m.diffuse = t.rgb(diffuse, "diffuse");
    m.emission = t.optional("emission", &TableReader::rgb, Rgb(0.0f));
    const toml::node* energy_at = &diffuse;
    if (phong) {
      energy_at = &t.require("specular", "[r, g, b]");
      m.specular = t.rgb(*energy_at, "specular");
      const toml::node& exponent = t.require("exponent", "50.0");
      m.exponent = static_cast<float>(t.number(exponent, "exponent"));
      if (m.exponent < 0)
        t.errors().fail(exponent, fmt::format("{}.exponent must be >= 0, got {}", name, m.exponent),
                        "use a Phong exponent >= 0");
    }
    // A material that reflects more than it receives makes the path tracer diverge.
    for (int c = 0; c < 3; ++c) {
      if (m.diffuse[c] + m.specular[c] > 1.0f)
        t.errors().fail(*energy_at,
                        fmt::format("{} reflects more light than it receives: {} = {} > 1 in "
                                    "channel {}",
                                    name, phong ? "diffuse + specular" : "diffuse",
                                    m.diffuse[c] + m.specular[c], c),
                        phong ? "lower diffuse or specular" : "use a reflectance <= 1");
    }
    indices[m.name] = static_cast<std::uint32_t>(materials.size());
    materials.push_back(std::move(m));
  }
  return materials;
}

// The text of the OBJ file at `path`; `where` is the `file` value, for errors.
std::string readObjText(const TableReader& t, const toml::node& where, const fs::path& path) {
  const std::string key = t.path("file");
  const std::string fix = "check the path (a relative path starts at the scene file's folder)";
  std::error_code ec;
  if (!fs::exists(path, ec))
    t.errors().fail(where, fmt::format("OBJ file '{}' ({}) does not exist", path.string(), key),
                    fix);
  if (!fs::is_regular_file(path, ec))
    t.errors().fail(where, fmt::format("OBJ path '{}' ({}) is not a file", path.string(), key),
                    fix);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in.is_open()) text << in.rdbuf();
  if (!in.is_open() || in.bad())
    t.errors().fail(where, fmt::format("cannot read OBJ file '{}' ({})", path.string(), key),
                    "check the file's permissions");
  return text.str();
}

// Triangles of an OBJ file (positions only); `where` is the `file` value, for errors.
Mesh loadObj(const TableReader& t, const toml::node& where, const fs::path& path) {
  const std::string key = t.path("file");
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string with an empty material library: the OBJ's own materials are never read.
  if (!reader.ParseFromString(readObjText(t, where, path), "", config))
    t.errors().fail(where,
                    fmt::format("OBJ file '{}' ({}) is malformed: {}", path.string(), key,
                                oneLine(reader.Error())),
                    "fix or re-export the OBJ file");

  Mesh mesh;
  const std::vector<tinyobj::real_t>& v = reader.GetAttrib().vertices;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    mesh.positions.emplace_back(v[i], v[i + 1], v[i + 2]);
    if (!isFinite(mesh.positions.back()))
      t.errors().fail(where,
                      fmt::format("OBJ file '{}' ({}) has a non-finite position at vertex {}",
                                  path.string(), key, mesh.positions.size()),
                      "fix or re-export the OBJ file");
  }
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t first = 0;
    for (unsigned int corners : shape.mesh.num_face_vertices) {
      // Already triangles after triangulation; a fan keeps any other polygon whole.
      for (unsigned int k = 1; k + 1 < corners; ++k) {
        glm::uvec3 triangle;
        for (int c = 0; c < 3; ++c) {
          const std::size_t corner = first + (c == 0 ? 0 : k + static_cast<unsigned int>(c) - 1);
          const int index = shape.mesh.indices[corner].vertex_index;
          if (index < 0 || static_cast<std::size_t>(index) >= mesh.positions.size())
            t.errors().fail(
                where,
                fmt::format("OBJ file '{}' ({}) refers to vertex {} but has {} vertices",
                            path.string(), key, index + 1, mesh.positions.size()),
                "fix or re-export the OBJ file");
          triangle[c] = static_cast<unsigned int>(index);
        }
        mesh.triangles.push_back(triangle);
      }
      first += corners;
    }
  }
  if (mesh.triangles.empty())
    t.errors().fail(where, fmt::format("OBJ file '{}' ({}) has no triangles", path.string(), key),
                    "give the OBJ file at least one face ('f' line) of 3 or more vertices");
  return mesh;
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
  bool flip = false;
  if (const toml::node* node = t.find("flip_normals")) {
    if (!node->is_boolean())
      t.errors().fail(*node, fmt::format("{} must be true or false", t.path("flip_normals")),
                      "write flip_normals = true or flip_normals = false");
    flip = node->as_boolean()->get();
  }

  const fs::path path = (base_dir / fs::path(file_name)).lexically_normal();
  Mesh mesh = loadObj(t, file, path);
  mesh.name = file_name;
  mesh.material = found->second;
  for (glm::vec3& p : mesh.positions) p = p * scale + translate;
  if (flip)
    for (glm::uvec3& triangle : mesh.triangles) std::swap(triangle.y, triangle.z);
  return mesh;
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
  const TableReader root(errors, document, "", "the top level of the scene file",
                         {"name", "camera", "image", "materials", "meshes", "lights", "sky"});

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
  scene.materials = readMaterials(root, material_indices);
  const fs::path base_dir = fs::absolute(toml_path).parent_path();
  const std::vector<const toml::table*> meshes = tomlTableArray(root, "meshes");
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const TableReader t(errors, *meshes[i], fmt::format("meshes[{}]", i),
                        fmt::format("[[meshes]] entry {}", i + 1),
                        {"file", "material", "translate", "scale", "flip_normals"});
    scene.meshes.push_back(readMesh(t, base_dir, material_indices));
  }
  const std::vector<const toml::table*> lights = tomlTableArray(root, "lights");
  for (std::size_t i = 0; i < lights.size(); ++i) readLight(root, *lights[i], i, scene);
  if (const toml::node* node = root.find("sky")) {
    const TableReader t(errors, requireTable(errors, *node, "sky", "write [sky]"), "sky", "[sky]",
                        {"radiance"});
    scene.sky_radiance = t.optional("radiance", &TableReader::rgb, Rgb(0.0f));
  }

  // The model's own checks; the ones above already give positions for what a file can get wrong.
  try {
    validateScene(scene);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", errors.file(), e.what()));
  }
  return scene;
}

}  // namespace gib::scene
