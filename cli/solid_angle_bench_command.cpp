// gibench solid-angle-bench --out DIR [--sizes 32,48,64] [--schemes ...] [--grid 100]
//                           [--timing-samples 25000] [--seed 1] [--figure-size 48]
// The bench test of hardware area-light sampling (Fournier & Péroche §6.1, Figs. 7–9): every
// scheme and image size estimates the visible solid angle of a partly hidden square light at a
// grid of points, against the exact value; writes the statistics, the per-point errors, the error
// images and a page.
#include "cli/commands.h"
#include "common/input_error.h"
#include "common/progress.h"
#include "gib/version.h"
#include "image/display.h"
#include "image/false_color.h"
#include "image/output_files.h"
#include "metrics/timing_statistics.h"
#include "realtime/gl/context.h"
#include "realtime/techniques/jittered_light_sampling/solid_angle_bench.h"
#include "reports/solid_angle_bench_page.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct SolidAngleBenchOptions {
  std::string out;
  std::vector<int> sizes = {32, 48, 64};
  std::vector<std::string> schemes = rt::coverageSchemeNames();
  int grid = 100;
  std::size_t timing_samples = 25000;
  std::uint32_t seed = 1;
  int figure_size = 48;
};

constexpr int kMaxGrid = 1000;
constexpr std::size_t kMaxTimingSamples = 1000000;

// The paper's Fig. 8 panels: regular, jittered with 1 and with 4 samples per pixel.
const std::vector<std::string> kFigureSchemes = {"regular", "jittered1", "jittered4"};

void validate(SolidAngleBenchOptions& o) {
  for (int size : o.sizes) rt::validateCoverageSize(size);
  for (const std::string& name : o.schemes) {
    rt::CoverageSettings s;
    rt::parseCoverageScheme(name, s);
  }
  if (o.grid < 1 || o.grid > kMaxGrid)
    throw InputError(
        fmt::format("--grid {} is out of range; give 1..{} (the paper's 10 000 points: --grid 100)",
                    o.grid, kMaxGrid));
  if (o.timing_samples > kMaxTimingSamples)
    throw InputError(
        fmt::format("--timing-samples {} is too many; give at most {} (the paper "
                    "took medians of 25 000)",
                    o.timing_samples, kMaxTimingSamples));
  std::error_code ec;
  if (fs::exists(o.out, ec) && !fs::is_directory(o.out, ec))
    throw InputError(fmt::format("--out '{}' is a file; give a directory", o.out));
}

reports::SolidAngleBenchRow rowOf(const rt::SchemeMeasurement& m) {
  reports::SolidAngleBenchRow r;
  r.scheme = rt::coverageSchemeName(m.settings);
  r.size = m.settings.size;
  r.mean_abs_error = m.mean_abs_error;
  r.mean_error = m.mean_error;
  r.sd_error = m.sd_error;
  r.max_abs_error = m.max_abs_error;
  r.mean_exact = m.mean_exact;
  if (m.phase_times.empty()) return r;  // not timed
  auto summary = [&](double rt::CoveragePhaseTimes::*phase) {
    std::vector<double> samples;
    for (const rt::CoveragePhaseTimes& t : m.phase_times) samples.push_back(t.*phase);
    return metrics::summarizeTimings(samples);
  };
  r.render_ms = summary(&rt::CoveragePhaseTimes::render_ms);
  r.read_back_ms = summary(&rt::CoveragePhaseTimes::read_back_ms);
  r.weight_ms = summary(&rt::CoveragePhaseTimes::weight_ms);
  return r;
}

nlohmann::json rowJson(const reports::SolidAngleBenchRow& r) {
  auto phase = [](const metrics::TimingSummary& t) {
    return nlohmann::json{{"first_quartile_ms", t.first_quartile},
                          {"median_ms", t.median},
                          {"third_quartile_ms", t.third_quartile}};
  };
  return {{"scheme", r.scheme},
          {"size", r.size},
          {"mean_abs_error_sr", r.mean_abs_error},
          {"mean_error_sr", r.mean_error},
          {"sd_error_sr", r.sd_error},
          {"max_abs_error_sr", r.max_abs_error},
          {"mean_exact_sr", r.mean_exact},
          {"timing_samples", r.render_ms.count},
          {"render", phase(r.render_ms)},
          {"read_back", phase(r.read_back_ms)},
          {"weight", phase(r.weight_ms)}};
}

std::string perPointCsv(const scene::OccludedLightBench& bench,
                        const std::vector<rt::SchemeMeasurement>& measurements) {
  std::ostringstream csv;
  csv << "x,z";
  for (const auto& m : measurements)
    csv << "," << rt::coverageSchemeName(m.settings) << "_" << m.settings.size << "_error_sr";
  csv << "\n";
  const std::vector<glm::dvec3> points = scene::occludedLightBenchPoints(bench);
  for (std::size_t i = 0; i < points.size(); ++i) {
    csv << fmt::format("{},{}", points[i].x, points[i].z);
    for (const auto& m : measurements) csv << fmt::format(",{:.9g}", m.errors[i]);
    csv << "\n";
  }
  return csv.str();
}

