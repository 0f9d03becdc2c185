#include "scene/scene_file_materials.h"

#include "common/join.h"
#include "scene/metals.h"

#include <fmt/format.h>

#include <string_view>
#include <utility>

namespace gib::scene {

namespace {

constexpr std::string_view kTypes = "\"lambert\", \"phong\", \"mirror\" or \"glass\"";

// Lambert and Phong: diffuse (and specular, exponent), optional emission.
void readReflector(const SceneTableReader& t, const std::string& name, bool phong, Material& m) {
  m.type = phong ? MaterialType::kPhong : MaterialType::kLambert;
  const toml::node& diffuse = t.require("diffuse", "[r, g, b]");
  m.diffuse = t.rgb(diffuse, "diffuse");
  m.emission = t.optional("emission", &SceneTableReader::rgb, Rgb(0.0f));
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
}

// Mirror: a named metal, or the complex index n + iκ given per channel; exactly one of the two.
void readMirror(const SceneTableReader& t, const std::string& name, Material& m) {
  const toml::node* metal = t.find("metal");
  const toml::node* n = t.find("n");
  const toml::node* k = t.find("k");
  const std::string metals = joinNames(metalNames(), ", ");
  if (metal && (n || k))
    t.errors().fail(n ? *n : *k, fmt::format("{} gives both metal and n/k", name),
                    "give either metal = \"<name>\" or n = [r, g, b] with k = [r, g, b]");
  if (metal) {
    const std::string metal_name = t.string(*metal, "metal");
    const Metal* found = findMetal(metal_name);
    if (!found)
      t.errors().fail(*metal,
                      fmt::format("{} '{}' is not a known metal", t.path("metal"), metal_name),
                      fmt::format("use one of {}, or give n and k", metals));
    m = mirrorMaterial(m.name, *found);
    return;
  }
  if (!n && !k)
    t.errors().fail(
        t.table(), fmt::format("{} (type \"mirror\") gives neither metal nor n and k", name),
        fmt::format("add metal = \"<name>\" ({}) or n = [r, g, b] and k = [r, g, b]", metals));
  if (!n || !k)
    t.errors().fail(n ? *n : *k,
                    fmt::format("{} gives {} without {}", name, n ? "n" : "k", n ? "k" : "n"),
                    "give both the refractive index n and the extinction coefficient k (kappa)");
  m.type = MaterialType::kMirror;
  m.conductor_n = t.vec3(*n, "n");
  m.conductor_k = t.vec3(*k, "k");
  for (int c = 0; c < 3; ++c) {
    if (!(m.conductor_n[c] > 0))
      t.errors().fail(*n,
                      fmt::format("{} must be > 0 in every channel, got {} in channel {}",
                                  t.path("n"), m.conductor_n[c], c),
                      "give the metal's refractive index (gold's is 0.14 at 660 nm)");
    if (m.conductor_k[c] < 0)
      t.errors().fail(*k,
                      fmt::format("{} (kappa) must be >= 0 in every channel, got {} in channel {}",
                                  t.path("k"), m.conductor_k[c], c),
                      "give the metal's extinction coefficient (gold's is 3.7 at 660 nm)");
  }
}

// Glass: the index of refraction (default 1.5) and an optional Beer–Lambert absorption.
void readGlass(const SceneTableReader& t, Material& m) {
  m.type = MaterialType::kGlass;
  if (const toml::node* ior = t.find("ior")) {
    m.ior = static_cast<float>(t.number(*ior, "ior"));
    if (!(m.ior >= kMinGlassIor && m.ior <= kMaxGlassIor))
      t.errors().fail(*ior,
                      fmt::format("{} must be in [{}, {}], got {}", t.path("ior"), kMinGlassIor,
                                  kMaxGlassIor, m.ior),
                      "give the index of refraction relative to air (glass is about 1.5)");
  }
  m.absorption = t.optional("absorption", &SceneTableReader::rgb, Rgb(0.0f));
}

}  // namespace

std::vector<Material> readSceneFileMaterials(const SceneTableReader& root,
                                             std::map<std::string, std::uint32_t>& indices) {
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  if (const toml::node* node = root.find("materials")) {
    const toml::table& table = requireTomlTable(
        root.errors(), *node, "materials", "write each material as a [materials.<name>] table");
    entries = entriesInFileOrder(table);
  }

  std::vector<Material> materials;
  for (const auto& [key, node] : entries) {
    const std::string name = "materials." + std::string(key->str());
    const std::string header = "[" + name + "]";
    const toml::table& table =
        requireTomlTable(root.errors(), *node, name, "write it as a [materials.<name>] table");
    Material m;
    m.name = std::string(key->str());
    const toml::node* type = table.get("type");
    const std::string type_name = type && type->is_string() ? type->as_string()->get() : "";
    if (!type)
      root.errors().fail(table, fmt::format("missing key '{}.type'", name),
                         fmt::format("add type = {} to {}", kTypes, header));
    // The keys each type allows: any other is an error, so a key of another type is never
    // silently ignored.
    std::vector<std::string> allowed;
    if (type_name == "lambert")
      allowed = {"type", "diffuse", "emission"};
    else if (type_name == "phong")
      allowed = {"type", "diffuse", "emission", "specular", "exponent"};
    else if (type_name == "mirror")
      allowed = {"type", "metal", "n", "k"};
    else if (type_name == "glass")
      allowed = {"type", "ior", "absorption"};
    else
      root.errors().fail(*type, fmt::format("{}.type must be {}", name, kTypes),
                         fmt::format("write type = {}", kTypes));
    const SceneTableReader t(root.errors(), table, name, header + " (type \"" + type_name + "\")",
                             allowed);
    if (type_name == "mirror")
      readMirror(t, name, m);
    else if (type_name == "glass")
      readGlass(t, m);
    else
      readReflector(t, name, type_name == "phong", m);
    indices[m.name] = static_cast<std::uint32_t>(materials.size());
    materials.push_back(std::move(m));
  }
  return materials;
}

}  // namespace gib::scene
