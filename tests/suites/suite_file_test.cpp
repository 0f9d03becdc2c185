#include "suites/suite_file.h"

#include "common/input_error.h"
#include "metrics/metric_registry.h"
#include "realtime/technique.h"
#include "scene/builtin_scenes.h"
#include "scene/path_class.h"
#include "suites/job_expansion.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

namespace gib::suites {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr const char* kSuite = R"(name = "unit"
description = "a suite for the tests"

[defaults]
width = 64
height = 48
metrics = ["flip", "relmse"]
frames = 5
warmup = 1

[defaults.reference]
spp = 256
seed = 7

[[case]]
scene = "cornell"
technique = "reference"
checkpoints = [4, 16, 64]

[[case]]
name = "direct-sweep"
scene = "cornell"
technique = "direct"
set = { shadow = ["hard", "pcf"], light_samples = 4.0, normal_offset = 1.50 }
width = 32
height = 32
metrics = "all"
[case.reference]
spp = 512
max_bounces = "unlimited"
)";

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// The 1-based line of the first occurrence of `needle` in `text`.
int lineOf(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class SuiteFileTest : public ::testing::Test {
 protected:
  std::filesystem::path suitePath() const { return dir_ / "suite.toml"; }

  Suite load(const std::string& text) const {
    writeFile(suitePath(), text);
    return loadSuiteFile(suitePath());
  }

  // The message of the InputError that loading `text` throws ("" if none is thrown).
  std::string errorOf(const std::string& text) const {
    try {
      load(text);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return "";
  }

  // Expects one line "<file>:<line of needle>:<column>: …; …" and returns it.
  std::string expectErrorAt(const std::string& text, const std::string& needle) const {
    const std::string message = errorOf(text);
    EXPECT_THAT(message,
                StartsWith(suitePath().string() + ":" + std::to_string(lineOf(text, needle)) + ":"))
        << text;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    EXPECT_THAT(message, HasSubstr("; ")) << "names a fix: " << message;
    return message;
  }

  test::TempDir dir_;
};

TEST_F(SuiteFileTest, CasesInheritTheDefaults) {
  const Suite suite = load(kSuite);
  EXPECT_EQ(suite.name, "unit");
  EXPECT_EQ(suite.description, "a suite for the tests");
  EXPECT_EQ(suite.file, std::filesystem::absolute(suitePath()).lexically_normal());
  ASSERT_EQ(suite.cases.size(), 2u);

  const Case& reference = suite.cases[0];
  EXPECT_EQ(reference.name, "cornell-reference");  // the default name
  EXPECT_EQ(reference.line, lineOf(kSuite, "[[case]]"));
  EXPECT_TRUE(reference.scene.builtin());
  EXPECT_EQ(reference.scene.name, "cornell");
  EXPECT_EQ(reference.scene.nameOrPath(), "cornell");
  EXPECT_EQ(reference.technique, kReferenceTechnique);
  EXPECT_EQ(reference.settings.width, 64);
  EXPECT_EQ(reference.settings.height, 48);
  EXPECT_EQ(reference.settings.frames, 5);
  EXPECT_EQ(reference.settings.warmup, 1);
  EXPECT_THAT(reference.settings.metrics, ElementsAre("relmse", "flip"));  // catalogue order
  EXPECT_EQ(reference.settings.reference.spp, 256);
  EXPECT_EQ(reference.settings.reference.seed, 7u);
  EXPECT_FALSE(reference.settings.reference.min_bounces.has_value());
  EXPECT_FALSE(reference.settings.reference.max_bounces.has_value());
  EXPECT_THAT(reference.settings.checkpoints, ElementsAre(4, 16, 64));
  EXPECT_TRUE(reference.technique_parameters.empty());
}

TEST_F(SuiteFileTest, CasesOverrideTheDefaultsKeyByKey) {
  const Suite suite = load(kSuite);
  const Case& direct = suite.cases[1];
  EXPECT_EQ(direct.name, "direct-sweep");
  EXPECT_EQ(direct.technique, "direct");
  EXPECT_EQ(direct.settings.width, 32);
  EXPECT_EQ(direct.settings.height, 32);
  EXPECT_EQ(direct.settings.frames, 5);
  EXPECT_EQ(direct.settings.metrics, metrics::parseMetricList("all"));
  EXPECT_EQ(direct.settings.reference.spp, 512);
  EXPECT_EQ(direct.settings.reference.seed, 7u);  // from [defaults.reference]
  EXPECT_EQ(direct.settings.reference.max_bounces, scene::PathClass::kUnlimited);
  EXPECT_TRUE(direct.settings.checkpoints.empty());
}

TEST_F(SuiteFileTest, ParameterValuesAreCanonicalAndInFileOrder) {
  const Suite suite = load(kSuite);
  const std::vector<Sweep>& set = suite.cases[1].technique_parameters;
  ASSERT_EQ(set.size(), 3u);
  // toml++ sorts keys; the suite keeps the order of the file.
  EXPECT_EQ(set[0].key, "shadow");
  EXPECT_TRUE(set[0].swept);
  EXPECT_THAT(set[0].values, ElementsAre("hard", "pcf"));
  EXPECT_EQ(set[1].key, "light_samples");
  EXPECT_FALSE(set[1].swept);
  EXPECT_THAT(set[1].values, ElementsAre("4"));  // written 4.0
  EXPECT_EQ(set[2].key, "normal_offset");
  EXPECT_THAT(set[2].values, ElementsAre("1.5"));  // written 1.50
}

TEST_F(SuiteFileTest, WithoutDefaultsTheBuiltInDefaultsApply) {
  const Suite suite =
      load("name = \"bare\"\n[[case]]\nscene = \"furnace\"\ntechnique = \"direct\"\n");
  ASSERT_EQ(suite.cases.size(), 1u);
  const Case& c = suite.cases[0];
  EXPECT_EQ(c.name, "furnace-direct");
  EXPECT_FALSE(c.settings.width.has_value());  // the scene's own size
  EXPECT_FALSE(c.settings.height.has_value());
  EXPECT_EQ(c.settings.frames, 8);
  EXPECT_EQ(c.settings.warmup, 2);
  EXPECT_EQ(c.settings.metrics, metrics::parseMetricList("all"));
  EXPECT_EQ(c.settings.reference, ReferenceSettings{});
  EXPECT_TRUE(c.technique_parameters.empty());
}

TEST_F(SuiteFileTest, SceneParametersIncludingVectors) {
  const Suite suite = load(R"(name = "vectors"
[[case]]
scene = "chamber"
scene_set = { detail = [1, 2], light_target = [-1, 0, 5], light_position = ["0,4,3", [1.0, 4, 3]] }
technique = "direct"
[case.reference]
min_bounces = 1
max_bounces = 1
)");
  const Case& c = suite.cases[0];
  ASSERT_EQ(c.scene_parameters.size(), 3u);
  EXPECT_EQ(c.scene_parameters[0].key, "detail");
  EXPECT_THAT(c.scene_parameters[0].values, ElementsAre("1", "2"));
  EXPECT_EQ(c.scene_parameters[1].key, "light_target");
  EXPECT_FALSE(c.scene_parameters[1].swept);  // three numbers are one vector, not a sweep
  EXPECT_THAT(c.scene_parameters[1].values, ElementsAre("-1,0,5"));
  EXPECT_EQ(c.scene_parameters[2].key, "light_position");
  EXPECT_TRUE(c.scene_parameters[2].swept);
  EXPECT_THAT(c.scene_parameters[2].values, ElementsAre("0,4,3", "1,4,3"));
  EXPECT_EQ(c.settings.reference.min_bounces, 1);
  EXPECT_EQ(c.settings.reference.max_bounces, 1);
}

TEST_F(SuiteFileTest, ReferenceWithoutTheEnvironmentsOcclusion) {
  const Suite suite = load(R"(name = "unoccluded"
[[case]]
scene = "outdoor"
technique = "environment_map"
reference = { spp = 16, environment_occlusion = false }
[[case]]
name = "occluded"
scene = "outdoor"
technique = "environment_map"
)");
  EXPECT_FALSE(suite.cases[0].settings.reference.environment_occlusion);
  EXPECT_TRUE(suite.cases[1].settings.reference.environment_occlusion);
  EXPECT_THAT(expectErrorAt(R"(name = "bad"
[[case]]
scene = "outdoor"
technique = "environment_map"
reference = { environment_occlusion = "off" }
)",
                            "environment_occlusion"),
              HasSubstr("environment_occlusion"));
}

// `lens = { radius, focus_distance }` in [defaults] or a case: the thin lens over the scene's
// camera, each key over the defaults'; a negative radius or a focus distance <= 0 is refused
// where it is written.
TEST_F(SuiteFileTest, LensInTheDefaultsAndACase) {
  const Suite suite = load(R"(name = "lens"
[defaults]
lens = { radius = 0.05, focus_distance = 4.0 }
[[case]]
scene = "cornell"
technique = "direct"
[[case]]
name = "closer"
scene = "cornell"
technique = "direct"
lens = { focus_distance = 2.0 }
)");
  EXPECT_EQ(suite.cases[0].settings.lens.radius, 0.05);
  EXPECT_EQ(suite.cases[0].settings.lens.focus_distance, 4.0);
  EXPECT_EQ(suite.cases[1].settings.lens.radius, 0.05);
  EXPECT_EQ(suite.cases[1].settings.lens.focus_distance, 2.0);
  EXPECT_THAT(expectErrorAt(R"(name = "bad"
[[case]]
scene = "cornell"
technique = "direct"
lens = { radius = -1.0 }
)",
                            "lens ="),
              HasSubstr("lens.radius -1 is not a lens radius"));
  EXPECT_THAT(expectErrorAt(R"(name = "bad"
[[case]]
scene = "cornell"
technique = "direct"
lens = { radius = 1.0, focus_distance = 0.0 }
)",
                            "lens ="),
              HasSubstr("focus_distance 0 is not a distance"));
}

