// The machine cannot do what was asked although the input is fine: a GL driver that rejects a
// shader, GPU memory that runs out. The command line prints it as one line and exits with code 1;
// a suite records the job as failed and runs the others (docs/architecture.md, "Errors"). A
// machine with no EGL or no GL 4.5 context at all is an InputError (exit 2) whose fix is to
// install Mesa (realtime/gl/context.cpp).
#pragma once

#include <stdexcept>
#include <string>

namespace gib {

// The message names what failed and the cause, e.g. "technique 'direct': out of GPU memory for a
// 4096x4096x6 texture of format 0x81a6 (384 MiB)".
class EnvironmentError : public std::runtime_error {
 public:
  explicit EnvironmentError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace gib
