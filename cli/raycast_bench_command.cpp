// gibench raycast-bench --scene NAME [--scene-set K=V …] [--sweep K=V1,V2,…]
//                       [--rays primary,reflection,diffuse] [--structures …] [--width 256]
//                       [--height 256] [--repeats 5] [--seed 1] [--brute-force-limit N] --out DIR
// Book Ch. 5 against Embree: the same rays cast by Embree on every core and by each GPU
// structure; per structure the hit mismatches under the tie rule (realtime/ray_casting/
// hit_comparison.h), M rays/s, build time and memory. Writes DIR/raycast.json, raycast.csv and
// index.html (the table and a chart of rays/s against triangle count).
#include "cli/commands.h"
#include "common/input_error.h"
#include "common/parallel_for.h"
#include "common/progress.h"
#include "gib/version.h"
#include "image/output_files.h"
#include "metrics/timing_statistics.h"
#include "realtime/gl/context.h"
#include "realtime/ray_casting/hit_comparison.h"
#include "realtime/ray_casting/ray_cast_pass.h"
#include "realtime/ray_casting/ray_engine.h"
#include "realtime/ray_casting/ray_sets.h"
#include "realtime/ray_casting/ray_structures.h"
#include "reference/embree_scene.h"
#include "reports/raycast_bench_page.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct RaycastBenchOptions {
  std::string scene;
  std::vector<std::string> scene_set;
  std::string sweep;
  std::vector<std::string> rays = rt::rayKindNames();
  std::vector<std::string> structures;
  int width = 256, height = 256;
  int repeats = 5;
  std::uint64_t seed = 1;
  double brute_force_limit = 2e9;
  std::string out;
};

// The ray engine and the §5.1 loop test every ray against every triangle (the cones cull only
// coherent rays); on llvmpipe 2·10⁹ tests take about a minute.
constexpr int kMaxSide = 2000;  // 4·10⁶ rays: one dispatch's work groups (65 535 × 64)
constexpr int kMaxRepeats = 1000;

std::vector<std::string> allStructures() {
  std::vector<std::string> names = {"embree"};
  for (const std::string& s : rt::gpuRayStructureNames()) {
    names.push_back(s);
    if (s == "brute_force") {
      names.push_back("ray_engine");
      names.push_back("ray_engine_cones");
    }
  }
  return names;
}

bool bruteForceFamily(std::string_view name) {
  return name == "brute_force" || name == "ray_engine" || name == "ray_engine_cones";
}

// The scene instances: one, or one per value of --sweep.
std::vector<std::vector<std::string>> sceneInstances(const RaycastBenchOptions& o) {
  if (o.sweep.empty()) return {o.scene_set};
  const std::size_t eq = o.sweep.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == o.sweep.size())
    throw InputError(fmt::format(
        "--sweep '{}' is not KEY=V1,V2,…; give e.g. --sweep detail=1,2,3,4,5", o.sweep));
  std::vector<std::vector<std::string>> instances;
  std::stringstream values(o.sweep.substr(eq + 1));
  for (std::string value; std::getline(values, value, ',');) {
    if (value.empty())
      throw InputError(fmt::format("--sweep '{}' has an empty value; give V1,V2,…", o.sweep));
    std::vector<std::string> set = o.scene_set;
    set.push_back(o.sweep.substr(0, eq + 1) + value);
    instances.push_back(set);
  }
  return instances;
}

