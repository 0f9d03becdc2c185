// Bad input from a user: an unknown name, a malformed file, an impossible parameter, a missing
// file. The command line turns it into one line on stderr and exit code 2 (docs/architecture.md,
// "Errors").
#pragma once

#include <stdexcept>
#include <string>

namespace gib {

// The message names the problem and the fix, e.g.
// "unknown scene 'cornel'; `gibench list scenes` lists the built-in scenes".
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace gib
