#include "support/headless_browser.h"

#include "reports/html_text.h"
#include "support/run_command.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>

namespace gib::test {

namespace fs = std::filesystem;

namespace {

// Real-time limit on one browser run: a page that never settles must not hang the test suite.
constexpr const char* kBrowserTimeoutSeconds = "60";

}  // namespace

std::optional<fs::path> findChromium() {
  std::error_code ec;
  if (fs::is_regular_file("/usr/bin/chromium", ec)) return fs::path("/usr/bin/chromium");
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && fs::is_regular_file(fs::path(dir) / "chromium", ec))
      return fs::path(dir) / "chromium";
  return std::nullopt;
}

LoadedPage loadPage(const fs::path& chromium, const fs::path& page, const fs::path& work_dir,
                    PageClock clock, WindowSize window) {
  const fs::path profile = work_dir / "chromium-profile";
  fs::create_directories(profile);
  // --virtual-time-budget lets the load event and its scripts run before the DOM is dumped;
  // --no-sandbox because test containers often lack user namespaces; a private profile and HOME
  // keep the run from touching the user's.
  std::vector<std::string> argv = {"timeout",
                                   kBrowserTimeoutSeconds,
                                   chromium.string(),
                                   "--headless",
                                   "--no-sandbox",
                                   "--disable-gpu",
                                   "--no-first-run",
                                   "--enable-logging=stderr",
                                   "--v=0",
                                   "--virtual-time-budget=5000",
                                   "--user-data-dir=" + profile.string(),
                                   "--dump-dom",
                                   "file://" + reports::urlPath(fs::absolute(page).string())};
  if (clock == PageClock::kReal)
    argv.erase(std::find(argv.begin(), argv.end(), "--virtual-time-budget=5000"));
  if (window.width > 0 && window.height > 0)
    argv.insert(argv.begin() + 3, "--window-size=" + std::to_string(window.width) + "," +
                                      std::to_string(window.height));
  const CommandResult run = runProgram(argv, work_dir, {"HOME=" + profile.string()});
  return {run.exit_code, run.out, run.err};
}

std::string rootAttribute(const std::string& dom, const std::string& name) {
  const std::size_t html = dom.find("<html");
  if (html == std::string::npos) return {};
  const std::size_t end = dom.find('>', html);
  const std::string tag = dom.substr(html, end - html);
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  if (at == std::string::npos) return {};
  const std::size_t start = at + key.size();
  const std::string raw = tag.substr(start, tag.find('"', start) - start);
  // The serialiser escapes &, ", < and > in attribute values (and non-breaking spaces).
  std::string value;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    bool replaced = false;
    for (const auto& [entity, text] : {std::pair<const char*, const char*>{"&amp;", "&"},
                                       {"&quot;", "\""},
                                       {"&lt;", "<"},
                                       {"&gt;", ">"},
                                       {"&nbsp;", "\u00a0"}})
      if (raw.compare(i, std::strlen(entity), entity) == 0) {
        value += text;
        i += std::strlen(entity) - 1;
        replaced = true;
        break;
      }
    if (!replaced) value += raw[i];
  }
  return value;
}

std::string reportCheck(const std::string& dom) {
  return rootAttribute(dom, "data-report-check");
}

std::vector<std::string> consoleProblems(const std::string& log) {
  std::vector<std::string> problems;
  std::stringstream lines(log);
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos || line.find("Uncaught") != std::string::npos ||
        line.find("Failed to load resource") != std::string::npos)
      problems.push_back(line);
  return problems;
}

}  // namespace gib::test