TEST_F(SuiteFileTest, RelativeScenePathsStartAtTheSuiteFilesFolder) {
  writeFile(dir_ / "scenes" / "room.toml", "# not read while parsing the suite\n");
  writeFile(dir_ / "sub" / "suite.toml", R"(name = "files"
[[case]]
scene = "../scenes/room.toml"
technique = "direct"
)");
  const Suite suite = loadSuiteFile(dir_ / "sub" / "suite.toml");
  const SceneSpec& scene = suite.cases[0].scene;
  EXPECT_FALSE(scene.builtin());
  EXPECT_EQ(scene.file,
            std::filesystem::absolute(dir_ / "scenes" / "room.toml").lexically_normal());
  EXPECT_EQ(scene.nameOrPath(), scene.file.string());
  EXPECT_EQ(scene.name, "room");
  EXPECT_EQ(suite.cases[0].name, "room-direct");
}

TEST_F(SuiteFileTest, MissingFile) {
  try {
    loadSuiteFile(dir_ / "nowhere.toml");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir_ / "nowhere.toml").string() + ": suite file not found; check the path");
  }
}

TEST_F(SuiteFileTest, MalformedToml) {
  const std::string text = replaced(kSuite, "frames = 5", "frames = = 5");
  EXPECT_THAT(expectErrorAt(text, "frames = = 5"), HasSubstr("invalid TOML"));
}

TEST_F(SuiteFileTest, UnknownKeysListTheAllowedOnes) {
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "description =", "descripton ="), "descripton"),
              HasSubstr("unknown key 'descripton' in the top level of the suite file; allowed "
                        "keys: name, description, defaults, case"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "warmup = 1", "warm_up = 1"), "warm_up"),
              HasSubstr("unknown key 'warm_up' in [defaults]"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "seed = 7", "sed = 7"), "sed = 7"),
              HasSubstr("unknown key 'sed' in [defaults.reference]; allowed keys: spp, seed, "
                        "min_bounces, max_bounces"));
  EXPECT_THAT(
      expectErrorAt(replaced(kSuite, "checkpoints = [4", "checkpoint = [4"), "checkpoint = [4"),
      HasSubstr("unknown key 'checkpoint' in [[case]] entry 1; allowed keys: name, scene, "
                "scene_set, technique, set, checkpoints, iterations, width"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "[[case]]", "[[cases]]"), "[[cases]]"),
              HasSubstr("unknown key 'cases'"));
}

TEST_F(SuiteFileTest, UnknownSceneListsTheBuiltInScenes) {
  const std::string text = replaced(kSuite, "scene = \"cornell\"", "scene = \"cornel\"");
  EXPECT_THAT(expectErrorAt(text, "scene = \"cornel\""),
              HasSubstr("unknown scene 'cornel'; use a built-in scene (cornell, furnace, chamber, "
                        "cloud"));
}

TEST_F(SuiteFileTest, MissingSceneFile) {
  const std::string text = replaced(kSuite, "scene = \"cornell\"", "scene = \"rooms/room.toml\"");
  const std::string message = expectErrorAt(text, "rooms/room.toml");
  EXPECT_THAT(message, HasSubstr((dir_ / "rooms" / "room.toml").string() + "' not found"));
  EXPECT_THAT(message, HasSubstr("suite file's folder"));
}

TEST_F(SuiteFileTest, UnknownTechniqueListsTheCatalogue) {
  const std::string text = replaced(kSuite, "technique = \"direct\"", "technique = \"drect\"");
  EXPECT_THAT(expectErrorAt(text, "technique = \"drect\""),
              HasSubstr("unknown technique 'drect'; available: reference, direct"));
}

