// The interface every real-time technique implements, and the catalogue that turns a name into
// one (pbrt's habit: one place maps names to objects, so the command line, `gibench list` and the
// suites agree on what exists and what it takes).
#pragma once

#include "common/parameters.h"
#include "image/image.h"
#include "realtime/pass_declarations.h"
#include "scene/obscurance.h"
#include "scene/path_class.h"
#include "scene/ray_caster.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gib::scene {
struct Scene;
}

namespace gib::rt {

class GpuScene;
class RenderTarget;
namespace gl {
class PassProfiler;
}

// What a frame renders into and is timed by, and where it is in the run: a technique that
// animates (a moving light) ends its animation at rest on the last frame, frames_left == 0, so
// the image that is measured is the scene's own.
struct Frame {
  RenderTarget& target;  // linear float RGB(A) at the output resolution
  gl::PassProfiler& profiler;
  int frames_left = 0;  // frames of the run after this one
  int frame_count = 1;  // frames of the run, warm-up included
};

// An image of a technique's internal state, linear float RGB like the camera image.
struct AuxiliaryImage {
  std::string name;         // a file-name-safe identifier: "atlas", "indirect-1"
  std::string description;  // one line, shown under the image in the report
  image::Image image;
};

struct TechniqueStatistic {
  std::string name;  // identifier: "vertices", "atlas_texels"
  double value = 0;
};

// What the harness lends a technique besides the GPU scene. The ray caster is the reference's
// Embree BVH (the realtime layer may not include the reference), for preprocessing that traces
// rays on the CPU; empty where the caller has none to lend.
struct TechniqueServices {
  scene::RayCasterFactory ray_caster;
};

// Constructing a technique (TechniqueInfo::create) must do no GL work: `gibench list` builds one
// without a context to ask its path class. GL objects are made in prepare().
class Technique {
 public:
  virtual ~Technique() = default;

  // Called once before prepare() with what the harness lends (TechniqueServices).
  virtual void provide(const TechniqueServices& /*services*/) {}

  // Builds everything that depends on the scene and the output size (programs, shadow maps,
  // volumes). Called once, after the scene has been uploaded; its time is reported separately.
  virtual void prepare(const GpuScene& scene, int width, int height) = 0;
  // Renders one frame of the current state into frame.target.
  virtual void render(Frame& frame) = 0;

  // A technique that computes on the CPU (the irradiance cache baseline) is timed by the
  // profiler's CPU clock on any renderer: GPU timestamps would miss its work.
  virtual bool timedOnCpu() const { return false; }

  // Iterative techniques (radiosity, light propagation) refine a state: step() runs one
  // iteration, iterations() counts those run, so the harness can draw error against iterations.
  virtual bool iterative() const { return false; }
  virtual void step(gl::PassProfiler& /*profiler*/) {}
  virtual int iterations() const { return 0; }

  // The light paths this technique models with its current parameters and state
  // (docs/architecture.md, "Path classes").
  virtual scene::PathClass pathClass() const = 0;
  // The class it will model after `iterations` steps, asked before any is run so that the harness
  // can pick the reference: an iteration that adds a scattering order (the illumination network)
  // overrides it.
  virtual scene::PathClass pathClassAfter(int /*iterations*/) const { return pathClass(); }
  // What the camera image holds when it is not radiance: an obscurance W(x) per pixel (book
  // Ch. 10, `obscurances` with output=obscurance). The harness then measures the image against a
  // reference of that obscurance (ref::RenderSettings::obscurance) instead of the radiance
  // references of its path class and of all paths.
  virtual std::optional<scene::ObscuranceDefinition> imageObscurance() const {
    return std::nullopt;
  }

  // Images of the technique's internal state that a paper shows beside the camera image (a
  // radiance atlas, one bounce's contribution). Called once after the last measured frame with
  // the context current; the harness writes them beside the job's image and shows them in the
  // report.
  virtual std::vector<AuxiliaryImage> auxiliaryImages() { return {}; }

