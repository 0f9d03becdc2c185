// Debian's Chromium, headless, for the report tests: load a page from disk, let its scripts run,
// and read back the DOM and the browser's log.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gib::test {

// /usr/bin/chromium, else `chromium` on PATH; nullopt when neither exists.
std::optional<std::filesystem::path> findChromium();

struct LoadedPage {
  int exit_code = -1;
  std::string dom;  // the serialised DOM after the load event and the scripts
  std::string log;  // the browser's stderr (console messages are logged there)
};

// How a page's scripts see time: a tests' 5-second virtual budget (timers run at once, the DOM is
// dumped when they are done), or real time (the DOM is dumped after the load event; for
// measuring how long a page takes to load).
enum class PageClock { kVirtual, kReal };

// A browser window's size in pixels (headless Chromium's window includes about 140 pixels of
// chrome above the page); 0 × 0: headless Chromium's default, whose page is 780 × 437 pixels.
struct WindowSize {
  int width = 0;
  int height = 0;
};

// Opens `page` (an absolute path) with a fresh profile under `work_dir`; the browser is killed
// after a minute of real time.
LoadedPage loadPage(const std::filesystem::path& chromium, const std::filesystem::path& page,
                    const std::filesystem::path& work_dir, PageClock clock = PageClock::kVirtual,
                    WindowSize window = {});

// The value of an attribute of the <html> element of a dumped DOM, entities decoded ("" when
// absent).
std::string rootAttribute(const std::string& dom, const std::string& name);

// The value of data-report-check on the <html> element of a dumped DOM ("" when absent).
std::string reportCheck(const std::string& dom);

// Lines of a browser log that show a page problem: console messages (a report page logs none, so
// any is unexpected: this Chromium logs every level as INFO:CONSOLE), uncaught exceptions and
// failed loads.
std::vector<std::string> consoleProblems(const std::string& log);

}  // namespace gib::test

// Skips without a browser, unless the environment says the browser is part of the test run
// (scripts/test.sh sets GIB_REQUIRE_BROWSER=1).
#define GIB_REQUIRE_CHROMIUM(chromium)                                                     \
  const std::optional<std::filesystem::path> chromium = ::gib::test::findChromium();       \
  if (!chromium) {                                                                         \
    const char* required = std::getenv("GIB_REQUIRE_BROWSER");                             \
    if (required && std::string_view(required) == "1")                                     \
      FAIL() << "GIB_REQUIRE_BROWSER=1 but no chromium (/usr/bin/chromium or on PATH); "   \
                "scripts/install-deps.sh installs it";                                     \
    GTEST_SKIP() << "no chromium (/usr/bin/chromium or on PATH); scripts/install-deps.sh " \
                    "installs it";                                                         \
  }