TEST_F(SuiteFileTest, UnknownTechniqueParameterListsTheKnownOnes) {
  const std::string text = replaced(kSuite, "normal_offset = 1.50", "normal_ofset = 1.50");
  EXPECT_THAT(expectErrorAt(text, "normal_ofset"),
              HasSubstr("technique 'direct' has no parameter 'normal_ofset'; its parameters are "
                        "shadow, shadow_map_size"));
}

TEST_F(SuiteFileTest, ParameterValuesAreCheckedOneByOne) {
  // The position is that of the offending value, also inside a sweep spread over lines.
  const std::string sweep =
      replaced(kSuite, "shadow = [\"hard\", \"pcf\"]", "shadow = [\n  \"hard\",\n  \"soft\",\n]");
  EXPECT_THAT(expectErrorAt(sweep, "\"soft\""),
              HasSubstr("technique 'direct' parameter 'shadow' = 'soft' is not one of the "
                        "choices; give a choice in hard|pcf|vsm"));
  const std::string range = replaced(kSuite, "light_samples = 4.0", "light_samples = 0");
  EXPECT_THAT(expectErrorAt(range, "light_samples = 0"), HasSubstr("is out of range"));
  const std::string fraction = replaced(kSuite, "light_samples = 4.0", "light_samples = 4.5");
  EXPECT_THAT(expectErrorAt(fraction, "light_samples = 4.5"), HasSubstr("is not an integer"));
  const std::string table = replaced(kSuite, "light_samples = 4.0", "light_samples = { n = 4 }");
  EXPECT_THAT(expectErrorAt(table, "light_samples ="),
              HasSubstr("set.light_samples must be a string or a finite number"));
}

TEST_F(SuiteFileTest, SceneParametersAreChecked) {
  const std::string none = replaced(kSuite, "technique = \"reference\"",
                                    "technique = \"reference\"\nscene_set = { detail = 2 }");
  EXPECT_THAT(expectErrorAt(none, "detail = 2"),
              HasSubstr("scene 'cornell' has no parameter 'detail'; its parameters are blocks"));
  const std::string chamber = replaced(
      replaced(kSuite, "scene = \"cornell\"", "scene = \"chamber\""), "technique = \"reference\"",
      "technique = \"reference\"\nscene_set = { detail = 9 }");
  EXPECT_THAT(expectErrorAt(chamber, "detail = 9"),
              HasSubstr("scene 'chamber' parameter 'detail' = '9' is out of range"));
  const std::string vector = replaced(chamber, "detail = 9", "light_target = [1, 2]");
  EXPECT_THAT(expectErrorAt(vector, "light_target"),
              HasSubstr("case.scene_set.light_target must be [x, y, z] or \"x,y,z\""));
  const std::string text = replaced(chamber, "detail = 9", "light_target = \"1,2\"");
  EXPECT_THAT(expectErrorAt(text, "light_target"), HasSubstr("does not have three components"));
  const std::string range =
      replaced(chamber, "detail = 9", "light_target = [[0, 0, 1], [0, 0, 1e9]]");
  EXPECT_THAT(expectErrorAt(range, "light_target"), HasSubstr("has a component out of range"));
}

TEST_F(SuiteFileTest, SweepsMustListDistinctValues) {
  const std::string empty = replaced(kSuite, "shadow = [\"hard\", \"pcf\"]", "shadow = []");
  EXPECT_THAT(expectErrorAt(empty, "shadow = []"),
              HasSubstr("set.shadow is an empty sweep; list at least one value"));
  const std::string twice = replaced(kSuite, "light_samples = 4.0", "light_samples = [4, 4.0]");
  EXPECT_THAT(expectErrorAt(twice, "light_samples = [4, 4.0]"),
              HasSubstr("set.light_samples lists the value 4 twice"));
}

TEST_F(SuiteFileTest, HugeSweepsAreRefused) {
  std::string values;
  for (int i = 1; i <= 4096; ++i) {
    if (i > 1) values += ',';
    values += std::to_string(i);
  }
  const std::string text =
      replaced(replaced(kSuite, "light_samples = 4.0", "light_samples = [" + values + "]"),
               "\"pcf\"]", "\"pcf\", \"vsm\"]");
  // Reported at the case's [[case]] line, the one before its name.
  const std::string message = errorOf(text);
  EXPECT_THAT(message,
              StartsWith(suitePath().string() + ":" +
                         std::to_string(lineOf(text, "name = \"direct-sweep\"") - 1) + ":"));
  EXPECT_THAT(message, HasSubstr("case 'direct-sweep' expands into 12288 jobs, more than 10000"));
}

TEST_F(SuiteFileTest, UnknownMetricListsTheKnownOnes) {
  const std::string text =
      replaced(kSuite, "metrics = [\"flip\", \"relmse\"]", "metrics = [\"flip\", \"relmsee\"]");
  const std::string message = expectErrorAt(text, "metrics = [");
  EXPECT_THAT(message, HasSubstr("unknown metric 'relmsee'; choose 'all' or a comma-separated "
                                 "list of: mse"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "metrics = \"all\"", "metrics = []"), "metrics = []"),
              HasSubstr("case.metrics must not be empty"));
  EXPECT_THAT(load(replaced(kSuite, "metrics = \"all\"", "metrics = \"ssim,mse\""))
                  .cases[1]
                  .settings.metrics,
              ElementsAre("mse", "ssim"));
}

TEST_F(SuiteFileTest, SizesAndCountsMustBePositive) {
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "width = 64", "width = 0"), "width = 0"),
              HasSubstr("defaults.width must be an integer in [1, 32768]"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "height = 32", "height = -32"), "height = -32"),
              HasSubstr("case.height must be an integer in [1, 32768]"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "width = 32", "width = 32.0"), "width = 32.0"),
              HasSubstr("case.width must be an integer"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "frames = 5", "frames = 0"), "frames = 0"),
              HasSubstr("defaults.frames must be an integer in [1, "));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "warmup = 1", "warmup = -1"), "warmup = -1"),
              HasSubstr("defaults.warmup must be an integer in [0, "));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "spp = 256", "spp = 0"), "spp = 0"),
              HasSubstr("defaults.reference.spp must be an integer in [1, "));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "spp = 512", "spp = \"many\""), "spp = \"many\""),
              HasSubstr("case.reference.spp must be an integer"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "seed = 7", "seed = -7"), "seed = -7"),
              HasSubstr("defaults.reference.seed must be an integer in [0, "));
}

TEST_F(SuiteFileTest, WidthNeedsHeight) {
  // Reported where the lone width is given, here in [defaults].
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "height = 48\n", ""), "width = 64"),
              HasSubstr("width is given without height; give both width and height"));
  // A case may override one of the two.
  const Suite suite = load(replaced(kSuite, "width = 32\n", ""));
  EXPECT_EQ(suite.cases[1].settings.width, 64);
  EXPECT_EQ(suite.cases[1].settings.height, 32);
}

