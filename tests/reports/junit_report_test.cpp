// `--junit`: the verdicts a CI pipeline reads from a run, on synthetic runs whose regressions,
// failures and paper values the tests choose; the document is read back with the tests' XML
// reader and validated with xmllint against tests/data/junit.xsd, the layout GitLab, Jenkins and
// GitHub's reporters read.
#include "reports/junit_report.h"

#include "reports/number_format.h"
#include "reports/report_labels.h"
#include "reports/run_comparison.h"
#include "support/run_command.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"
#include "support/xml_reader.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

std::optional<fs::path> findXmllint() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::error_code ec;
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && fs::is_regular_file(fs::path(dir) / "xmllint", ec))
      return fs::path(dir) / "xmllint";
  return std::nullopt;
}

// Skips without xmllint, unless the environment says it is part of the test run
// (scripts/test.sh sets GIB_REQUIRE_XMLLINT=1: scripts/install-deps.sh installs it).
#define GIB_REQUIRE_XMLLINT(xmllint)                                                           \
  const std::optional<fs::path> xmllint = findXmllint();                                       \
  if (!xmllint) {                                                                              \
    const char* required = std::getenv("GIB_REQUIRE_XMLLINT");                                 \
    if (required && std::string_view(required) == "1")                                         \
      FAIL() << "GIB_REQUIRE_XMLLINT=1 but no xmllint on PATH; scripts/install-deps.sh "       \
                "installs it (libxml2-utils)";                                                 \
    GTEST_SKIP() << "no xmllint on PATH; scripts/install-deps.sh installs it (libxml2-utils)"; \
  }

const fs::path kSchema = fs::path(GIB_SOURCE_DIR) / "tests" / "data" / "junit.xsd";
const fs::path kRunDir = "runs/smoke";

// The suite's previous run: the synthetic run a day earlier, identical unless a test changes it.
results::RunResults previousRun() {
  results::RunResults previous =
      test::syntheticReportResults("20261121-100405-smoke-00000000", "fedcba9876543210");
  previous.run.started = "2026-11-21T10:04:05Z";
  return previous;
}

struct Junit {
  std::string xml;
  test::XmlElement root;
  const test::XmlElement* suite = nullptr;

  std::vector<const test::XmlElement*> cases() const { return suite->childrenNamed("testcase"); }
  const test::XmlElement* testCase(const std::string& name) const {
    for (const test::XmlElement* c : cases())
      if (c->at("name") == name) return c;
    return nullptr;
  }
  std::string property(const std::string& name) const {
    for (const test::XmlElement* p : suite->child("properties")->childrenNamed("property"))
      if (p->at("name") == name) return p->at("value");
    return "(absent)";
  }
};

Junit junitOf(const results::RunResults& results,
              const std::optional<results::RunResults>& previous) {
  const RunComparison comparison(results, previous);
  Junit junit;
  junit.xml = junitReport(results, comparison, kRunDir, previous ? &*previous : nullptr);
  junit.root = test::parseXml(junit.xml);
  junit.suite = junit.root.child("testsuite");
  return junit;
}

// The one failure, error or skipped element of a test case, or nullptr when it passed.
const test::XmlElement* verdictOf(const test::XmlElement& test_case) {
  for (const char* name : {"failure", "error", "skipped"})
    if (const test::XmlElement* e = test_case.child(name)) return e;
  return nullptr;
}

// The counts of both the <testsuites> and the <testsuite> element against the test cases.
void expectCounts(const Junit& junit, std::size_t tests, std::size_t failures, std::size_t errors,
                  std::size_t skipped) {
  ASSERT_NE(junit.suite, nullptr) << junit.xml;
  EXPECT_EQ(junit.root.name, "testsuites");
  EXPECT_EQ(junit.cases().size(), tests) << junit.xml;
  for (const test::XmlElement* e : {&junit.root, junit.suite}) {
    EXPECT_EQ(e->at("tests"), std::to_string(tests)) << e->name;
    EXPECT_EQ(e->at("failures"), std::to_string(failures)) << e->name;
    EXPECT_EQ(e->at("errors"), std::to_string(errors)) << e->name;
  }
  EXPECT_EQ(junit.suite->at("skipped"), std::to_string(skipped));
  std::size_t counted[3] = {0, 0, 0};
  for (const test::XmlElement* c : junit.cases()) {
    counted[0] += c->child("failure") != nullptr;
    counted[1] += c->child("error") != nullptr;
    counted[2] += c->child("skipped") != nullptr;
  }
  EXPECT_EQ(counted[0], failures);
  EXPECT_EQ(counted[1], errors);
  EXPECT_EQ(counted[2], skipped);
}

