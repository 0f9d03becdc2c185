#include "common/stall_point.h"

#include "common/input_error.h"

#include <fmt/format.h>
#include <fnmatch.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace gib {

void stallPoint(const std::string& name) {
  const char* pattern = std::getenv("GIB_STALL_AT");
  if (!pattern || !*pattern || fnmatch(pattern, name.c_str(), 0) != 0) return;
  long milliseconds = 60000;
  if (const char* value = std::getenv("GIB_STALL_MS")) {
    char* end = nullptr;
    milliseconds = std::strtol(value, &end, 10);
    if (end == value || *end != '\0' || milliseconds < 0)
      throw InputError(fmt::format(
          "GIB_STALL_MS is '{}', not a number of milliseconds; give one such as 5000, or unset it",
          value));
  }
  // Unbuffered and flushed: the test reading stderr acts on this line while the process sleeps.
  std::fprintf(stderr, "gibench: stalled at %s\n", name.c_str());
  std::fflush(stderr);
  std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
}

}  // namespace gib