TEST_F(SuiteFileTest, BounceLimits) {
  const std::string text =
      replaced(kSuite, "max_bounces = \"unlimited\"", "min_bounces = 2\nmax_bounces = 1");
  EXPECT_THAT(expectErrorAt(text, "min_bounces = 2"),
              HasSubstr("reference min_bounces 2 is above max_bounces 1"));
  const std::string word = replaced(kSuite, "max_bounces = \"unlimited\"", "max_bounces = \"all\"");
  EXPECT_THAT(expectErrorAt(word, "max_bounces = \"all\""),
              HasSubstr("case.reference.max_bounces must be an integer in [0, 1000000] or "
                        "\"unlimited\""));
}

TEST_F(SuiteFileTest, PathExpressionClasses) {
  const Suite suite = load(replaced(kSuite, "max_bounces = \"unlimited\"", "paths = \"L S+ D E\""));
  EXPECT_EQ(suite.cases[1].settings.reference.paths, "LS+DE");  // as PathExpression::text()
  EXPECT_FALSE(suite.cases[1].settings.reference.max_bounces.has_value());
  EXPECT_FALSE(suite.cases[0].settings.reference.paths.has_value());

  const std::string syntax = replaced(kSuite, "max_bounces = \"unlimited\"", "paths = \"L(D\"");
  EXPECT_THAT(expectErrorAt(syntax, "paths = \"L(D\""),
              HasSubstr("case.reference.paths: path expression 'L(D': column 2: '(' is not "
                        "closed; add ')'"));
  const std::string none = replaced(kSuite, "max_bounces = \"unlimited\"", "paths = \"DE\"");
  EXPECT_THAT(expectErrorAt(none, "paths = \"DE\""), HasSubstr("matches no light path"));
  // The bounces are its shorthand: one or the other, also across [defaults] and a case.
  const std::string both =
      replaced(kSuite, "max_bounces = \"unlimited\"", "max_bounces = 1\npaths = \"LDE\"");
  EXPECT_THAT(expectErrorAt(both, "paths = \"LDE\""),
              HasSubstr("reference paths and max_bounces both choose the path class; give one"));
  const std::string inherited = replaced(replaced(kSuite, "seed = 7", "seed = 7\nmin_bounces = 1"),
                                         "max_bounces = \"unlimited\"", "paths = \"LDE\"");
  EXPECT_THAT(expectErrorAt(inherited, "paths = \"LDE\""),
              HasSubstr("reference paths and min_bounces both choose the path class"));
}

TEST_F(SuiteFileTest, DuplicateCaseNames) {
  const std::string text =
      replaced(kSuite, "name = \"direct-sweep\"", "name = \"cornell-reference\"");
  EXPECT_THAT(expectErrorAt(text, "name = \"cornell-reference\""),
              HasSubstr("case name 'cornell-reference' is also the name of the case at line 15; "
                        "give each case its own name"));
  // Two cases that take the default name: at the second one's [[case]] line, after kSuite.
  const std::string defaults =
      std::string(kSuite) + "[[case]]\nscene = \"cornell\"\ntechnique = \"reference\"\n";
  const std::string message = errorOf(defaults);
  EXPECT_THAT(message, StartsWith(suitePath().string() + ":" +
                                  std::to_string(lineOf(kSuite, "max_bounces") + 1) + ":"));
  EXPECT_THAT(message, HasSubstr("is also the name of the case at line 15; give the case a name"));
}

TEST_F(SuiteFileTest, BadNames) {
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "name = \"unit\"", "name = \"my suite\""), "my suite"),
              HasSubstr("suite name 'my suite' has characters other than letters"));
  EXPECT_THAT(
      expectErrorAt(replaced(kSuite, "name = \"direct-sweep\"", "name = \"a/b\""), "\"a/b\""),
      HasSubstr("case name 'a/b' has characters other than letters"));
}

TEST_F(SuiteFileTest, MissingKeysPointAtTheirTable) {
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "name = \"unit\"\n", ""), "description"),
              HasSubstr("missing key 'name'; add name = \"smoke\" to the top level"));
  const std::string no_scene = replaced(kSuite, "scene = \"cornell\"\ntechnique = \"reference\"",
                                        "technique = \"reference\"");
  EXPECT_THAT(expectErrorAt(no_scene, "[[case]]"),
              HasSubstr("missing key 'case.scene'; add scene = \"cornell\" to [[case]] entry 1"));
  const std::string no_technique = replaced(kSuite, "technique = \"reference\"\n", "");
  EXPECT_THAT(expectErrorAt(no_technique, "[[case]]"), HasSubstr("missing key 'case.technique'"));
}

TEST_F(SuiteFileTest, ASuiteNeedsCases) {
  const std::string text = "name = \"empty\"\n[defaults]\nframes = 3\n";
  EXPECT_THAT(expectErrorAt(text, "name"), HasSubstr("the suite has no cases; add a [[case]]"));
  EXPECT_THAT(expectErrorAt("name = \"x\"\n[case]\nscene = \"cornell\"\n", "[case]"),
              HasSubstr("case must be an array of tables; write each entry as a [[case]] table"));
}

TEST_F(SuiteFileTest, WhatAReferenceCaseCannotTake) {
  const std::string set = replaced(kSuite, "technique = \"reference\"",
                                   "technique = \"reference\"\nset = { shadow = \"pcf\" }");
  EXPECT_THAT(expectErrorAt(set, "set = { shadow"), HasSubstr("a reference case takes no set"));
  const std::string checkpoints = replaced(kSuite, "[4, 16, 64]", "[4, 16, 64, 512]");
  EXPECT_THAT(expectErrorAt(checkpoints, "[4, 16, 64, 512]"),
              HasSubstr("checkpoint 512 is above the reference's 256 spp"));
}

TEST_F(SuiteFileTest, CheckpointsIncrease) {
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "[4, 16, 64]", "[4, 4]"), "[4, 4]"),
              HasSubstr("case.checkpoints must be strictly increasing"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "[4, 16, 64]", "[0, 4]"), "[0, 4]"),
              HasSubstr("case.checkpoints must hold positive integers"));
  EXPECT_THAT(expectErrorAt(replaced(kSuite, "[4, 16, 64]", "[]"), "checkpoints = []"),
              HasSubstr("case.checkpoints must be a non-empty array"));
}

TEST_F(SuiteFileTest, SceneFileTakesNoSceneSet) {
  writeFile(dir_ / "room.toml", "");
  const std::string text =
      replaced(kSuite, "scene = \"cornell\"\ntechnique = \"reference\"",
               "scene = \"room.toml\"\nscene_set = { detail = 2 }\ntechnique = \"reference\"");
  EXPECT_THAT(expectErrorAt(text, "scene_set"), HasSubstr("a scene file takes no scene_set"));
}