TEST(JunitReport, ARegressionFailsExactlyItsJobAndTheOthersPass) {
  const results::RunResults results = test::syntheticReportResults();
  results::RunResults previous = previousRun();
  // relmse of the pcf job halves in the previous run: this run's is a regression beyond the
  // default 5% tolerance (the way the diff tests inject one); nothing else changes.
  const results::JobResult& regressed = results.jobs[1];
  const double before = previous.jobs[1].metrics[0].second / 2;
  previous.jobs[1].metrics[0].second = before;
  const double after = regressed.metrics[0].second;

  const Junit junit = junitOf(results, previous);
  expectCounts(junit, results.jobs.size(), 1, 0, 0);
  for (const results::JobResult& job : results.jobs) {
    const test::XmlElement* test_case = junit.testCase(job.id);
    ASSERT_NE(test_case, nullptr) << job.id;
    EXPECT_EQ(test_case->at("classname"), "smoke.cornell." + job.technique);
    EXPECT_EQ(test_case->at("time"), fmt::format("{:.3f}", job.seconds));
    const test::XmlElement* out = test_case->child("system-out");
    ASSERT_NE(out, nullptr);
    EXPECT_THAT(out->text, HasSubstr((kRunDir / jobPageFile(job)).string()));
    if (job.id != regressed.id) {
      EXPECT_EQ(verdictOf(*test_case), nullptr) << job.id;
      continue;
    }
    const test::XmlElement* failure = test_case->child("failure");
    ASSERT_NE(failure, nullptr);
    EXPECT_EQ(failure->at("type"), "regression");
    EXPECT_THAT(failure->at("message"), HasSubstr("relmse"));
    EXPECT_THAT(failure->at("message"), HasSubstr(previous.run.id));
    EXPECT_THAT(failure->at("message"), Not(HasSubstr("\n")));
    // The body: the quantity with previous, this run, change and the allowed tolerance.
    const results::Tolerance& tolerance = results.tolerances.forMetric("relmse");
    const std::string line = fmt::format(
        "relmse: previous {}, this run {}, change {}, allowed ±max({}, {}·|previous|)",
        formatNumber(before), formatNumber(after), formatChange((after - before) / before),
        formatNumber(tolerance.absolute), formatNumber(tolerance.relative));
    EXPECT_THAT(failure->text, HasSubstr(line)) << failure->text;
    // Only the injected value regressed: the full-reference relmse did not change.
    EXPECT_THAT(failure->text, Not(HasSubstr("full:relmse")));
    EXPECT_THAT(out->text, HasSubstr("primary metric relmse: " + formatNumber(after)));
  }
  EXPECT_EQ(junit.suite->at("name"), "smoke");
  EXPECT_EQ(junit.suite->at("hostname"), results.run.host);
  EXPECT_EQ(junit.suite->at("timestamp"), "2026-11-22T10:04:05");
  EXPECT_EQ(junit.property("run_id"), results.run.id);
  EXPECT_EQ(junit.property("commit"), results.run.git_commit);
  EXPECT_EQ(junit.property("gibench_version"), results.run.gibench_version);
  EXPECT_EQ(junit.property("previous_run_id"), previous.run.id);
}

TEST(JunitReport, WithoutAPreviousRunNothingRegresses) {
  const Junit junit = junitOf(test::syntheticReportResults(), std::nullopt);
  expectCounts(junit, 3, 0, 0, 0);
  EXPECT_EQ(junit.property("previous_run_id"), "");
}

