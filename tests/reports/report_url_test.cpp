// `gibench run` and `gibench report` tell the reader the report's file:/// address, the form a
// browser keeps a "#…" view in (a bare path loses it in Chromium).
#include "reports/html_text.h"
#include "support/run_command.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;

// The last line of `text` (without its '\n').
std::string lastLine(const std::string& text) {
  const std::string trimmed = text.substr(0, text.find_last_not_of('\n') + 1);
  return trimmed.substr(trimmed.rfind('\n') + 1);
}

TEST(ReportUrl, ReportPrintsThePathOnStdoutAndTheAddressForABrowserOnStderr) {
  test::TempDir dir;
  results::RunResults results = test::syntheticReportResults();
  test::writeSyntheticRunDirectory(dir / "run", results, dir / "store");
  const test::CommandResult r = test::runGibench({"report", (dir / "run").string()}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path index = fs::absolute(dir / "run" / "index.html");
  EXPECT_EQ(r.out, (dir / "run" / "index.html").string() + "\n");
  EXPECT_EQ(lastLine(r.err), "open       file://" + urlPath(index.generic_string())) << r.err;
}

// The smallest run there is: one reference job of a few pixels, no GL.
constexpr const char* kReferenceOnlySuite = R"(name = "url"
[defaults]
width = 4
height = 4
metrics = ["mse"]
[defaults.reference]
spp = 4
[[case]]
scene = "cornell"
technique = "reference"
)";

TEST(ReportUrl, RunEndsWithTheReportsFileUrl) {
  test::TempDir dir;
  std::ofstream(dir / "url.toml") << kReferenceOnlySuite;
  const test::CommandResult r =
      test::runGibench({"run", (dir / "url.toml").string(), "--out",
                        (dir / "run with space").string(), "--store", (dir / "store").string()},
                       dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string url =
      "file://" + urlPath(dir.path().generic_string()) + "/run%20with%20space/index.html";
  EXPECT_EQ(lastLine(r.out), "open       " + url) << r.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "run with space" / "index.html"));
}

}  // namespace
}  // namespace gib::reports