// The suites of the repository parse, and the nightly suite keeps up with the registries.
TEST_F(SuiteFileTest, TolerancesDefaultAndPerMetric) {
  const Suite plain = load(kSuite);
  EXPECT_EQ(plain.tolerances, results::Tolerances{});
  const Suite suite = load(std::string(kSuite) + R"(
[tolerances]
default = { relative = 0.02 }
relmse = { absolute = 1e-4, relative = 0.1 }
flip_mean = { absolute = 0.001 }
frame_time = { relative = 0.2, significance = 0.001 }
)");
  EXPECT_EQ(suite.tolerances.metric_default.relative, 0.02);
  EXPECT_EQ(suite.tolerances.forMetric("relmse"), (results::Tolerance{1e-4, 0.1}));
  // A key given alone keeps the built-in default of the other.
  EXPECT_EQ(suite.tolerances.forMetric("flip_mean"),
            (results::Tolerance{0.001, results::Tolerance{}.relative}));
  EXPECT_EQ(suite.tolerances.forMetric("ssim").relative, 0.02);
  EXPECT_EQ(suite.tolerances.timing, (results::TimingTolerance{0.2, 0.001}));
}

TEST_F(SuiteFileTest, BadTolerances) {
  const std::string base = std::string(kSuite) + "\n[tolerances]\n";
  EXPECT_THAT(expectErrorAt(base + "relmes = { relative = 0.1 }\n", "relmes"),
              HasSubstr("[tolerances] has no metric 'relmes'"));
  EXPECT_THAT(expectErrorAt(base + "relmse = { relative = -0.1 }\n", "relative = -"),
              HasSubstr("tolerances.relmse.relative must be in [0, "));
  EXPECT_THAT(expectErrorAt(base + "relmse = { rel = 0.1 }\n", "rel ="),
              HasSubstr("unknown key 'rel'"));
  EXPECT_THAT(expectErrorAt(base + "frame_time = { significance = 1.5 }\n", "significance"),
              HasSubstr("tolerances.frame_time.significance must be in (0, 1)"));
  EXPECT_THAT(expectErrorAt(base + "relmse = 0.1\n", "relmse = 0.1"), HasSubstr("must be a table"));
}

TEST_F(SuiteFileTest, PaperValuesNameJobsOfTheSuite) {
  const Suite suite = load(std::string(kSuite) + R"(
[[paper]]
job = "direct-sweep/shadow=pcf"
quantity = "frame"
value = 12.5
unit = "ms"
source = "A paper, Table 1"
note = "an old GPU"
)");
  ASSERT_EQ(suite.paper.size(), 1u);
  EXPECT_EQ(suite.paper[0], (results::PaperValue{"direct-sweep/shadow=pcf", "frame", 12.5, "ms",
                                                 "A paper, Table 1", "an old GPU"}));
  const std::string wrong_job = std::string(kSuite) + R"(
[[paper]]
job = "direct-sweep/shadow=vsm"
quantity = "frame"
value = 1
source = "A paper"
)";
  EXPECT_THAT(expectErrorAt(wrong_job, "job = \"direct-sweep/shadow=vsm"),
              HasSubstr("paper.job 'direct-sweep/shadow=vsm' is not a job of this suite"));
  const std::string no_value = std::string(kSuite) + R"(
[[paper]]
job = "direct-sweep/shadow=pcf"
quantity = "frame"
source = "A paper"
)";
  EXPECT_THAT(errorOf(no_value), HasSubstr("value"));
}

// A tolerance marks a paper value we should reproduce; it is relative, so it cannot be negative,
// and a non-finite one would judge nothing.
TEST_F(SuiteFileTest, PaperValuesMayCarryARelativeTolerance) {
  auto paper = [](const std::string& tolerance_line) {
    return std::string(kSuite) + "\n[[paper]]\njob = \"direct-sweep/shadow=pcf\"\nquantity = " +
           "\"relmse\"\nvalue = 0.02\nsource = \"A paper\"\n" + tolerance_line;
  };
  const Suite with = load(paper("tolerance = 0.05\n"));
  ASSERT_EQ(with.paper.size(), 1u);
  EXPECT_EQ(with.paper[0].tolerance, std::optional<double>(0.05));
  EXPECT_EQ(load(paper("tolerance = 0\n")).paper[0].tolerance, std::optional<double>(0.0));
  EXPECT_EQ(load(paper("")).paper[0].tolerance, std::nullopt);  // shown, not judged
  for (const char* bad :
       {"tolerance = -0.05", "tolerance = inf", "tolerance = nan", "tolerance = \"5%\""}) {
    const std::string message = expectErrorAt(paper(std::string(bad) + "\n"), bad);
    EXPECT_THAT(message, HasSubstr("[[paper]] entry 1 (job 'direct-sweep/shadow=pcf', quantity "
                                   "'relmse') has tolerance = "))
        << bad;
    EXPECT_THAT(message, HasSubstr("finite number ≥ 0")) << bad;
    EXPECT_THAT(message, HasSubstr("tolerance = 0.05 for ±5%")) << bad;
  }
}

// Pass names are each technique's declared interface: a figure that names a pass the technique
// does not declare (a renamed pass, a typo) is refused where it is written, not left without its
// numbers in the report.
TEST_F(SuiteFileTest, PassesMustBeDeclaredByTheTechnique) {
  auto paper = [](const std::string& job, const std::string& quantity) {
    return std::string(kSuite) + "\n[[paper]]\njob = \"" + job + "\"\nquantity = \"" + quantity +
           "\"\nvalue = 1\nsource = \"A paper\"\n";
  };
  EXPECT_EQ(
      load(paper("direct-sweep/shadow=pcf", "frame/lights/shadow map + shading")).paper.size(), 1u);
  EXPECT_EQ(load(paper("direct-sweep/shadow=pcf", "g-buffer + relmse")).paper.size(), 1u);
  const std::string message = expectErrorAt(
      paper("direct-sweep/shadow=pcf", "frame/lights/relight cube maps"), "quantity = ");
  EXPECT_THAT(message, HasSubstr("names the pass 'frame/lights/relight cube maps', which "
                                 "technique 'direct' does not declare"));
  EXPECT_THAT(message, HasSubstr("frame/lights/shadow map"));  // the fix lists the declared ones
  EXPECT_THAT(expectErrorAt(paper("direct-sweep/shadow=hard", "iteration/update"), "quantity = "),
              HasSubstr("does not declare"));
  EXPECT_THAT(expectErrorAt(paper("cornell-reference", "frame"), "quantity = "),
              HasSubstr("reference jobs are not timed"));

  const std::string chart = std::string(kSuite) + "\n[[chart]]\ntitle = \"t\"\n";
  EXPECT_THAT(expectErrorAt(chart + "x = \"parameter:shadow\"\ny = \"shadow maps\"\n", "y = "),
              HasSubstr("chart.y 'shadow maps' names the pass 'shadow maps'"));
  EXPECT_THAT(expectErrorAt(chart + "jobs = \"cornell-reference\"\nx = \"frame\"\ny = \"relmse\"\n",
                            "x = "),
              HasSubstr("reference jobs are not timed"));
}

