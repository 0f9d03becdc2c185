// The marble chamber: a procedural vaulted hall in the spirit of the marble chamber of
// Szirmay-Kalos, Szécsi & Sbert, "GPU-Based Techniques for Global Illumination Effects", §8.4,
// Fig. 8.12/8.13 (3335 triangles, lit by a spot light aimed at the floor), and of the hall of
// Nijasure et al.'s irradiance volumes. A nave under a barrel vault, two aisles behind arcades
// of round arches on pillars, closed by end walls: every surface bounces light, so indirect
// illumination matters, and the red wainscot, plinths and green arch soffits bleed colour.
//
// Units are metres. x runs across the hall (aisle walls at x = ±4), y up (floor at 0), z along
// it (end walls at z = 0 and z = 12). The `detail` parameter d multiplies every tessellation
// count, so the triangle count grows as d²: 3 384 at d = 1 (the book's chamber has 3 335),
// 85 240 at d = 5 (the scale of the paper's art gallery), for timing sweeps.
//
// sky=true is the book's Fig. 4.15, "a difficult scene, where only a small fraction of the
// environment is visible from surface points inside the room": four roof lights cut in the vault's
// crown let in the Preetham sky (scene/sky_parameters.h, as `outdoor` builds it) and, with the
// default sun 70° high behind the camera, patches of sunlight on the nave's floor.
#include "common/input_error.h"
#include "scene/builtin_scenes.h"
#include "scene/chamber_geometry.h"
#include "scene/mesh_builder.h"
#include "scene/metals.h"
#include "scene/sky_parameters.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

using chamber::appendArchSoffit;
using chamber::appendBarrelVault;
using chamber::appendBox;
using chamber::appendLunette;
using chamber::appendPanel;
using chamber::appendShaft;
using chamber::appendSpandrel;

// The hall's layout (metres). Five bays of 2.4 m; the arcades stand on the lines x = ±2.5.
constexpr double kHalfWidth = 4.0;        // aisle walls at x = ±kHalfWidth
constexpr double kLength = 12.0;          // end walls at z = 0 and z = kLength
constexpr int kBays = 5;                  // arches per arcade
constexpr double kBay = kLength / kBays;  // pillar spacing
constexpr double kArcadeX = 2.5;          // axis of each arcade
constexpr double kWallHalfThickness = 0.3;
constexpr double kNaveHalfWidth = kArcadeX - kWallHalfThickness;  // also the vault's radius
constexpr double kAisleInnerX = kArcadeX + kWallHalfThickness;
constexpr double kPlinthHalfSize = 0.4, kPlinthHeight = 0.3;
constexpr double kShaftRadius = 0.24;
constexpr double kCapitalHalfSize = 0.35, kCapitalHeight = 0.3;
constexpr double kSpringY = 3.0;  // top of the capitals: where the arches spring
constexpr double kArchRadius = kBay / 2 - kCapitalHalfSize;
constexpr double kAisleCeilingY = 4.4;  // flat ceiling of the aisles
constexpr double kVaultSpringY = 5.0;   // the nave vault's springing line (crown at 7.2 m)
constexpr double kWainscotY = 1.0;      // top of the red marble band around the walls

// sky=true: roof lights along the crown, each the vault's two crown segments across (22.5° of arc,
// 0.86 m wide at the crown, 7.2 m up) and one metre along, at z = 1, 4, 7 and 10 m (symmetric
// about the middle of the nave). They are whole cells of the vault's tessellation at every
// detail level, so the vault keeps its vertices and the rest of the shell stays closed.
constexpr int kRoofLightRows[] = {1, 4, 7, 10};  // metre rows of the vault (kVaultRows = 12)
// The default sun: 70° high, azimuth 270° (towards −z, behind the camera, which looks along +z),
// so that the light falling through the roof lights lands on the floor 2.6 m further along the
// nave, in view.
constexpr const char* kSkySunElevation = "70";
constexpr const char* kSkySunAzimuth = "270";

// Tessellation at detail 1; each count is multiplied by the detail level.
constexpr int kFloorCellsAcross = 16, kFloorCellsAlong = 24;  // 0.5 m tiles
constexpr int kVaultSegments = 16, kVaultRows = 12;
constexpr int kLunetteRings = 2;
constexpr int kShaftSegments = 16, kShaftRows = 3;
constexpr int kArchSegments = 12;
constexpr int kWallCellsAlong = 12, kWallRowsUpper = 3, kEndWallCellsAcross = 8,
              kEndWallRowsUpper = 4;