TEST(JunitReport, AFailedJobIsAnError) {
  results::RunResults results = test::syntheticReportResults();
  results::JobResult& failed = results.jobs[2];
  test::markFailed(failed, "no result: the task was cancelled\nslurmstepd: CANCELLED AT 10:05");
  const Junit junit = junitOf(results, previousRun());
  expectCounts(junit, 3, 0, 1, 0);
  const test::XmlElement* error = junit.testCase(failed.id)->child("error");
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(error->at("message"), "no result: the task was cancelled");
  EXPECT_THAT(error->text, HasSubstr(failed.failure));
}

TEST(JunitReport, APaperValueOutsideItsToleranceFailsAndOneInsidePasses) {
  results::RunResults results = test::syntheticReportResults();
  const results::JobResult& pcf = results.jobs[1];
  const results::JobResult& vsm = results.jobs[2];
  const double pcf_relmse = *pcf.metric("relmse"), vsm_relmse = *vsm.metric("relmse");
  // Within: the paper's value 4% above ours, tolerance 5%. Outside: 10% above, tolerance 5%.
  results.paper = {{pcf.id, "relmse", pcf_relmse * 1.04, "", "Paper A", "", 0.05},
                   {vsm.id, "relmse", vsm_relmse * 1.10, "", "Paper B", "", 0.05},
                   // No tolerance: a number shown beside ours, never a failure.
                   {vsm.id, "frame", 1.0, "ms", "Paper C", "other hardware"}};
  const Junit junit = junitOf(results, std::nullopt);
  expectCounts(junit, 3, 1, 0, 0);
  EXPECT_EQ(verdictOf(*junit.testCase(pcf.id)), nullptr);
  const test::XmlElement* failure = junit.testCase(vsm.id)->child("failure");
  ASSERT_NE(failure, nullptr);
  EXPECT_EQ(failure->at("type"), "paper");
  EXPECT_THAT(failure->at("message"), HasSubstr("relmse"));
  EXPECT_THAT(failure->text, HasSubstr("outside ±5%"));
  EXPECT_THAT(failure->text, HasSubstr("Paper B"));
  EXPECT_THAT(failure->text, Not(HasSubstr("Paper C")));
}

TEST(JunitReport, AJobThePreviousRunHadIsMissingOrSkipped) {
  const results::RunResults results = test::syntheticReportResults();
  results::RunResults previous = previousRun();
  results::JobResult gone = previous.jobs[2];
  gone.id = "cornell-direct/shadow=hard,light_samples=4";
  previous.jobs.push_back(gone);

  const Junit junit = junitOf(results, previous);
  expectCounts(junit, 4, 1, 0, 0);
  const test::XmlElement* missing = junit.testCase(gone.id);
  ASSERT_NE(missing, nullptr);
  EXPECT_EQ(missing->at("classname"), "smoke.cornell.direct");  // from the previous run
  ASSERT_NE(missing->child("failure"), nullptr);
  EXPECT_EQ(missing->child("failure")->at("type"), "missing");

  // A run of part of its suite (--only) did not lose the job: it left it out.
  results::RunResults partial = results;
  partial.run.complete = false;
  const Junit skipped = junitOf(partial, previous);
  expectCounts(skipped, 4, 0, 0, 1);
  ASSERT_NE(skipped.testCase(gone.id)->child("skipped"), nullptr);
}

// Job ids carry '/', '=' and ','; a hand-written suite may add '<', '&' and quotes, and a failed
// task's reason may hold a terminal escape and bytes that are not UTF-8.
results::RunResults awkwardResults() {
  results::RunResults results = test::syntheticReportResults();
  results.run.suite = "smoke&<co>";
  results::JobResult& job = results.jobs[2];
  job.id = "cornell-direct/label=<a&b>,quote=\"x\",apostrophe='y'";
  job.failure = "failed: <EGL_BAD_ALLOC> & \"quotes\" 'too' \x1b[31mred\x1b[0m \xff]]>\nline 2";
  results.paper = {
      {results.jobs[1].id, "relmse", 1.0, "", "A & B <2005> \"Table\" 'one'", "", 0.01}};
  return results;
}