TEST_F(SuiteFileTest, ChartsNameQuantitiesAndJobsOfTheSuite) {
  const Suite suite = load(std::string(kSuite) + R"(
[[chart]]
title = "Frame time by shadow filter"
jobs = "direct-sweep/*"
x = "parameter:light_samples"
y = "frame"
series = "parameter:shadow"
log_y = true
front = true
)");
  ASSERT_EQ(suite.charts.size(), 1u);
  const results::ChartSpec& c = suite.charts[0];
  EXPECT_EQ(c.title, "Frame time by shadow filter");
  EXPECT_EQ(c.jobs, "direct-sweep/*");
  EXPECT_EQ(c.x, "parameter:light_samples");
  EXPECT_EQ(c.y, "frame");
  EXPECT_EQ(c.series, "parameter:shadow");
  EXPECT_FALSE(c.log_x);
  EXPECT_TRUE(c.log_y);
  EXPECT_TRUE(c.front);

  const std::string chart = std::string(kSuite) + "\n[[chart]]\ntitle = \"t\"\n";
  EXPECT_THAT(expectErrorAt(chart + "x = \"frame\"\ny = \"statistic:\"\n", "y = \"statistic:"),
              HasSubstr("chart.y 'statistic:' names no statistic"));
  EXPECT_THAT(expectErrorAt(chart + "x = \"fulll:relmse\"\ny = \"frame\"\n", "x = \"fulll"),
              HasSubstr("unknown prefix 'fulll:'"));
  EXPECT_THAT(
      expectErrorAt(chart + "x = \"frame\"\ny = \"relmse\"\njobs = \"chamber-*\"\n", "jobs ="),
      HasSubstr("chart.jobs 'chamber-*' matches no job of this suite"));
  EXPECT_THAT(expectErrorAt(chart + "x = \"frame\"\ny = \"relmse\"\nlog_x = \"yes\"\n", "log_x"),
              HasSubstr("chart.log_x must be true or false"));
  EXPECT_THAT(expectErrorAt(chart + "x = \"frame\"\ny = \"relmse\"\ncolour = \"red\"\n", "colour"),
              HasSubstr("colour"));
  EXPECT_THAT(errorOf(chart + "y = \"relmse\"\n"), HasSubstr("chart.x"));
}

TEST_F(SuiteFileTest, IterationsAreForTechniqueCasesAndReachTheLastCheckpoint) {
  const std::string reference_iterations = std::string(kSuite) + R"(
[[case]]
name = "ref-iterations"
scene = "cornell"
technique = "reference"
iterations = 10
)";
  EXPECT_THAT(expectErrorAt(reference_iterations, "iterations = 10"),
              HasSubstr("a reference case takes no iterations"));
  const std::string below = std::string(kSuite) + R"(
[[case]]
name = "below"
scene = "cornell"
technique = "direct"
checkpoints = [1, 8, 64]
iterations = 32
)";
  EXPECT_THAT(expectErrorAt(below, "iterations = 32"),
              HasSubstr("iterations = 32 is below the last checkpoint, 64"));
  const Suite suite = load(std::string(kSuite) + R"(
[[case]]
name = "fifty"
scene = "cornell"
technique = "direct"
checkpoints = [1, 8]
iterations = 50
)");
  EXPECT_EQ(suite.cases.back().settings.iterationCount(), 50);
  EXPECT_EQ(suite.cases.front().settings.iterationCount(), 64);  // the last checkpoint
  EXPECT_EQ(suite.cases[1].settings.iterationCount(), 1);        // neither given
}

// kSuite's jobs with a case that measures no FLIP, for figures.
const std::string kFigureSuite = std::string(kSuite) + R"(
[[case]]
name = "no-flip"
scene = "cornell"
technique = "direct"
metrics = ["relmse"]
)";

// A figure "f" with `columns` (when not empty) and the given panels (TOML of [[figure.panel]]
// tables).
std::string figure(const std::string& panels, const std::string& columns = "") {
  return kFigureSuite + "\n[[figure]]\nname = \"f\"\ntitle = \"Fig. 1\"\n" +
         (columns.empty() ? "" : "columns = " + columns + "\n") + panels;
}

std::string panel(const std::string& job, const std::string& image, const std::string& more = "") {
  return "[[figure.panel]]\njob = \"" + job + "\"\nimage = \"" + image + "\"\n" + more;
}

TEST_F(SuiteFileTest, FiguresPlaceTheirPanelsInTheDeclaredGrid) {
  const Suite suite = load(kFigureSuite + R"(
[[figure]]
name = "fig2"
title = "Fig. 2: shadows"
caption = "Hard and PCF shadows beside the reference."
columns = 3

[[figure.panel]]
job = "direct-sweep/shadow=pcf"
image = "image"
caption = "PCF"
row = 2
column = 3
metric = "frame"

[[figure.panel]]   # a row only: the first free column of row 1
job = "direct-sweep/shadow=hard"
image = "difference"
row = 1

[[figure.panel]]   # a column only: the first free row of column 3
job = "cornell-reference"
image = "reference"
column = 3

[[figure.panel]]   # neither: the first free cell, row by row
job = "direct-sweep/shadow=hard"
image = "difference"
metric = "none"

[[figure.panel]]
job = "direct-sweep/shadow=pcf"
image = "flip"
metric = "full:relmse"

[[figure]]
name = "second"
title = "Second"

[[figure.panel]]
job = "cornell-reference"
image = "image"

[[figure.panel]]
job = "cornell-reference"
image = "difference"
)");
  using Panel = results::FigureSpec::Panel;
  ASSERT_EQ(suite.figures.size(), 2u);
  const results::FigureSpec& fig2 = suite.figures[0];
  EXPECT_EQ(fig2.name, "fig2");
  EXPECT_EQ(fig2.title, "Fig. 2: shadows");
  EXPECT_EQ(fig2.caption, "Hard and PCF shadows beside the reference.");
  EXPECT_EQ(fig2.columns, 3);
  EXPECT_THAT(fig2.panels,
              ElementsAre(Panel{"direct-sweep/shadow=pcf", "image", "PCF", 2, 3, "frame"},
                          Panel{"direct-sweep/shadow=hard", "difference", "", 1, 1, ""},
                          Panel{"cornell-reference", "reference", "", 1, 3, ""},
                          Panel{"direct-sweep/shadow=hard", "difference", "", 1, 2, "none"},
                          Panel{"direct-sweep/shadow=pcf", "flip", "", 2, 1, "full:relmse"}));
  // Without columns, one row of all the panels.
  const results::FigureSpec& second = suite.figures[1];
  EXPECT_EQ(second.columns, 2);
  EXPECT_THAT(second.panels, ElementsAre(Panel{"cornell-reference", "image", "", 1, 1, ""},
                                         Panel{"cornell-reference", "difference", "", 1, 2, ""}));
}