std::uint32_t addMaterial(Scene& scene, std::string name, Rgb diffuse, Rgb specular = Rgb(0.0f),
                          float exponent = 1.0f) {
  Material m;
  m.name = std::move(name);
  m.type = specular == Rgb(0.0f) ? MaterialType::kLambert : MaterialType::kPhong;
  m.diffuse = diffuse;
  m.specular = specular;
  m.exponent = exponent;
  scene.materials.push_back(m);
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

struct Materials {
  std::uint32_t wall, pillar, floor, rosso, verde;
};

Materials addMaterials(Scene& scene) {
  Materials m;
  // Rec.709 linear reflectances of polished marbles, chosen by eye (no measured data): a warm
  // light marble for the shell, a cooler white for the pillars, a darker glossy floor (diffuse +
  // specular ≤ 1), and a red and a green marble for colour bleeding.
  m.wall = addMaterial(scene, "light_marble", {0.75f, 0.72f, 0.66f});
  m.pillar = addMaterial(scene, "pillar_marble", {0.80f, 0.79f, 0.76f});
  m.floor = addMaterial(scene, "floor_marble", {0.30f, 0.29f, 0.27f}, Rgb(0.1f), 30.0f);
  m.rosso = addMaterial(scene, "rosso_marble", {0.62f, 0.20f, 0.14f});
  m.verde = addMaterial(scene, "verde_marble", {0.16f, 0.42f, 0.28f});
  return m;
}

Mesh makeMesh(std::string name, std::uint32_t material) {
  Mesh mesh;
  mesh.name = std::move(name);
  mesh.material = material;
  return mesh;
}

void addMeshes(Scene& scene, std::initializer_list<Mesh*> meshes) {
  for (Mesh* mesh : meshes) scene.meshes.push_back(std::move(*mesh));
}

// Whether vault cell (i across, j along) at detail d is a roof light: the two crown segments
// (kVaultSegments·d across, the crown at i = kVaultSegments·d/2) in the rows of kRoofLightRows.
bool isRoofLight(int i, int j, int d) {
  const int crown = kVaultSegments * d / 2;
  if (i < crown - d || i >= crown + d) return false;
  for (int row : kRoofLightRows)
    if (j / d == row) return true;
  return false;
}

// Floor, aisle walls, aisle ceilings, end walls and the nave's vault: the closed shell, with roof
// lights in the vault when `roof_lights`.
void addShell(Scene& scene, const Materials& m, int d, bool roof_lights) {
  Mesh floor = makeMesh("floor", m.floor);
  appendPanel(floor, {-kHalfWidth, 0, 0}, {2 * kHalfWidth, 0, 0}, {0, 0, kLength},
              kFloorCellsAcross * d, kFloorCellsAlong * d, {0, 1, 0});

  Mesh wainscot = makeMesh("wainscot", m.rosso);
  Mesh aisle_walls = makeMesh("aisle_walls", m.wall);
  Mesh aisle_ceilings = makeMesh("aisle_ceilings", m.wall);
  for (double side : {-1.0, 1.0}) {
    const double x = side * kHalfWidth;
    appendPanel(wainscot, {x, 0, 0}, {0, 0, kLength}, {0, kWainscotY, 0}, kWallCellsAlong * d, d,
                {-side, 0, 0});
    appendPanel(aisle_walls, {x, kWainscotY, 0}, {0, 0, kLength},
                {0, kAisleCeilingY - kWainscotY, 0}, kWallCellsAlong * d, kWallRowsUpper * d,
                {-side, 0, 0});
    appendPanel(aisle_ceilings, {side * kAisleInnerX, kAisleCeilingY, 0},
                {side * (kHalfWidth - kAisleInnerX), 0, 0}, {0, 0, kLength}, d, kWallCellsAlong * d,
                {0, -1, 0});
  }

  // The end walls run full width up to the vault's springing line (the parts above the aisle
  // ceilings lie outside the hall and are never seen); a lunette closes the vault above.
  Mesh end_walls = makeMesh("end_walls", m.wall);
  Mesh lunettes = makeMesh("lunettes", m.wall);
  for (double z : {0.0, kLength}) {
    const double facing = z == 0.0 ? 1.0 : -1.0;
    appendPanel(wainscot, {-kHalfWidth, 0, z}, {2 * kHalfWidth, 0, 0}, {0, kWainscotY, 0},
                kEndWallCellsAcross * d, d, {0, 0, facing});
    appendPanel(end_walls, {-kHalfWidth, kWainscotY, z}, {2 * kHalfWidth, 0, 0},
                {0, kVaultSpringY - kWainscotY, 0}, kEndWallCellsAcross * d, kEndWallRowsUpper * d,
                {0, 0, facing});
    appendLunette(lunettes, z, facing, kVaultSpringY, kNaveHalfWidth, kVaultSegments * d,
                  kLunetteRings * d);
  }
  Mesh vault = makeMesh("vault", m.wall);
  chamber::PatchCells openings;
  if (roof_lights) openings = [d](int i, int j) { return isRoofLight(i, j, d); };
  appendBarrelVault(vault, kVaultSpringY, kNaveHalfWidth, 0.0, kLength, kVaultSegments * d,
                    kVaultRows * d, openings);
  addMeshes(scene,
            {&floor, &wainscot, &aisle_walls, &aisle_ceilings, &end_walls, &lunettes, &vault});
}

// The two arcades: pillars (plinth, shaft, capital) at the bay boundaries, half piers (responds)
// against the end walls, and over each bay a round arch in a wall that rises to the vault on the
// nave side and to the aisle ceiling on the aisle side.
void addArcades(Scene& scene, const Materials& m, int d) {
  Mesh plinths = makeMesh("plinths", m.rosso);
  Mesh shafts = makeMesh("pillar_shafts", m.pillar);
  Mesh capitals = makeMesh("capitals", m.pillar);
  Mesh responds = makeMesh("responds", m.pillar);
  Mesh arcade_walls = makeMesh("arcade_walls", m.wall);
  Mesh soffits = makeMesh("arch_soffits", m.verde);
  for (double side : {-1.0, 1.0}) {
    const double axis = side * kArcadeX;
    const double nave_face = side * kNaveHalfWidth, aisle_face = side * kAisleInnerX;

    // Pillars at the inner bay boundaries.
    for (int k = 1; k < kBays; ++k) {
      const double z = kBay * k;
      appendBox(plinths, {axis - kPlinthHalfSize, 0, z - kPlinthHalfSize},
                {axis + kPlinthHalfSize, kPlinthHeight, z + kPlinthHalfSize}, d, false);
      appendShaft(shafts, {axis, kPlinthHeight, z}, kShaftRadius,
                  kSpringY - kCapitalHeight - kPlinthHeight, kShaftSegments * d, kShaftRows * d);
      appendBox(capitals,
                {axis - kCapitalHalfSize, kSpringY - kCapitalHeight, z - kCapitalHalfSize},
                {axis + kCapitalHalfSize, kSpringY, z + kCapitalHalfSize}, d, true);
    }

    // Responds: the first and last arches spring from piers built into the end walls. Only
    // their three free faces are built (the fourth would lie in the end wall's plane).
    for (double end : {0.0, kLength}) {
      const double inward = end == 0.0 ? 1.0 : -1.0;
      const double face_z = end + inward * kCapitalHalfSize;
      const glm::dvec3 up(0, kSpringY, 0), depth(0, 0, face_z - end);
      appendPanel(responds, {nave_face, 0, end}, depth, up, d, 3 * d, {-side, 0, 0});
      appendPanel(responds, {aisle_face, 0, end}, depth, up, d, 3 * d, {side, 0, 0});
      appendPanel(responds, {nave_face, 0, face_z}, {aisle_face - nave_face, 0, 0}, up, d, 3 * d,
                  {0, 0, inward});
    }

    // Arches: the soffit under each, the wall around it on both faces.
    for (int b = 0; b < kBays; ++b) {
      const double z0 = kBay * b, z1 = b + 1 == kBays ? kLength : kBay * (b + 1);
      appendArchSoffit(soffits, nave_face, aisle_face, (z0 + z1) / 2, kSpringY, kArchRadius,
                       kArchSegments * d, d);
      appendSpandrel(arcade_walls, nave_face, -side, z0, z1, kSpringY, kVaultSpringY, kArchRadius,
                     kArchSegments * d, d);
      appendSpandrel(arcade_walls, aisle_face, side, z0, z1, kSpringY, kAisleCeilingY, kArchRadius,
                     kArchSegments * d, d);
    }
  }
  addMeshes(scene, {&plinths, &shafts, &capitals, &responds, &arcade_walls, &soffits});
}

// specular=objects: specular objects standing on the nave's floor for the distance-map
// reflections and refractions of the book's §6.2 (Figs. 6.9 and 6.11). An aluminium torus stands
// in for the aluminium teapot (2 300 triangles there, 2 304 here) and a glass sphere of index 1.3
// for the glass skull of Fig. 6.9; a thin glass pane and a thin mirror panel are the thin objects
// whose reflections show the linear search's missed spikes (Fig. 6.11). All stand in the
// spot-lit middle of the nave (the spot reaches the floor around (0.4, 0, 7.5)), inside the
// default view (which sees the floor from z ≈ 4 on), clear of each other and at least 0.3 m
// inside the plinths' faces (x = ±2.1). Each is its own mesh and material; every one is closed,
// the glass ones facing outwards as glass must. They float 5 mm above the floor, so that no
// triangle touches or cuts it.
constexpr float kLift = 0.005f;
constexpr float kSkullRadius = 0.4f;
constexpr glm::vec3 kSkullCentre{-0.4f, kSkullRadius + kLift, 6.0f};
constexpr float kSkullIor = 1.3f;
constexpr int kSkullRings = 32, kSkullSegments = 64;
// Upright, on its rim, the ring turned 45° from the view so that its hole and both curvatures show.
constexpr float kTeapotMajorRadius = 0.45f, kTeapotMinorRadius = 0.15f;
constexpr glm::vec3 kTeapotCentre{1.1f, kTeapotMajorRadius + kTeapotMinorRadius + kLift, 7.0f};
constexpr glm::vec3 kTeapotAxis{1.0f, 0.0f, -1.0f};
constexpr int kTeapotRings = 48, kTeapotSegments = 24;
// The pane: 1.0 m wide, 1.2 m high, 4 cm thick, turned 30° about the vertical; the mirror panel:
// 1.0 × 1.4 m, 2 cm thick, turned −40°, facing the middle of the nave.
constexpr float kPaneHalfWidth = 0.5f, kPaneHalfHeight = 0.6f, kPaneHalfThickness = 0.02f;
constexpr glm::vec3 kPaneCentre{-1.3f, kPaneHalfHeight + kLift, 8.5f};
constexpr float kPaneYawDeg = 30.0f;
constexpr float kPanelHalfWidth = 0.5f, kPanelHalfHeight = 0.7f, kPanelHalfThickness = 0.01f;
constexpr glm::vec3 kPanelCentre{1.4f, kPanelHalfHeight + kLift, 9.8f};
constexpr float kPanelYawDeg = -40.0f;

// An upright slab turned `yaw_deg` about the vertical: its width along (cos yaw, 0, sin yaw).
void appendUprightSlab(Mesh& mesh, glm::vec3 centre, float half_width, float half_height,
                       float half_thickness, float yaw_deg) {
  const float yaw = glm::radians(yaw_deg);
  const glm::vec3 across(std::cos(yaw), 0.0f, std::sin(yaw));
  const glm::vec3 through(-across.z, 0.0f, across.x);
  appendParallelepiped(mesh, centre, half_width * across, {0.0f, half_height, 0.0f},
                       half_thickness * through);
}

Material glassMaterial(std::string name, float ior) {
  Material glass;
  glass.name = std::move(name);
  glass.type = MaterialType::kGlass;
  glass.ior = ior;
  return glass;
}

void addSpecularObjects(Scene& scene) {
  const Metal& aluminium = *findMetal("aluminium");
  appendTorus(addMeshOfMaterial(scene, "aluminium_torus", mirrorMaterial("aluminium", aluminium)),
              kTeapotCentre, kTeapotAxis, kTeapotMajorRadius, kTeapotMinorRadius, kTeapotRings,
              kTeapotSegments);
  appendSphere(addMeshOfMaterial(scene, "glass_sphere", glassMaterial("glass_1.3", kSkullIor)),
               kSkullCentre, kSkullRadius, kSkullRings, kSkullSegments, /*inward=*/false,
               SphereShading::kSmooth);
  appendUprightSlab(addMeshOfMaterial(scene, "glass_pane", glassMaterial("pane_glass", 1.5f)),
                    kPaneCentre, kPaneHalfWidth, kPaneHalfHeight, kPaneHalfThickness, kPaneYawDeg);
  appendUprightSlab(addMeshOfMaterial(scene, "mirror_panel",
                                      mirrorMaterial("panel_silver", *findMetal("silver"))),
                    kPanelCentre, kPanelHalfWidth, kPanelHalfHeight, kPanelHalfThickness,
                    kPanelYawDeg);
}

glm::vec3 toVec3(const std::vector<double>& v) {
  return {float(v[0]), float(v[1]), float(v[2])};
}

// The spot light, hung under the crown of the vault. Its default (500 W/sr from 7.7 m, reaching
// the floor at 31° from the normal) gives the middle of the lit floor a diffuse radiance of
// about 0.3/π · 500 · cos 31° / 7.7² ≈ 0.7, and the indirect light adds some tenths: bright
// but not clipped by the sRGB display transform at exposure 0.
void addSpotLight(Scene& scene, const ParameterValues& parameters) {
  const glm::vec3 position = toVec3(parameters.vector3("light_position"));
  const glm::vec3 target = toVec3(parameters.vector3("light_target"));
  if (glm::length(target - position) < 1e-3f)
    throw InputError(fmt::format(
        "scene 'chamber' parameter light_target = '{}' is where the light is; give a target away "
        "from light_position = '{}'",
        parameters.text("light_target"), parameters.text("light_position")));
  SpotLight spot;
  spot.position = position;
  spot.direction = glm::normalize(target - position);
  spot.intensity = Rgb(float(parameters.number("light_intensity")));
  spot.cone_angle_deg = 30.0f;
  spot.falloff_exponent = 2.0f;
  scene.spot_lights.push_back(spot);
}

}  // namespace

