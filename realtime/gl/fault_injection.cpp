#include "realtime/gl/fault_injection.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <cstdlib>
#include <string>
#include <string_view>

namespace gib::rt::gl {

namespace {

constexpr std::string_view kNames[] = {"shader-compile", "texture-out-of-memory", "context"};

}  // namespace

bool glFaultInjected(GlFault fault) {
  const char* value = std::getenv("GIB_GL_FAULT");
  if (!value) return false;
  bool injected = false;
  std::string_view rest = value;
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    const std::string_view name = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    if (name.empty()) continue;
    bool known = false;
    for (std::size_t i = 0; i < std::size(kNames); ++i)
      if (name == kNames[i]) {
        known = true;
        if (i == std::size_t(fault)) injected = true;
      }
    if (!known)
      throw InputError(
          fmt::format("GIB_GL_FAULT names no fault '{}'; give shader-compile, "
                      "texture-out-of-memory or context, or unset it",
                      name));
  }
  return injected;
}

}  // namespace gib::rt::gl