TEST_F(SuiteFileTest, FiguresRefuseUnknownJobsImagesSharedCellsAndRepeatedNames) {
  const std::string unknown_job = expectErrorAt(figure(panel("direct-sweep/shadow=vsm", "image")),
                                                "job = \"direct-sweep/shadow=vsm\"");
  EXPECT_THAT(unknown_job, HasSubstr("figure 'f' panel 1: job 'direct-sweep/shadow=vsm' is not a "
                                     "job of this suite"));
  EXPECT_THAT(unknown_job, HasSubstr("cornell-reference, direct-sweep/shadow=hard, "
                                     "direct-sweep/shadow=pcf, no-flip"));  // the choices

  const std::string unknown_image = expectErrorAt(
      figure(panel("cornell-reference", "image") + panel("cornell-reference", "atlas")),
      "image = \"atlas\"");
  EXPECT_THAT(unknown_image, HasSubstr("figure 'f' panel 2: image 'atlas' is not a picture"));
  EXPECT_THAT(unknown_image, HasSubstr("image, reference, difference, flip or aux:<name>"));
  EXPECT_THAT(expectErrorAt(figure(panel("cornell-reference", "aux:")), "image = \"aux:\""),
              HasSubstr("image 'aux:' is not a picture"));
  EXPECT_THAT(expectErrorAt(figure(panel("no-flip", "flip")), "image = \"flip\""),
              HasSubstr("figure 'f' panel 1: job 'no-flip' does not measure flip"));

  const std::string shared = expectErrorAt(
      figure(panel("cornell-reference", "image", "row = 1\ncolumn = 2\n") +
                 panel("cornell-reference", "reference", "row = 1\ncolumn = 2  # again\n"),
             "2"),
      "column = 2  # again");
  EXPECT_THAT(shared, HasSubstr("figure 'f': panels 1 and 2 are both at row 1, column 2"));

  EXPECT_THAT(
      expectErrorAt(figure(panel("cornell-reference", "image", "column = 3\n"), "2"), "column = 3"),
      HasSubstr("figure 'f' panel 1: column 3 is beyond the figure's 2 columns"));
  EXPECT_THAT(expectErrorAt(figure(panel("cornell-reference", "image", "row = 1\ncolumn = 1\n") +
                                       panel("cornell-reference", "reference", "row = 1  # full\n"),
                                   "1"),
                            "row = 1  # full"),
              HasSubstr("figure 'f' panel 2: row 1 has no free cell"));

  const std::string twice = figure(panel("cornell-reference", "image")) +
                            "\n[[figure]]\nname = \"f\"  # again\ntitle = \"Fig. 2\"\n" +
                            panel("cornell-reference", "reference");
  EXPECT_THAT(expectErrorAt(twice, "name = \"f\"  # again"),
              HasSubstr("figure name 'f' is also the name of the figure at line " +
                        std::to_string(lineOf(twice, "[[figure]]"))));
}

TEST_F(SuiteFileTest, FiguresCheckTheirNamesPanelsAndMetrics) {
  EXPECT_THAT(expectErrorAt(kFigureSuite + "\n[[figure]]\nname = \"fig 6\"\ntitle = \"t\"\n" +
                                panel("cornell-reference", "image"),
                            "name = \"fig 6\""),
              HasSubstr("figure name 'fig 6' has characters other than"));
  EXPECT_THAT(expectErrorAt(figure(""), "[[figure]]"), HasSubstr("figure 'f' has no panels"));
  EXPECT_THAT(
      errorOf(kFigureSuite + "\n[[figure]]\nname = \"f\"\n" + panel("cornell-reference", "image")),
      HasSubstr("missing key 'figure.title'"));
  EXPECT_THAT(
      expectErrorAt(figure(panel("cornell-reference", "image", "colour = \"red\"\n")), "colour"),
      HasSubstr("allowed keys: job, image, caption, row, column, metric"));
  EXPECT_THAT(
      expectErrorAt(figure(panel("cornell-reference", "image", "metric = \"fulll:relmse\"\n")),
                    "metric = "),
      HasSubstr("figure 'f' panel 1's metric 'fulll:relmse' has an unknown prefix"));
  EXPECT_THAT(expectErrorAt(figure(panel("cornell-reference", "image", "metric = \"frame\"\n")),
                            "metric = "),
              HasSubstr("reference jobs are not timed"));
  EXPECT_THAT(
      expectErrorAt(figure(panel("direct-sweep/shadow=pcf", "image", "metric = \"shadow maps\"\n")),
                    "metric = "),
      HasSubstr("figure 'f' panel 1's metric 'shadow maps' names the pass 'shadow maps', which "
                "technique 'direct' does not declare"));
  EXPECT_THAT(expectErrorAt(figure(panel("cornell-reference", "image"), "0"), "columns = 0"),
              HasSubstr("figure.columns"));
}

std::filesystem::path repositorySuite(const char* name) {
  return std::filesystem::path(GIB_SOURCE_DIR) / "suites" / name;
}

// The pixel-sampling suite compares each technique case against both references: every case
// "<name>-area" asks for the box filter and has a twin "<name>" (the default, pixel centres)
// with the same scene, technique and parameters, so the two columns of its table differ in the
// reference alone.
TEST(RepositorySuites, PixelSamplingSuitePairsEachCaseWithItsBoxFilteredTwin) {
  const Suite suite = loadSuiteFile(repositorySuite("pixel-sampling.toml"));
  std::size_t twins = 0;
  for (const Case& c : suite.cases) {
    const bool area = c.name.ends_with("-area");
    EXPECT_EQ(c.settings.reference.pixel_sampling,
              area ? std::optional<std::string>("area") : std::nullopt)
        << c.name;
    if (!area) continue;
    const std::string twin_name = c.name.substr(0, c.name.size() - 5);
    for (const Case& twin : suite.cases)
      if (twin.name == twin_name) {
        ++twins;
        EXPECT_EQ(twin.scene.name, c.scene.name) << c.name;
        EXPECT_EQ(twin.technique, c.technique) << c.name;
        EXPECT_EQ(twin.technique_parameters.size(), c.technique_parameters.size()) << c.name;
      }
  }
  EXPECT_EQ(2 * twins, suite.cases.size());
}