void validate(RaycastBenchOptions& o) {
  if (o.width < 1 || o.height < 1 || o.width > kMaxSide || o.height > kMaxSide)
    throw InputError(fmt::format(
        "--width {} --height {} is out of range; give 1..{} a side (one dispatch's rays)", o.width,
        o.height, kMaxSide));
  if (o.repeats < 1 || o.repeats > kMaxRepeats)
    throw InputError(
        fmt::format("--repeats {} is out of range; give 1..{}", o.repeats, kMaxRepeats));
  if (!(o.brute_force_limit >= 0))
    throw InputError("--brute-force-limit must be ≥ 0 (ray–triangle tests per cast)");
  for (const std::string& kind : o.rays) rt::parseRayKind(kind);
  if (o.structures.empty()) o.structures = allStructures();
  const std::vector<std::string> known = allStructures();
  for (const std::string& s : o.structures)
    if (std::find(known.begin(), known.end(), s) == known.end())
      throw InputError(fmt::format("--structures: unknown structure '{}'; give some of {}", s,
                                   fmt::join(known, ", ")));
  std::error_code ec;
  if (fs::exists(o.out, ec) && !fs::is_directory(o.out, ec))
    throw InputError(fmt::format("--out '{}' is a file; give a directory", o.out));
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A structure as the bench drives it.
struct Caster {
  std::string name;
  std::function<void(const std::vector<rt::CastRay>&)> set_rays;
  std::function<void()> cast;
  std::function<std::vector<rt::gpu::RayCastHit>()> hits;
  std::function<std::size_t()> bytes;
  std::function<std::optional<double>()> kept_pairs = [] { return std::optional<double>(); };
};

// Median and quartiles of `repeats` timed calls after one untimed warm-up.
metrics::TimingSummary timeRepeats(int repeats, const std::function<void()>& once) {
  once();
  std::vector<double> ms;
  for (int r = 0; r < repeats; ++r) {
    const Clock::time_point start = Clock::now();
    once();
    ms.push_back(millisecondsSince(start));
  }
  return metrics::summarizeTimings(ms);
}

nlohmann::json timingJson(const metrics::TimingSummary& t) {
  return {{"first_quartile_ms", t.first_quartile},
          {"median_ms", t.median},
          {"third_quartile_ms", t.third_quartile}};
}

int runRaycastBench(RaycastBenchOptions& o) {
  validate(o);
  // Every scene is loaded and checked before anything is cast or written.
  struct Instance {
    std::vector<std::string> set;
    scene::Scene scene;
    rt::IvmTriangleSet triangles;
  };
  std::vector<Instance> instances;
  for (const std::vector<std::string>& set : sceneInstances(o)) {
    scene::Scene scene = scene::loadScene(o.scene, set);
    rt::IvmTriangleSet triangles = rt::buildIvmTriangles(scene);
    instances.push_back({set, std::move(scene), std::move(triangles)});
  }
  const std::unique_ptr<rt::gl::Context> context = rt::gl::Context::create();
  const int threads = resolveThreadCount(0);
  ProgressBar progress("raycast bench", instances.size() * o.rays.size() * o.structures.size(),
                       "casts");

  std::vector<reports::RaycastCase> cases;
  nlohmann::json json_cases = nlohmann::json::array();
  std::ostringstream csv;
  csv << "scene,scene_hash,triangles,rays,ray_count,structure,skipped,mismatches,wrong_triangle,"
         "missed,extra,ties,max_abs_dt,mean_abs_dt,max_barycentric_error,mrays_per_second,"
         "cast_median_ms,build_ms,bytes\n";
  for (const Instance& instance : instances) {
    const std::string scene_label =
        instance.set.empty() ? o.scene
                             : fmt::format("{} {}", o.scene, fmt::join(instance.set, " "));
    const std::string hash = scene::hashScene(instance.scene);
    const Clock::time_point embree_start = Clock::now();
    const auto embree_scene = std::make_shared<const ref::EmbreeScene>(instance.scene);
    const double embree_build_ms = millisecondsSince(embree_start);
    const ref::EmbreeScene& embree = *embree_scene;
    // The primary hits that secondary rays leave from, through the same BVH.
    const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCaster(embree_scene);

    // The GPU structures, built once per scene (CPU build and upload, finished).
    std::vector<Caster> casters;
    std::vector<double> build_ms;
    std::vector<std::unique_ptr<rt::GpuRayStructure>> structures;
    std::vector<std::unique_ptr<rt::RayCastPass>> passes;
    std::vector<std::unique_ptr<rt::RayEngine>> engines;
    for (const std::string& name : o.structures) {
      if (name == "embree") continue;
      glFinish();
      const Clock::time_point start = Clock::now();
      if (name == "ray_engine" || name == "ray_engine_cones") {
        engines.push_back(
            std::make_unique<rt::RayEngine>(instance.triangles, name == "ray_engine_cones"));
        glFinish();
        build_ms.push_back(millisecondsSince(start));
        rt::RayEngine* engine = engines.back().get();
        const int width = o.width;
        casters.push_back(
            {name,
             [engine, width](const std::vector<rt::CastRay>& r) { engine->setRays(r, width); },
             [engine] { engine->cast(); }, [engine] { return engine->hits(); },
             [engine] { return engine->bytes(); },
             [engine]() -> std::optional<double> {
               if (engine->name() != "ray_engine_cones") return std::nullopt;
               return engine->keptPairFraction();
             }});
      } else {
        structures.push_back(rt::makeGpuRayStructure(name, instance.triangles));
        glFinish();
        build_ms.push_back(millisecondsSince(start));
        passes.push_back(std::make_unique<rt::RayCastPass>(*structures.back()));
        rt::RayCastPass* pass = passes.back().get();
        const rt::GpuRayStructure* structure = structures.back().get();
        casters.push_back({name, [pass](const std::vector<rt::CastRay>& r) { pass->setRays(r); },
                           [pass] { pass->cast(); }, [pass] { return pass->hits(); },
                           [structure] { return structure->bytes(); }});
      }
    }

    for (const std::string& kind_name : o.rays) {
      const rt::RayKind kind = rt::parseRayKind(kind_name);
      const std::vector<scene::Ray> rays =
          rt::makeRaySet(instance.scene, kind, o.width, o.height, o.seed, *caster);
      std::vector<scene::RayHit> reference(rays.size());
      const bool coherent = kind == rt::RayKind::kPrimary;
      auto embree_cast = [&] {
        parallelFor(rays.size(), threads, 4096, [&](std::size_t begin, std::size_t end) {
          embree.intersect(std::span(rays).subspan(begin, end - begin),
                           std::span(reference).subspan(begin, end - begin), coherent);
        });
      };
      reports::RaycastCase c;
      c.scene = scene_label;
      c.rays = kind_name;
      c.triangles = instance.triangles.size();
      c.ray_count = rays.size();
      c.tie_distance = rt::tieDistance(instance.triangles);
      const metrics::TimingSummary embree_ms = timeRepeats(o.repeats, embree_cast);
      for (const scene::RayHit& h : reference) c.reference_hits += h.valid() ? 1 : 0;
      nlohmann::json json_structures = nlohmann::json::array();
      auto record = [&](const reports::RaycastStructureRow& row, const rt::HitComparison* cmp) {
        c.structures.push_back(row);
        nlohmann::json j = {
            {"name", row.name},
            {"mismatches", row.skipped.empty() ? nlohmann::json(row.mismatches) : nlohmann::json()},
            {"mrays_per_second", row.mrays_per_second},
            {"build_ms", row.build_ms},
            {"bytes", row.bytes ? nlohmann::json(*row.bytes) : nlohmann::json()}};
        if (!row.skipped.empty()) j["skipped"] = row.skipped;
        if (row.kept_pair_fraction) j["kept_pair_fraction"] = *row.kept_pair_fraction;
        if (row.cast_ms.count > 0) j["cast"] = timingJson(row.cast_ms);
        if (cmp)
          j["hits"] = {{"wrong_triangle", cmp->wrong_triangle},
                       {"missed", cmp->missed},
                       {"extra", cmp->extra},
                       {"ties", cmp->ties},
                       {"same_triangle", cmp->same_triangle},
                       {"max_abs_dt", cmp->max_abs_dt},
                       {"mean_abs_dt", cmp->mean_abs_dt},
                       {"max_barycentric_error", cmp->max_barycentric_error},
                       {"mean_barycentric_error", cmp->mean_barycentric_error}};
        json_structures.push_back(j);
        csv << fmt::format(
            "\"{}\",{},{},{},{},{},\"{}\",{},{},{},{},{},{:.9g},{:.9g},{:.9g},{:.6g},"
            "{:.6g},{:.6g},{}\n",
            scene_label, hash, c.triangles, kind_name, c.ray_count, row.name, row.skipped,
            row.skipped.empty() ? std::to_string(row.mismatches) : "",
            cmp ? cmp->wrong_triangle : 0, cmp ? cmp->missed : 0, cmp ? cmp->extra : 0,
            cmp ? cmp->ties : 0, cmp ? cmp->max_abs_dt : 0, cmp ? cmp->mean_abs_dt : 0,
            cmp ? cmp->max_barycentric_error : 0, row.mrays_per_second, row.cast_ms.median,
            row.build_ms, row.bytes ? std::to_string(*row.bytes) : "");
        progress.advance(1);
      };
      if (std::find(o.structures.begin(), o.structures.end(), "embree") != o.structures.end()) {
        reports::RaycastStructureRow row;
        row.name = "embree";
        row.cast_ms = embree_ms;
        row.mrays_per_second = double(rays.size()) / (embree_ms.median * 1e3);
        row.build_ms = embree_build_ms;
        row.bytes = embree.bytes();
        record(row, nullptr);
      }
      const std::vector<rt::CastRay> cast_rays = rt::castRaysOf(instance.triangles, rays);
      for (std::size_t s = 0; s < casters.size(); ++s) {
        Caster& gpu = casters[s];
        reports::RaycastStructureRow row;
        row.name = gpu.name;
        row.build_ms = build_ms[s];
        const double tests = double(rays.size()) * double(instance.triangles.size());
        if (bruteForceFamily(gpu.name) && tests > o.brute_force_limit) {
          row.skipped = fmt::format(
              "{:.3g} ray–triangle tests per cast, over --brute-force-limit "
              "{:.3g}",
              tests, o.brute_force_limit);
          record(row, nullptr);
          continue;
        }
        gpu.set_rays(cast_rays);
        row.cast_ms = timeRepeats(o.repeats, [&] {
          gpu.cast();
          glFinish();
        });
        row.mrays_per_second = double(rays.size()) / (row.cast_ms.median * 1e3);
        row.bytes = gpu.bytes();
        row.kept_pair_fraction = gpu.kept_pairs();
        const std::vector<rt::gpu::RayCastHit> hits = gpu.hits();
        const rt::HitComparison cmp = rt::compareHits(instance.scene, instance.triangles, rays,
                                                      reference, hits, c.tie_distance);
        row.mismatches = cmp.mismatches;
        row.ties = cmp.ties;
        row.max_abs_dt = cmp.max_abs_dt;
        row.max_barycentric_error = cmp.max_barycentric_error;
        record(row, &cmp);
      }
      json_cases.push_back({{"scene", o.scene},
                            {"scene_parameters", instance.set},
                            {"scene_hash", hash},
                            {"triangles", c.triangles},
                            {"degenerate_triangles", instance.triangles.degenerate},
                            {"ivm_min_plane_distance", instance.triangles.min_plane_distance},
                            {"rays", kind_name},
                            {"ray_count", c.ray_count},
                            {"reference_hits", c.reference_hits},
                            {"tie_distance", c.tie_distance},
                            {"structures", json_structures}});
      cases.push_back(std::move(c));
    }
  }
  progress.finish();

  const rt::gl::GlIdentity& gl = context->identity();
  nlohmann::json summary = {{"gibench_version", kVersion},
                            {"gl_renderer", gl.renderer},
                            {"gl_version", gl.version},
                            {"embree_version", ref::embreeVersion()},
                            {"embree_threads", threads},
                            {"parameters",
                             {{"scene", o.scene},
                              {"scene_set", o.scene_set},
                              {"sweep", o.sweep},
                              {"rays", o.rays},
                              {"structures", o.structures},
                              {"width", o.width},
                              {"height", o.height},
                              {"repeats", o.repeats},
                              {"seed", o.seed},
                              {"brute_force_limit", o.brute_force_limit},
                              {"tie_fraction", rt::kTieFraction}}},
                            {"cases", json_cases}};
  fs::create_directories(o.out);
  image::writeTextFile(fs::path(o.out) / "raycast.json", summary.dump(2) + "\n");
  image::writeTextFile(fs::path(o.out) / "raycast.csv", csv.str());
  const std::vector<std::pair<std::string, std::string>> facts = {
      {"gibench", kVersion},
      {"GL renderer", gl.renderer},
      {"Embree", fmt::format("{} on {} threads", ref::embreeVersion(), threads)},
      {"scene", o.scene},
      {"rays", fmt::format("{} × {} camera pixels; diffuse seed {}", o.width, o.height, o.seed)},
      {"timing", fmt::format("median of {} casts after one warm-up, wall clock, GPU finished "
                             "(glFinish); rays uploaded beforehand",
                             o.repeats)}};
  image::writeTextFile(fs::path(o.out) / "index.html", reports::raycastBenchPage(facts, cases));

  for (const reports::RaycastCase& c : cases) {
    fmt::print("{}, {} rays ({}), {} triangles\n", c.scene, c.rays, c.ray_count, c.triangles);
    fmt::print("  {:<18} {:>10} {:>8} {:>10} {:>10} {:>12}\n", "structure", "mismatches", "ties",
               "M rays/s", "build ms", "MiB");
    for (const reports::RaycastStructureRow& r : c.structures) {
      if (!r.skipped.empty()) {
        fmt::print("  {:<18} skipped: {}\n", r.name, r.skipped);
        continue;
      }
      fmt::print("  {:<18} {:>10} {:>8} {:>10.3g} {:>10.3g} {:>12}\n", r.name,
                 r.name == "embree" ? std::string("-") : std::to_string(r.mismatches),
                 r.name == "embree" ? std::string("-") : std::to_string(r.ties), r.mrays_per_second,
                 r.build_ms, r.bytes ? fmt::format("{:.2f}", double(*r.bytes) / 1048576.0) : "-");
    }
  }
  fmt::print("wrote {}\n", (fs::path(o.out) / "index.html").string());
  return 0;
}

}  // namespace

