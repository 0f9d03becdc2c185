#include "reports/junit_report.h"

#include "reports/number_format.h"
#include "reports/paper_check.h"
#include "reports/regressed_values.h"
#include "reports/report_labels.h"
#include "reports/xml_text.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <regex>
#include <vector>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

// How many quantities a failure's one-line message names before "and N more".
constexpr std::size_t kMessageQuantities = 4;

enum class Outcome { kPassed, kFailed, kError, kSkipped };

struct TestCase {
  std::string classname, name;
  double seconds = 0;
  Outcome outcome = Outcome::kPassed;
  std::string type, message, body;  // of the failure, error or skipped element
  std::string out;                  // <system-out>
};

std::string attribute(std::string_view name, std::string_view value) {
  return fmt::format(" {}=\"{}\"", name, escapeXml(value, true));
}

// Seconds as JUnit readers parse them: a plain non-negative decimal.
std::string secondsText(double seconds) {
  return fmt::format("{:.3f}", std::isfinite(seconds) && seconds > 0 ? seconds : 0.0);
}

// XML Schema's dateTime without a zone, as Ant's JUnit schema has it: the run's start is UTC
// ("2026-11-22T10:04:05Z"), and the zone is dropped. Nothing when the start is not in that form.
std::optional<std::string> timestampText(const std::string& started) {
  static const std::regex kIso(R"((\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2})Z?)");
  std::smatch match;
  if (!std::regex_match(started, match, kIso)) return std::nullopt;
  return match[1].str();
}

std::string firstLine(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? std::string("no reason recorded") : line;
}

std::string plural(std::size_t count, const char* noun) {
  return fmt::format("{} {}{}", count, noun, count == 1 ? "" : "s");
}

// "relmse +110.0%, median frame time (ms) +50.0% and 2 more".
std::string quantityList(const std::vector<std::string>& items) {
  std::string list;
  for (std::size_t i = 0; i < items.size() && i < kMessageQuantities; ++i)
    list += (i ? ", " : "") + items[i];
  if (items.size() > kMessageQuantities)
    list += fmt::format(" and {} more", items.size() - kMessageQuantities);
  return list;
}

std::string previousRunText(const RunComparison& comparison) {
  const results::RunInfo& previous = *comparison.previousRun();
  return fmt::format("the previous run {} (commit {})", previous.id, shortCommit(previous));
}

std::string jobOutput(const results::RunResults& results, const results::JobResult& job,
                      const fs::path& run_dir) {
  const std::string metric = results.primary_metric.empty() ? "metric" : results.primary_metric;
  std::string out;
  if (const std::optional<double> value = job.metric(results.primary_metric)) {
    out += fmt::format("primary metric {}: {}", metric, formatNumber(*value));
    for (const auto& [name, full] : job.metrics_full)
      if (name == results.primary_metric)
        out += fmt::format(" (against the full reference {})", formatNumber(full));
    out += "\n";
  } else {
    out += fmt::format("primary metric {}: not measured\n", metric);
  }
  const std::optional<double> frame = job.frameMedianMs();
  out += frame ? fmt::format("frame time: {} ms (median)\n", formatNumber(*frame))
               : std::string("frame time: not timed\n");
  out += fmt::format("report page: {}\n", (run_dir / jobPageFile(job)).string());
  if (!job.outputs.log.empty())
    out += fmt::format("log: {}\n", (run_dir / job.outputs.log).string());
  return out;
}

// The failure of a job that ran: its regressed values and its paper values outside tolerance.
void judgeJob(TestCase& test, const results::JobResult& job, const RunComparison& comparison,
              const std::vector<RegressedValue>& regressed, const std::vector<PaperCheck>& paper) {
  std::vector<std::string> changes, paper_items;
  std::string body;
  const std::optional<JobComparison> compared = comparison.job(job.id);
  if (compared && compared->overall == results::Verdict::kRegressed) {
    body += fmt::format("Regressed against {}:\n", previousRunText(comparison));
    for (const RegressedValue& v : regressed) {
      if (v.job != job.id) continue;
      changes.push_back(v.quantity + " " + v.change);
      body += fmt::format("  {}: previous {}, this run {}, change {}, allowed {}\n", v.quantity,
                          v.previous, v.next, v.change, v.allowed);
      if (!v.evidence.empty()) body += fmt::format("    {}\n", v.evidence);
    }
  }
  for (const PaperCheck& check : paper) {
    if (check.job != &job || check.verdict != PaperVerdict::kOutside) continue;
    const results::PaperValue& p = *check.paper;
    if (paper_items.empty()) body += "Paper values outside their tolerance:\n";
    const std::string unit = p.unit.empty() ? "" : " " + p.unit;
    const std::string ours = check.ours ? formatNumber(*check.ours) + unit : "not measured";
    paper_items.push_back(
        fmt::format("{} {} against {}{}", p.quantity, ours, formatNumber(p.value), unit));
    body += fmt::format("  {}: paper {}{}, ours {}, {} ({})\n", p.quantity, formatNumber(p.value),
                        unit, ours, paperVerdictText(check), p.source);
  }
  if (changes.empty() && paper_items.empty()) return;
  test.outcome = Outcome::kFailed;
  test.body = body;
  std::vector<std::string> parts;
  if (!changes.empty())
    parts.push_back(fmt::format("regressed against run {}: {}", comparison.previousRun()->id,
                                quantityList(changes)));
  if (!paper_items.empty())
    parts.push_back(fmt::format("{} outside tolerance: {}",
                                paper_items.size() == 1 ? std::string("paper value")
                                                        : plural(paper_items.size(), "paper value"),
                                quantityList(paper_items)));
  test.type = changes.empty() ? "paper" : "regression";
  test.message = parts.size() == 1 ? parts[0] : parts[0] + "; " + parts[1];
}