TEST(RepositorySuites, SmokeSuiteParses) {
  const Suite suite = loadSuiteFile(repositorySuite("smoke.toml"));
  EXPECT_EQ(suite.name, "smoke");
  const std::vector<Job> jobs = expandSuite(suite);
  std::vector<std::string> ids;
  for (const Job& job : jobs) {
    ids.push_back(job.id);
    EXPECT_EQ(job.scene.name, "cornell");
    EXPECT_LE(*job.settings.width * *job.settings.height *
                  static_cast<long long>(job.settings.reference.spp),
              1LL << 25)
        << "keep the smoke suite quick";
  }
  EXPECT_THAT(ids, ElementsAre("cornell-reference", "cornell-direct/shadow=hard",
                               "cornell-direct/shadow=pcf", "cornell-direct/shadow=vsm",
                               "cornell-stochastic_radiosity"));
}

TEST(RepositorySuites, EveryFigureSuiteParsesAndShowsThePapersNumbersOrCharts) {
  int count = 0, figures = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(GIB_SOURCE_DIR) / "suites" / "figures")) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    const Suite suite = loadSuiteFile(entry.path());
    EXPECT_FALSE(expandSuite(suite).empty()) << entry.path();
    EXPECT_FALSE(suite.paper.empty() && suite.charts.empty())
        << entry.path() << " reproduces a figure: give it [[paper]] values or a [[chart]]";
    figures += int(suite.figures.size());
  }
  EXPECT_GE(count, 1);
  EXPECT_GE(figures, 5) << "the figure suites declare the documents' figures as [[figure]]s";
}

// The figure suites' [[figure]]s as their comments describe the documents' figures.
TEST(RepositorySuites, FigureSuitesLayOutTheDocumentsFigures) {
  using Panel = results::FigureSpec::Panel;
  const Suite fig6 = loadSuiteFile(repositorySuite("figures/barsi-jakab-fig6.toml"));
  ASSERT_EQ(fig6.figures.size(), 2u);
  EXPECT_EQ(fig6.figures[0].name, "fig6");
  EXPECT_EQ(fig6.figures[0].columns, 3);
  std::vector<std::string> atlas_jobs;
  for (const Panel& p : fig6.figures[0].panels) {
    EXPECT_EQ(p.image, "aux:atlas");
    EXPECT_EQ(p.row, 1);
    atlas_jobs.push_back(p.job);
  }
  EXPECT_THAT(atlas_jobs, ElementsAre("iterations-1", "iterations-4", "iterations-50"));
  EXPECT_EQ(fig6.figures[1].name, "fig5");
  ASSERT_EQ(fig6.figures[1].panels.size(), 2u);
  EXPECT_EQ(fig6.figures[1].panels[0].job, "iterations-50");
  EXPECT_EQ(fig6.figures[1].panels[0].image, "image");
  EXPECT_EQ(fig6.figures[1].panels[1].image, "reference");
  for (const char* name :
       {"nijasure-fig2.toml", "nijasure-fig3.toml", "nijasure-fig5.toml", "book-fig7-5.toml"}) {
    const Suite suite = loadSuiteFile(repositorySuite((std::string("figures/") + name).c_str()));
    EXPECT_FALSE(suite.figures.empty()) << name;
  }
}

// What a technique declares besides its passes (TechniqueInfo): its auxiliary images, its
// statistics and what it needs of the scene. A suite naming one it does not have is refused when
// it loads, at the line that names it, rather than when the report is written.
constexpr const char* kRadiositySuite = R"(name = "declared"

[defaults]
width = 32
height = 32

[[case]]
name = "radiosity"
scene = "cornell"
technique = "stochastic_radiosity"
iterations = 2

[[chart]]
title = "atlas"
jobs = "radiosity"
x = "statistic:atlas_texels"
y = "iteration"

[[figure]]
name = "atlas"
title = "the radiance atlas"

[[figure.panel]]
job = "radiosity"
image = "aux:atlas"
)";

TEST_F(SuiteFileTest, DeclaredAuxiliaryImagesAndStatisticsLoad) {
  const Suite suite = load(kRadiositySuite);
  ASSERT_EQ(suite.figures.size(), 1u);
  EXPECT_EQ(suite.figures[0].panels[0].image, "aux:atlas");
}

TEST_F(SuiteFileTest, AnUndeclaredAuxiliaryImageIsRefusedWhereItIsNamed) {
  const std::string text = replaced(kRadiositySuite, "\"aux:atlas\"", "\"aux:atlsa\"");
  EXPECT_THAT(expectErrorAt(text, "aux:atlsa"),
              HasSubstr("technique 'stochastic_radiosity' declares no auxiliary image 'atlsa'; "
                        "choose one of aux:atlas"));
}

TEST_F(SuiteFileTest, AnUndeclaredStatisticIsRefusedWhereItIsNamed) {
  const std::string text =
      replaced(kRadiositySuite, "statistic:atlas_texels", "statistic:atlas_texel");
  EXPECT_THAT(expectErrorAt(text, "statistic:atlas_texel"),
              HasSubstr("names the statistic 'atlas_texel', which technique "
                        "'stochastic_radiosity' does not declare; name one of its statistics: "
                        "vertices, atlas_texels"));
}

TEST_F(SuiteFileTest, ATechniqueOnASceneWithoutWhatItNeedsIsRefusedAtItsCase) {
  const std::string text = replaced(kRadiositySuite, "\"stochastic_radiosity\"",
                                    "\"spherical_billboards\"\nset = { sky_directions = [0, 4] }");
  const std::string cut = text.substr(0, text.find("[[chart]]"));
  EXPECT_THAT(expectErrorAt(cut, "spherical_billboards"),
              HasSubstr("job 'radiosity/sky_directions=0': technique 'spherical_billboards' "
                        "renders a participating medium and scene 'cornell' has none"));
  // On the cloud the same case loads.
  EXPECT_NO_THROW(load(replaced(cut, "\"cornell\"", "\"cloud\"")));
}

TEST(RepositorySuites, NightlySuiteCoversEverySceneAndTechnique) {
  const Suite suite = loadSuiteFile(repositorySuite("nightly.toml"));
  EXPECT_EQ(suite.name, "nightly");
  std::set<std::pair<std::string, std::string>> covered;
  for (const Job& job : expandSuite(suite)) covered.emplace(job.scene.name, job.technique);
  for (const scene::BuiltinSceneInfo& info : scene::builtinScenes()) {
    EXPECT_TRUE(covered.count({info.name, kReferenceTechnique}))
        << "suites/nightly.toml has no reference case for " << info.name;
    // A technique refuses a scene that lacks what it needs (a medium, a sky).
    const scene::Scene scene = scene::loadScene(info.name);
    for (const rt::TechniqueInfo& technique : rt::techniqueCatalogue()) {
      if (rt::missingSceneNeed(technique, scene)) continue;
      EXPECT_TRUE(covered.count({info.name, technique.name}))
          << "suites/nightly.toml has no case for " << info.name << " x " << technique.name;
    }
  }
}

}  // namespace
}  // namespace gib::suites
