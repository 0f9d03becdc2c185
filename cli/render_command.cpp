#include "cli/commands.h"
#include "cli/render_options.h"
#include "scene/builtin_scenes.h"

#include <memory>

namespace gib::cli {

std::vector<std::string> givenOptions(const CLI::App& app, const std::vector<std::string>& names) {
  std::vector<std::string> given;
  for (const std::string& name : names)
    if (app.count(name) > 0) given.push_back(name);
  return given;
}

scene::Scene loadRenderScene(const RenderOptions& o) {
  scene::Scene scene = scene::loadScene(o.scene, o.scene_set);
  scene::applyLens(scene.camera, o.lens, "--lens-radius", "--focus-distance");
  return scene;
}

CommandRunner addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* render =
      app.add_subcommand("render", "Render a scene with the reference or a technique");
  render->add_option("--scene", o->scene, "built-in scene name or path to a .toml scene file")
      ->required();
  render->add_option("--scene-set", o->scene_set,
                     "scene parameter key=value (repeatable; see `gibench list scenes`)");
  render->add_option("--technique", o->technique,
                     "reference (default) or a technique (see `gibench list techniques`)");
  render->add_option("--width", o->width, "image width in pixels (default: the scene's)");
  render->add_option("--height", o->height, "image height in pixels (default: the scene's)");
  render->add_option("--out", o->out, "output EXR (a PNG is written beside it)")->required();
  render->add_option("--lens-radius", o->lens.radius,
                     "thin-lens radius in scene units, 0 for the pinhole (default: the scene's, "
                     "usually 0); the reference renders its depth of field, a technique keeps its "
                     "pinhole and records the lens in its metadata");
  render->add_option("--focus-distance", o->lens.focus_distance,
                     "distance in scene units along the view to the plane in focus (default: the "
                     "scene's, else look_at's distance)");

  const char* kReference = "Reference path tracer";
  render->add_option("--spp", o->spp, "samples per pixel")
      ->capture_default_str()
      ->group(kReference);
  render->add_option("--seed", o->seed, "random seed")->capture_default_str()->group(kReference);
  render
      ->add_option("--replicas", o->replicas,
                   "independently scrambled batches whose spread gives the variance layer; must "
                   "divide --spp (default: its largest divisor up to 4)")
      ->group(kReference);
  render
      ->add_option("--sampler", o->sampler,
                   "sobol (padded Owen-scrambled Sobol points) or independent (classic Monte "
                   "Carlo, for comparison)")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--environment-occlusion", o->environment_occlusion,
                   "on, or off: the environment (sky or map) lights diffuse and glossy surfaces "
                   "unblocked, the assumption of environment mapping without shadows (book "
                   "§4.2.1-4.2.2)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--light-paths", o->light_paths,
                   "auto (trace the caustics' paths, L S (D|S)* D E, from the lights when the "
                   "scene has mirrors or glass) or off (camera paths only: caustics of spot and "
                   "directional lights go missing)")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--pixel-sampling", o->pixel_sampling,
                   "area (a box filter over each pixel, anti-aliased) or center (every camera ray "
                   "through the pixel centre, as a rasteriser samples: the reference a real-time "
                   "frame is measured against)")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--paths", o->paths,
                   "only the paths this expression matches, in Heckbert's notation read from the "
                   "light to the eye: L(D|S|P)*E all, LS+DE caustics on diffuse surfaces, LDSE a "
                   "diffuse surface seen in a mirror (docs/rendering.md, \"Path classes\")")
      ->group(kReference);
  render
      ->add_option("--min-bounces", o->min_bounces,
                   "only paths with at least this many bounces (0: emitters seen directly); "
                   "with --max-bounces b, short for --paths 'L(D|S|P){a,b}E'")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--max-bounces", o->max_bounces,
                   "only paths with at most this many bounces (default: unlimited)")
      ->group(kReference);
  render->add_option("--threads", o->threads, "worker threads, 0 = all cores (same image)")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--obscurance", o->obscurance,
                   "render the obscurance W(x) at each pixel's first hit instead of radiance, "
                   "with this fall-off: sqrt (rho(d) = sqrt(d/d_max)) or ambient_occlusion (a step "
                   "at d_max) (docs/rendering.md, \"Obscurances\")")
      ->group(kReference);
  render
      ->add_option("--obscurance-mode", o->obscurance_mode,
                   "with --obscurance: scalar (grey W in [0, 1]) or spectral (weighted by the "
                   "albedo seen: colour bleeding)")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_option("--d-max", o->d_max,
                   "with --obscurance: d_max as a fraction of the scene's bounding-box diagonal")
      ->capture_default_str()
      ->group(kReference);
  render
      ->add_flag("--checkpoints", o->checkpoints,
                 "also write the mean at 1, 2, 4, ... spp as <stem>.sppNNNN.exr")
      ->group(kReference);

  const char* kTechnique = "Real-time techniques";
  render
      ->add_option("--set", o->set,
                   "technique parameter key=value (repeatable; see `gibench list techniques`)")
      ->group(kTechnique);
  render->add_option("--frames", o->frames, "measured frames")
      ->capture_default_str()
      ->group(kTechnique);
  render->add_option("--warmup", o->warmup, "warm-up frames before measuring")
      ->capture_default_str()
      ->group(kTechnique);
  render
      ->add_option("--iterations", o->iterations,
                   "iterative techniques: iterations before the frames")
      ->capture_default_str()
      ->group(kTechnique);
  render
      ->add_option("--clock", o->clock,
                   "pass timing clock: gpu (timestamp queries), cpu (glFinish around each pass), "
                   "auto (cpu on a software renderer)")
      ->check(CLI::IsMember({"auto", "gpu", "cpu"}))
      ->capture_default_str()
      ->group(kTechnique);
  render
      ->add_option(
          "--gl-device", o->gl_device,
          "EGL device: auto, surfaceless or an index (default: $GIBENCH_GL_DEVICE or auto)")
      ->group(kTechnique);
  render->add_option("--timings-json", o->timings_json, "also write the pass timings as JSON here")
      ->group(kTechnique);

  return [o, render] {
    return o->technique == "reference" ? renderReference(*o, *render)
                                       : renderTechnique(*o, *render);
  };
}

}  // namespace gib::cli