int runSolidAngleBench(SolidAngleBenchOptions& o) {
  validate(o);
  const std::unique_ptr<rt::gl::Context> context = rt::gl::Context::create();
  const scene::OccludedLightBench bench = scene::occludedLightBench(o.grid);
  const std::size_t points = std::size_t(o.grid) * o.grid;
  const std::size_t per_config = std::max(points, o.timing_samples);
  ProgressBar progress("solid-angle bench", per_config * o.sizes.size() * o.schemes.size(),
                       "points");
  std::vector<rt::SchemeMeasurement> measurements;
  for (const std::string& name : o.schemes)
    for (int size : o.sizes) {
      rt::CoverageSettings s;
      rt::parseCoverageScheme(name, s);
      s.size = size;
      s.seed = o.seed;
      std::size_t reported = 0;
      measurements.push_back(rt::measureScheme(bench, s, o.timing_samples, [&](std::size_t done) {
        progress.advance(done - reported);
        reported = done;
      }));
    }
  progress.finish();

  std::vector<reports::SolidAngleBenchRow> rows;
  for (const auto& m : measurements) rows.push_back(rowOf(m));

  // Fig. 8: the error over the plane at --figure-size, each panel on its own scale (its maximum)
  // so that the structure of the smaller errors shows, as the paper's does.
  std::vector<const rt::SchemeMeasurement*> panels;
  for (const std::string& name : kFigureSchemes)
    for (const auto& m : measurements)
      if (rt::coverageSchemeName(m.settings) == name && m.settings.size == o.figure_size)
        panels.push_back(&m);

  fs::create_directories(o.out);
  std::vector<reports::SolidAngleBenchFigure> figures;
  // Each point a block of pixels, so that a 100 × 100 grid reads at the page's size.
  const int zoom = std::max(1, 400 / o.grid);
  for (const auto* m : panels) {
    image::Image map(o.grid * zoom, o.grid * zoom, 1);
    for (int y = 0; y < map.height(); ++y)
      for (int x = 0; x < map.width(); ++x)
        map.data()[std::size_t(y) * map.width() + x] =
            float(std::abs(m->errors[std::size_t(y / zoom) * o.grid + x / zoom]));
    const std::string file =
        fmt::format("error_{}_{}.png", rt::coverageSchemeName(m->settings), o.figure_size);
    image::writePng(
        fs::path(o.out) / file,
        image::falseColorWithBar(map, 0.0f, float(m->max_abs_error > 0 ? m->max_abs_error : 1)));
    figures.push_back(
        {fmt::format("{}, {}²", rt::coverageSchemeName(m->settings), o.figure_size), file});
  }

  const rt::gl::GlIdentity& gl = context->identity();
  nlohmann::json summary = {{"gibench_version", kVersion},
                            {"gl_renderer", gl.renderer},
                            {"gl_version", gl.version},
                            {"parameters",
                             {{"grid", o.grid},
                              {"points", points},
                              {"seed", o.seed},
                              {"timing_samples", o.timing_samples},
                              {"light_corners", nlohmann::json::array()},
                              {"occluder_corners", nlohmann::json::array()}}},
                            {"results", nlohmann::json::array()}};
  for (const glm::dvec3& c : bench.light)
    summary["parameters"]["light_corners"].push_back({c.x, c.y, c.z});
  for (const glm::dvec3& c : bench.occluder)
    summary["parameters"]["occluder_corners"].push_back({c.x, c.y, c.z});
  for (const auto& r : rows) summary["results"].push_back(rowJson(r));
  image::writeTextFile(fs::path(o.out) / "solid_angle_bench.json", summary.dump(2) + "\n");
  image::writeTextFile(fs::path(o.out) / "solid_angle_errors.csv",
                       perPointCsv(bench, measurements));
  const std::vector<std::pair<std::string, std::string>> facts = {
      {"gibench", kVersion},
      {"GL renderer", gl.renderer},
      {"points", fmt::format("{} × {} over [−2, 2]² of the plane y = 0", o.grid, o.grid)},
      {"jitter seed", std::to_string(o.seed)},
      {"timing samples per scheme and size", std::to_string(o.timing_samples)}};
  image::writeTextFile(fs::path(o.out) / "index.html",
                       reports::solidAngleBenchPage(facts, rows, figures));

  fmt::print("{:<16} {:>5} {:>12} {:>12} {:>12} {:>12} {:>10} {:>10} {:>10}\n", "scheme", "size",
             "mean|err|", "SD err", "max|err|", "bias", "render ms", "readback", "weight");
  for (const auto& r : rows)
    fmt::print(
        "{:<16} {:>5} {:>12.3e} {:>12.3e} {:>12.3e} {:>+12.2e} {:>10.4f} {:>10.4f} {:>10.4f}\n",
        r.scheme, r.size, r.mean_abs_error, r.sd_error, r.max_abs_error, r.mean_error,
        r.render_ms.median, r.read_back_ms.median, r.weight_ms.median);
  fmt::print("wrote {}\n", (fs::path(o.out) / "index.html").string());
  return 0;
}

}  // namespace

CommandRunner addSolidAngleBenchCommand(CLI::App& app) {
  auto o = std::make_shared<SolidAngleBenchOptions>();
  CLI::App* command = app.add_subcommand(
      "solid-angle-bench",
      "Hardware sampling of an area light against its exact visible solid angle (Fournier & "
      "Péroche §6.1, Figs. 7-9)");
  command->add_option("--out", o->out, "directory for the page, statistics and images")->required();
  command->add_option("--sizes", o->sizes, "sampling image sizes, pixels a side")
      ->delimiter(',')
      ->capture_default_str();
  command
      ->add_option("--schemes", o->schemes,
                   "occlusion_query, regular, jittered1, jittered4, jittered8")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--grid", o->grid, "points per side of the plane's grid")
      ->capture_default_str();
  command
      ->add_option("--timing-samples", o->timing_samples,
                   "points timed per scheme and size (medians, as the paper's Fig. 9)")
      ->capture_default_str();
  command->add_option("--seed", o->seed, "seed of the jittered positions")->capture_default_str();
  command
      ->add_option("--figure-size", o->figure_size,
                   "image size of the error maps (Fig. 8: regular, jittered1, jittered4)")
      ->capture_default_str();
  return [o] { return runSolidAngleBench(*o); };
}

}  // namespace gib::cli
