// The catalogue and what each technique declares besides its passes: a folder under
// realtime/techniques/ is a technique in the catalogue and back, a declared output family matches
// its members only, needs are checked against the scene and the services, and the runner refuses
// a technique that writes an image or a statistic it did not declare.
#include "realtime/technique.h"

#include "common/input_error.h"
#include "realtime/technique_runner.h"
#include "scene/builtin_scenes.h"
#include "support/technique_frame.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

namespace gib::rt {
namespace {

using ::testing::HasSubstr;

TEST(TechniqueCatalogue, EveryTechniqueFolderIsACatalogueEntryAndBack) {
  std::set<std::string> folders, entries;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(GIB_SOURCE_DIR) / "realtime" / "techniques")) {
    if (!entry.is_directory()) continue;
    folders.insert(entry.path().filename().string());
    EXPECT_TRUE(std::filesystem::exists(entry.path() / "README.md")) << entry.path();
  }
  for (const TechniqueInfo& info : techniqueCatalogue()) {
    EXPECT_TRUE(entries.insert(info.name).second) << info.name << " is in the catalogue twice";
    EXPECT_FALSE(info.description.empty()) << info.name;
    EXPECT_FALSE(info.source.empty()) << info.name;
  }
  EXPECT_EQ(folders, entries) << "realtime/technique.cpp lists one technique per folder of "
                                 "realtime/techniques/ (scripts/new-technique.py adds both)";
}

TEST(TechniqueCatalogue, EveryDeclaredOutputHasANameAndADescriptionOnce) {
  for (const TechniqueInfo& info : techniqueCatalogue())
    for (const auto* declared : {&info.auxiliary_images, &info.statistics}) {
      std::set<std::string> names;
      for (const DeclaredOutput& output : *declared) {
        EXPECT_TRUE(names.insert(output.name).second) << info.name << ": " << output.name;
        EXPECT_FALSE(output.description.empty()) << info.name << ": " << output.name;
      }
    }
}

// A parameter declared twice would take the first declaration's default and range while the
// second's showed in the docs.
TEST(TechniqueCatalogue, EveryTechniqueDeclaresEachParameterOnce) {
  for (const TechniqueInfo& info : techniqueCatalogue()) {
    std::set<std::string> names;
    for (const ParameterSpec& spec : info.parameters)
      EXPECT_TRUE(names.insert(spec.name).second) << info.name << ": " << spec.name;
  }
}

TEST(DeclaredOutputs, AFamilyMatchesItsNumberedMembersOnly) {
  const std::vector<DeclaredOutput> declared = {{"indirect-<n>", "bounce n"},
                                                {"atlas", "the atlas"}};
  EXPECT_EQ(findDeclaredOutput(declared, "atlas"), &declared[1]);
  EXPECT_EQ(findDeclaredOutput(declared, "indirect-1"), &declared[0]);
  EXPECT_EQ(findDeclaredOutput(declared, "indirect-12"), &declared[0]);
  for (const char* name : {"indirect", "indirect-", "indirect-0", "indirect-x", "indirect-1a",
                           "atlas2", "indirect-<n>x"})
    EXPECT_EQ(findDeclaredOutput(declared, name), nullptr) << name;
}

TechniqueInfo infoNeeding(std::vector<TechniqueNeed> needs) {
  TechniqueInfo info;
  info.name = "needy";
  info.needs = std::move(needs);
  return info;
}

TEST(TechniqueNeeds, EachNeedIsCheckedAgainstTheSceneOrTheServices) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const scene::Scene cloud = scene::loadScene("cloud");
  const scene::Scene cloud_without_sky = scene::loadScene("cloud", {"sky=false"});
  const TechniqueInfo medium = infoNeeding({TechniqueNeed::kMedium});
  EXPECT_THAT(missingSceneNeed(medium, cornell).value_or(""),
              HasSubstr("renders a participating medium and scene 'cornell' has none"));
  EXPECT_FALSE(missingSceneNeed(medium, cloud));
  const TechniqueInfo sky = infoNeeding({TechniqueNeed::kEnvironmentLight});
  EXPECT_FALSE(missingSceneNeed(sky, cloud));
  EXPECT_THAT(missingSceneNeed(sky, cloud_without_sky).value_or(""), HasSubstr("has no sky"));
  const TechniqueInfo specular = infoNeeding({TechniqueNeed::kSpecularMaterials});
  EXPECT_THAT(missingSceneNeed(specular, cornell).value_or(""), HasSubstr("no such material"));

  const TechniqueInfo rays = infoNeeding({TechniqueNeed::kRayCaster});
  EXPECT_FALSE(missingSceneNeed(rays, cornell)) << "the ray caster is not the scene's";
  EXPECT_FALSE(needsSceneFeatures(rays));
  EXPECT_TRUE(needsSceneFeatures(medium));
  EXPECT_THAT(missingNeed(rays, cornell, {}).value_or(""), HasSubstr("did not lend"));
  TechniqueServices lent;
  lent.ray_caster = [](const scene::Scene&) -> std::unique_ptr<scene::RayCaster> {
    return nullptr;
  };
  EXPECT_FALSE(missingNeed(rays, cornell, lent));
}

