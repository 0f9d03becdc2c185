// The runner's contract with iterative techniques: each step() timed as one "iteration" with its
// passes, images captured on the way for convergence series, and a technique's auxiliary images
// and statistics handed back. A counting technique makes every expectation exact.
#include "realtime/technique_runner.h"

#include "common/input_error.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/render_target.h"
#include "scene/builtin_scenes.h"

#include <gtest/gtest.h>

namespace gib::rt {
namespace {

// Renders its iteration count as a grey level; each step opens two passes.
class CountingTechnique final : public Technique {
 public:
  void prepare(const GpuScene&, int, int) override {}
  void render(Frame& frame) override {
    auto scope = frame.profiler.pass("show");
    frame.target.clear(float(steps_), float(steps_), float(steps_));
  }
  bool iterative() const override { return true; }
  void step(gl::PassProfiler& profiler) override {
    { auto selection = profiler.pass("select"); }
    { auto update = profiler.pass("update"); }
    ++steps_;
  }
  int iterations() const override { return steps_; }
  scene::PathClass pathClass() const override { return {}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override {
    image::Image state(2, 1);
    state.pixel(1, 0)[0] = float(steps_);
    return {{"state", "the counter", state}};
  }
  std::vector<TechniqueStatistic> statistics() const override { return {{"passes_per_step", 2}}; }

 private:
  int steps_ = 0;
};

TechniqueInfo countingInfo() {
  TechniqueInfo info;
  info.name = "counting";
  info.description = "counts its steps";
  info.source = "a test";
  info.passes.add("frame/show", "the counter as a grey level")
      .add("iteration", "one step")
      .add("iteration/select", "the first pass of a step")
      .add("iteration/update", "the second");
  info.auxiliary_images = {{"state", "the counter"}};
  info.statistics = {{"passes_per_step", "passes each step times"}};
  info.create = [](const ParameterValues&) { return std::make_unique<CountingTechnique>(); };
  return info;
}

TechniqueRunSettings settings(int iterations, std::vector<int> capture_after) {
  TechniqueRunSettings s;
  s.width = 4;
  s.height = 3;
  s.warmup_frames = 1;
  s.frames = 2;
  s.iterations = iterations;
  s.capture_after = std::move(capture_after);
  return s;
}

TEST(TechniqueRunner, TimesEachIterationAndCapturesImagesOnTheWay) {
  const scene::Scene scene = scene::loadScene("cornell");
  const TechniqueInfo info = countingInfo();
  const ParameterValues none = parseParameters(info.parameters, {}, "technique 'counting'");
  const TechniqueRunResult r = runTechnique(scene, info, none, settings(5, {0, 2, 5}));

  EXPECT_EQ(r.iterations, 5);
  EXPECT_EQ(r.image.pixel(3, 2)[0], 5.0f);
  ASSERT_EQ(r.captures.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const int expected = std::vector<int>{0, 2, 5}[i];
    EXPECT_EQ(r.captures[i].iterations, expected);
    EXPECT_EQ(r.captures[i].image.pixel(0, 0)[1], float(expected));
  }
  EXPECT_LE(r.captures[1].iterate_ms, r.captures[2].iterate_ms);

  // Iterations are profiled apart from the frames, with the technique's pass names.
  EXPECT_EQ(r.iteration_profile.measured_frames, 5);
  ASSERT_EQ(r.iteration_profile.passes.size(), 3u);
  EXPECT_EQ(r.iteration_profile.passes[0].name, "iteration");
  EXPECT_EQ(r.iteration_profile.passes[1].path, "iteration/select");
  EXPECT_EQ(r.iteration_profile.passes[2].path, "iteration/update");
  EXPECT_EQ(r.iteration_profile.reported(r.iteration_profile.passes[2]).size(), 5u);
  // The captures' frames are not timed: only the two measured frames are.
  EXPECT_EQ(r.profile.measured_frames, 2);
  ASSERT_EQ(r.profile.passes.size(), 2u);
  EXPECT_EQ(r.profile.passes[1].path, "frame/show");

  ASSERT_EQ(r.auxiliary.size(), 1u);
  EXPECT_EQ(r.auxiliary[0].name, "state");
  EXPECT_EQ(r.auxiliary[0].image.pixel(1, 0)[0], 5.0f);  // after the last step
  ASSERT_EQ(r.statistics.size(), 1u);
  EXPECT_EQ(r.statistics[0].value, 2);
}

// A pass the technique does not declare would be one that no suite can name and no README lists.
TEST(TechniqueRunner, RefusesAProfileWithAnUndeclaredPass) {
  const scene::Scene scene = scene::loadScene("cornell");
  TechniqueInfo info = countingInfo();
  info.passes = PassDeclarations();
  info.passes.add("frame/show", "declared").add("iteration", "declared");
  info.passes.add("iteration/select", "declared");  // but not iteration/update
  const ParameterValues none = parseParameters(info.parameters, {}, "technique 'counting'");
  try {
    runTechnique(scene, info, none, settings(1, {}));
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("'iteration/update'"), std::string::npos) << e.what();
  }
}

TEST(TechniqueRunner, RefusesCapturesBeyondOrOutOfOrder) {
  const scene::Scene scene = scene::loadScene("cornell");
  const TechniqueInfo info = countingInfo();
  const ParameterValues none = parseParameters(info.parameters, {}, "technique 'counting'");
  EXPECT_THROW(runTechnique(scene, info, none, settings(3, {1, 4})), InputError);
  EXPECT_THROW(runTechnique(scene, info, none, settings(8, {4, 2})), InputError);
}

}  // namespace
}  // namespace gib::rt