ParameterTable chamberParameters() {
  return joinParameterTables(
      {{
           numericParameter("detail", ParameterType::kInteger, "1", 1, 5, "",
                            "tessellation level d: about 3400·d² triangles (1: 3384, like the "
                            "book's chamber; 5: "
                            "85240)"),
           numericParameter(
               "light_position", ParameterType::kVector3, "0,6.6,3.5", -100, 100, "m",
               "spot light position (the hall spans x in [-4, 4], y in [0, 7.2], z in [0, 12])"),
           numericParameter("light_target", ParameterType::kVector3, "0.4,0,7.5", -100, 100, "m",
                            "point the spot light aims at (on the floor, y = 0, by default)"),
           numericParameter("light_intensity", ParameterType::kNumber, "500", 0, 1e6, "W/sr",
                            "spot light intensity on its axis (white)"),
           choiceParameter(
               "specular", "none", {"none", "objects"},
               "specular objects on the nave's floor (book Figs. 6.9 and 6.11): an "
               "aluminium torus for the teapot, a glass sphere of index 1.3 for the skull, "
               "a thin glass pane and a thin silver mirror panel"),
           booleanParameter(
               "sky", false,
               "book Fig. 4.15: four roof lights (0.86 × 1 m) in the vault's crown open "
               "the hall to the sky (the environment parameters below; ignored without "
               "it)"),
           choiceParameter(
               "spot_light", "auto", {"auto", "on", "off"},
               "the spot light: auto is on without the sky and off with it (the sky and "
               "sun through the roof lights are then the only light)"),
       },
       skyParameters({kSkySunElevation, kSkySunAzimuth,
                      "(the camera looks along +z; 270 puts the sun behind it, so that sunlight "
                      "through the roof lights lands on the floor in view)"})});
}