// A scene with a mirror or glass on a mesh (Scene::hasIdealSpecular) is refused to every technique
// that does not declare kSpecularMaterials, and given to one that does; a specular material no
// mesh uses changes nothing.
TEST(TechniqueNeeds, OnlyTechniquesThatRenderMirrorsOrGlassAcceptThem) {
  for (const scene::MaterialType type :
       {scene::MaterialType::kMirror, scene::MaterialType::kGlass}) {
    scene::Scene s = scene::loadScene("cornell");
    scene::Material specular;
    specular.name = "specular";
    specular.type = type;
    specular.perfect_mirror = true;
    s.materials.push_back(specular);
    const TechniqueInfo plain = infoNeeding({});
    const TechniqueInfo renders_specular = infoNeeding({TechniqueNeed::kSpecularMaterials});
    EXPECT_FALSE(missingSceneNeed(plain, s)) << "no mesh is specular yet";
    s.meshes.front().material = std::uint32_t(s.materials.size() - 1);
    ASSERT_TRUE(s.hasIdealSpecular());
    EXPECT_THAT(missingSceneNeed(plain, s).value_or(""),
                HasSubstr("does not render ideal mirrors or glass and scene 'cornell' has them"));
    EXPECT_FALSE(missingSceneNeed(renders_specular, s));
    TechniqueInfo renders_without_needing = plain;
    renders_without_needing.renders_specular_materials = true;
    EXPECT_FALSE(missingSceneNeed(renders_without_needing, s));
    s.meshes.front().material = 0;
    EXPECT_FALSE(missingSceneNeed(renders_without_needing, s)) << "and needs none";
    EXPECT_TRUE(missingSceneNeed(renders_specular, s)) << "needs one";
    s.meshes.front().material = std::uint32_t(s.materials.size() - 1);
    for (const TechniqueInfo& info : techniqueCatalogue()) {
      if (!info.rendersSpecularMaterials()) {
        EXPECT_TRUE(missingSceneNeed(info, s)) << info.name;
      }
    }
  }
}

// A technique that draws nothing and reports what it is told to: the runner must refuse an image
// or a statistic that its info does not declare.
class ReportingTechnique final : public Technique {
 public:
  ReportingTechnique(std::string image, std::string statistic)
      : image_(std::move(image)), statistic_(std::move(statistic)) {}
  void prepare(const GpuScene&, int, int) override {}
  void render(Frame&) override {}
  scene::PathClass pathClass() const override { return {0, 1}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override {
    return {{image_, "an image", image::Image(2, 2, 3)}};
  }
  std::vector<TechniqueStatistic> statistics() const override { return {{statistic_, 1.0}}; }

 private:
  std::string image_, statistic_;
};

TechniqueInfo reportingInfo(std::string image, std::string statistic) {
  TechniqueInfo info;
  info.name = "reporting";
  info.auxiliary_images = {{"bounce-<n>", "a bounce"}};
  info.statistics = {{"points", "points"}};
  info.create = [image, statistic](const ParameterValues&) -> std::unique_ptr<Technique> {
    return std::make_unique<ReportingTechnique>(image, statistic);
  };
  return info;
}

std::string runErrorOf(const TechniqueInfo& info) {
  TechniqueRunSettings settings;
  settings.width = settings.height = 4;
  settings.warmup_frames = 0;
  settings.frames = 1;
  try {
    runTechnique(test::floorScene(), info, parseParameters({}, {}, "reporting"), settings);
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST(TechniqueRunner, RefusesAnImageOrAStatisticTheTechniqueDoesNotDeclare) {
  EXPECT_EQ(runErrorOf(reportingInfo("bounce-2", "points")), "");
  EXPECT_THAT(runErrorOf(reportingInfo("bounce-2", "pionts")),
              HasSubstr("wrote the statistic 'pionts', which its TechniqueInfo::statistics does "
                        "not declare"));
  EXPECT_THAT(runErrorOf(reportingInfo("bounces", "points")),
              HasSubstr("wrote the auxiliary image 'bounces'"));
}

TEST(TechniqueRunner, RefusesAJobWhoseSceneLacksANeedBeforeMakingTheTechnique) {
  TechniqueInfo info = reportingInfo("bounce-1", "points");
  info.needs = {TechniqueNeed::kMedium};
  bool made = false;
  info.create = [&made](const ParameterValues&) -> std::unique_ptr<Technique> {
    made = true;
    return std::make_unique<ReportingTechnique>("bounce-1", "points");
  };
  TechniqueRunSettings settings;
  settings.width = settings.height = 4;
  EXPECT_THROW(runTechnique(test::floorScene(), info, parseParameters({}, {}, "x"), settings),
               InputError);
  EXPECT_FALSE(made);
}

}  // namespace
}  // namespace gib::rt