std::vector<TestCase> testCases(const results::RunResults& results, const RunComparison& comparison,
                                const fs::path& run_dir, const results::RunResults* previous) {
  const std::vector<RegressedValue> regressed = regressedValues(comparison);
  const std::vector<PaperCheck> paper = checkPaperValues(results);
  const std::string& suite = results.run.suite;
  std::vector<TestCase> tests;
  for (const results::JobResult& job : results.jobs) {
    TestCase test;
    test.classname = fmt::format("{}.{}.{}", suite, job.scene, job.technique);
    test.name = job.id;
    test.seconds = job.seconds;
    test.out = jobOutput(results, job, run_dir);
    if (job.failed()) {
      test.outcome = Outcome::kError;
      test.type = "job-failed";
      test.message = firstLine(job.failure);
      test.body = job.failure + "\n";
    } else {
      judgeJob(test, job, comparison, regressed, paper);
    }
    tests.push_back(std::move(test));
  }
  if (!comparison.hasPrevious()) return tests;
  for (const results::JobPresence& presence : comparison.diff()->presence) {
    if (presence.verdict != results::Verdict::kMissing &&
        presence.verdict != results::Verdict::kNotRun)
      continue;
    TestCase test;
    const results::JobResult* before = previous ? previous->findJob(presence.job) : nullptr;
    test.classname =
        before ? fmt::format("{}.{}.{}", suite, before->scene, before->technique) : suite;
    test.name = presence.job;
    if (presence.verdict == results::Verdict::kMissing) {
      test.outcome = Outcome::kFailed;
      test.type = "missing";
      test.message = fmt::format("in the previous run {}, missing from this one",
                                 comparison.previousRun()->id);
      test.body = fmt::format(
          "The job ran in {} and is not in this run: the suite no longer has it, or its id "
          "changed.\n",
          previousRunText(comparison));
    } else {
      test.outcome = Outcome::kSkipped;
      test.message = "not run: this run ran part of its suite (--only)";
    }
    tests.push_back(std::move(test));
  }
  return tests;
}

std::string testCaseXml(const TestCase& test) {
  std::string xml =
      fmt::format("    <testcase{}{}{}>\n", attribute("classname", test.classname),
                  attribute("name", test.name), attribute("time", secondsText(test.seconds)));
  const char* element = test.outcome == Outcome::kFailed  ? "failure"
                        : test.outcome == Outcome::kError ? "error"
                                                          : nullptr;
  if (element)
    xml += fmt::format("      <{}{}{}>{}</{}>\n", element, attribute("message", test.message),
                       attribute("type", test.type), escapeXml(test.body, false), element);
  if (test.outcome == Outcome::kSkipped)
    xml += fmt::format("      <skipped{}/>\n", attribute("message", test.message));
  if (!test.out.empty())
    xml += fmt::format("      <system-out>{}</system-out>\n", escapeXml(test.out, false));
  return xml + "    </testcase>\n";
}

std::string property(std::string_view name, std::string_view value) {
  return fmt::format("      <property{}{}/>\n", attribute("name", name), attribute("value", value));
}

}  // namespace

std::string junitReport(const results::RunResults& results, const RunComparison& comparison,
                        const fs::path& run_dir, const results::RunResults* previous) {
  const std::vector<TestCase> tests = testCases(results, comparison, run_dir, previous);
  std::size_t failures = 0, errors = 0, skipped = 0;
  double seconds = 0;
  for (const TestCase& test : tests) {
    failures += test.outcome == Outcome::kFailed;
    errors += test.outcome == Outcome::kError;
    skipped += test.outcome == Outcome::kSkipped;
    if (std::isfinite(test.seconds) && test.seconds > 0) seconds += test.seconds;
  }
  const results::RunInfo& run = results.run;
  const std::optional<results::RunInfo>& before = comparison.previousRun();
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += fmt::format("<testsuites{}{}{}{}{}>\n", attribute("name", "gibench " + run.suite),
                     attribute("tests", std::to_string(tests.size())),
                     attribute("failures", std::to_string(failures)),
                     attribute("errors", std::to_string(errors)),
                     attribute("time", secondsText(seconds)));
  const std::optional<std::string> timestamp = timestampText(run.started);
  xml += fmt::format(
      "  <testsuite{}{}{}{}{}{}{}{}>\n", attribute("name", run.suite),
      attribute("tests", std::to_string(tests.size())),
      attribute("failures", std::to_string(failures)), attribute("errors", std::to_string(errors)),
      attribute("skipped", std::to_string(skipped)), attribute("time", secondsText(seconds)),
      timestamp ? attribute("timestamp", *timestamp) : std::string(),
      attribute("hostname", run.host));
  xml += "    <properties>\n";
  xml += property("run_id", run.id);
  xml += property("suite_file", run.suite_file);
  xml += property("commit", run.git_commit);
  xml += property("git_dirty", run.git_dirty ? "true" : "false");
  xml += property("gibench_version", run.gibench_version);
  xml += property("previous_run_id", before ? before->id : "");
  xml += property("previous_commit", before ? before->git_commit : "");
  xml += property("report", (run_dir / "index.html").string());
  xml += "    </properties>\n";
  for (const TestCase& test : tests) xml += testCaseXml(test);
  xml += "  </testsuite>\n</testsuites>\n";
  return xml;
}

}  // namespace gib::reports