Scene makeChamber(const ParameterValues& parameters) {
  Scene scene;
  scene.name = "chamber";
  scene.provenance =
      "procedural marble chamber after Szirmay-Kalos et al. Fig. 8.12/8.13 (3335 triangles) and "
      "Nijasure et al.'s hall: vaulted nave, arcades of round arches on pillars, spot light aimed "
      "at the floor";
  const int d = parameters.integer("detail");

  // Geometry.
  const Materials materials = addMaterials(scene);
  const bool sky = parameters.boolean("sky");
  addShell(scene, materials, d, sky);
  addArcades(scene, materials, d);
  if (parameters.text("specular") == "objects") addSpecularObjects(scene);

  if (sky) {
    scene.environment = makeSkyEnvironment(parameters, "chamber");
    scene.provenance += "; sky=true: roof lights open to the Preetham sky (book Fig. 4.15)";
  }
  const std::string& spot_light = parameters.text("spot_light");
  if (spot_light == "on" || (spot_light == "auto" && !sky)) addSpotLight(scene, parameters);

  // The camera stands near the entrance at eye height, slightly off the axis, and looks down the
  // nave: the arcades on both sides, the vault and the lit floor ahead.
  scene.camera.position = {-0.9f, 1.7f, 0.6f};
  scene.camera.look_at = {0.4f, 2.4f, 12.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = 60.0f;
  scene.default_width = 640;
  scene.default_height = 480;
  return scene;
}

}  // namespace gib::scene