CommandRunner addRaycastBenchCommand(CLI::App& app) {
  auto o = std::make_shared<RaycastBenchOptions>();
  CLI::App* command = app.add_subcommand(
      "raycast-bench",
      "Ray casting on the GPU (book Ch. 5: ray engine, loose kd-tree, a BVH) against Embree: "
      "hit mismatches, rays/s, build time, memory");
  command->add_option("--scene", o->scene, "built-in scene or scene file")->required();
  command->add_option("--scene-set", o->scene_set, "scene parameter KEY=VALUE (repeatable)");
  command->add_option("--sweep", o->sweep,
                      "one scene parameter over values, KEY=V1,V2,… (e.g. detail=1,2,3,4,5)");
  command->add_option("--rays", o->rays, "kinds of rays: primary, reflection, diffuse")
      ->delimiter(',')
      ->capture_default_str();
  command
      ->add_option("--structures", o->structures,
                   "embree, brute_force, ray_engine, ray_engine_cones, loose_kd_tree, bvh "
                   "(default: all)")
      ->delimiter(',');
  command->add_option("--width", o->width, "camera pixels across (rays)")->capture_default_str();
  command->add_option("--height", o->height, "camera pixels down")->capture_default_str();
  command->add_option("--repeats", o->repeats, "timed casts per structure (medians)")
      ->capture_default_str();
  command->add_option("--seed", o->seed, "seed of the diffuse rays")->capture_default_str();
  command
      ->add_option("--brute-force-limit", o->brute_force_limit,
                   "skip brute_force and the ray engines above this many ray-triangle tests")
      ->capture_default_str();
  command->add_option("--out", o->out, "directory for raycast.json, raycast.csv, index.html")
      ->required();
  return [o] { return runRaycastBench(*o); };
}

}  // namespace gib::cli