  // Counts that figures are drawn against (vertices drawn, texels, grid points), recorded in the
  // job's results. Called after prepare().
  virtual std::vector<TechniqueStatistic> statistics() const { return {}; }
  // Counts measured on the last frame (a search's mean error against Embree), recorded with
  // statistics(). Called after auxiliaryImages(); declared in TechniqueInfo::statistics alike.
  virtual std::vector<TechniqueStatistic> finalStatistics() const { return {}; }
  // The pixels its own light reaches, where the rest of the image is the shared direct light (a
  // gathered object, the mirrors and glass): one channel of the image's size, 1 inside, pixel
  // (0,0) at the top left. The harness measures relMSE over them too (relmse_region). Called
  // after auxiliaryImages(); none: the whole image is the technique's.
  virtual std::optional<image::Image> measuredRegion() { return std::nullopt; }
};

// What a technique needs besides a GPU scene. The runner checks every need once, before the
// technique is made, and refuses a job whose scene or caller lacks one with a line naming it; a
// suite runs a technique only on the scenes that have what it needs.
enum class TechniqueNeed {
  kRayCaster,  // the harness's CPU ray caster (TechniqueServices::ray_caster)
  kMedium,     // a participating medium (the scene's particles)
  // a mesh that reflects or refracts ideally (scene::Scene::hasIdealSpecular); a technique without
  // it is refused such a scene
  kSpecularMaterials,
  kEnvironmentLight,  // light arriving from beyond the scene (a constant sky or a map)
  // a mesh with triangles that does not emit, for a technique that shades one object by itself
  // (distance_map_gather's final gathering)
  kShadedObject,
};

// "ray caster", "participating medium", …: the need in messages, `gibench list` and the READMEs.
std::string_view needName(TechniqueNeed need);

// An auxiliary image or a statistic a technique may write, declared before anything runs so that
// a suite naming one ("aux:atlas", "statistic:vertices") is checked when it loads, and a technique
// writing one it did not declare fails its tests. A name ending in "<n>" stands for a family
// numbered from 1: "indirect-<n>" declares indirect-1, indirect-2, ….
struct DeclaredOutput {
  std::string name;
  std::string description;  // one line, for `gibench list techniques` and the README
};

// The declared output `name` is an instance of, or nullptr.
const DeclaredOutput* findDeclaredOutput(const std::vector<DeclaredOutput>& declared,
                                         std::string_view name);

struct TechniqueInfo {
  std::string name;
  std::string description;  // one line
  std::string source;       // the document and section it implements
  ParameterTable parameters;
  // Every pass its frames and iterations may time, whatever the parameters (a variance shadow
  // map's filter, a GPU selection's pyramid): the runner refuses a profile with any other.
  PassDeclarations passes;
  // Every image auxiliaryImages() and every statistic statistics() may return, whatever the
  // parameters; the runner refuses any other.
  std::vector<DeclaredOutput> auxiliary_images;
  std::vector<DeclaredOutput> statistics;
  std::vector<TechniqueNeed> needs;
  // Whether it renders mirrors and glass where a scene has them without needing them (a scene
  // without is no less its subject): `environment_map`'s diffuse objects alone. A technique that
  // needs them declares kSpecularMaterials, which implies this.
  bool renders_specular_materials = false;
  // Whether it renders an environment map's light and shows the map where camera rays leave the
  // scene (scene::Scene::environment). A scene with a map is refused to every technique that
  // does not, as a scene with mirrors is: its own passes would take the map for black.
  bool renders_environment_map = false;
  std::function<std::unique_ptr<Technique>(const ParameterValues&)> create;

  bool hasNeed(TechniqueNeed need) const;
  // renders_specular_materials, or a need of them.
  bool rendersSpecularMaterials() const;
};

// The first need of `info` that the scene lacks (a medium, a sky, a specular material), or the
// mirrors and glass (Scene::hasIdealSpecular) of a scene given to a technique that does not
// declare kSpecularMaterials, with a line saying why and what to do; empty when the scene suits
// the technique. A suite is checked with it when it loads.
std::optional<std::string> missingSceneNeed(const TechniqueInfo& info, const scene::Scene& scene);
// Whether any need of `info` is a feature of the scene (a medium, a sky, specular materials).
bool needsSceneFeatures(const TechniqueInfo& info);
// missingSceneNeed, and the services the technique needs (the ray caster): what the runner checks
// once, before it makes the technique.
std::optional<std::string> missingNeed(const TechniqueInfo& info, const scene::Scene& scene,
                                       const TechniqueServices& services);

// Every technique, in catalogue order.
const std::vector<TechniqueInfo>& techniqueCatalogue();

// Throws gib::InputError naming the known techniques for an unknown name.
const TechniqueInfo& findTechnique(std::string_view name);

}  // namespace gib::rt