TEST(JunitReport, SpecialCharactersAreEscapedAndReadBack) {
  const results::RunResults results = awkwardResults();
  const Junit junit = junitOf(results, std::nullopt);
  expectCounts(junit, 3, 1, 1, 0);
  EXPECT_EQ(junit.suite->at("name"), results.run.suite);
  const test::XmlElement* test_case = junit.testCase(results.jobs[2].id);
  ASSERT_NE(test_case, nullptr) << junit.xml;
  EXPECT_EQ(test_case->at("classname"), results.run.suite + ".cornell.direct");
  const test::XmlElement* error = test_case->child("error");
  ASSERT_NE(error, nullptr);
  // The control characters and the stray byte become U+FFFD; everything else reads back.
  EXPECT_EQ(error->at("message"),
            "failed: <EGL_BAD_ALLOC> & \"quotes\" 'too' \xEF\xBF\xBD[31mred\xEF\xBF\xBD[0m "
            "\xEF\xBF\xBD]]>");
  EXPECT_THAT(error->text, HasSubstr("\nline 2"));
  const test::XmlElement* paper = junit.testCase(results.jobs[1].id)->child("failure");
  ASSERT_NE(paper, nullptr);
  EXPECT_THAT(paper->text, HasSubstr(results.paper[0].source));
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

test::CommandResult validate(const fs::path& xmllint, const fs::path& file) {
  return test::runProgram(
      {xmllint.string(), "--noout", "--schema", kSchema.string(), file.string()},
      file.parent_path());
}

TEST(JunitReport, EveryKindOfOutcomeValidatesAgainstTheSchema) {
  GIB_REQUIRE_XMLLINT(xmllint);
  test::TempDir dir;
  results::RunResults regressed = test::syntheticReportResults();
  results::RunResults previous = previousRun();
  previous.jobs[1].metrics[0].second /= 2;
  results::JobResult gone = previous.jobs[2];
  gone.id = "cornell-gone";
  previous.jobs.push_back(gone);
  results::RunResults partial = regressed;
  partial.run.complete = false;
  partial.run.started = "";  // no timestamp at all
  const std::vector<std::pair<std::string, std::string>> documents = {
      {"regressed", junitOf(regressed, previous).xml},
      {"partial", junitOf(partial, previous).xml},
      {"first", junitOf(test::syntheticReportResults(), std::nullopt).xml},
      {"awkward", junitOf(awkwardResults(), std::nullopt).xml}};
  for (const auto& [name, xml] : documents) {
    const fs::path file = dir / (name + ".xml");
    writeText(file, xml);
    const test::CommandResult r = validate(*xmllint, file);
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err << "\n" << xml;
  }
  // An independent parser reads the escaped job id back as it was.
  const test::CommandResult id = test::runProgram(
      {xmllint->string(), "--xpath", "string(/testsuites/testsuite/testcase[3]/@name)",
       (dir / "awkward.xml").string()},
      dir.path());
  EXPECT_EQ(id.exit_code, 0) << id.err;
  EXPECT_EQ(id.out.substr(0, id.out.find_last_not_of('\n') + 1), awkwardResults().jobs[2].id);
}

TEST(JunitReport, TheSchemaRejectsInvalidDocuments) {
  GIB_REQUIRE_XMLLINT(xmllint);
  test::TempDir dir;
  const std::string valid = junitOf(test::syntheticReportResults(), previousRun()).xml;
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = valid;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  };
  const std::vector<std::pair<std::string, std::string>> invalid = {
      {"count", replaced("tests=\"3\"", "tests=\"three\"")},
      {"classname", replaced(" classname=\"smoke.cornell.reference\"", "")},
      {"zone", replaced("timestamp=\"2026-11-22T10:04:05\"", "timestamp=\"2026-11-22T10:04:05Z\"")},
      {"order", replaced("<properties>", "<testcase/><properties>")},
      {"unescaped", replaced("name=\"smoke\"", "name=\"a & b\"")},
  };
  writeText(dir / "valid.xml", valid);
  ASSERT_EQ(validate(*xmllint, dir / "valid.xml").exit_code, 0);
  for (const auto& [name, xml] : invalid) {
    const fs::path file = dir / (name + ".xml");
    writeText(file, xml);
    EXPECT_NE(validate(*xmllint, file).exit_code, 0) << name << " was accepted:\n" << xml;
  }
}

}  // namespace
}  // namespace gib::reports
