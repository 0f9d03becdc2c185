// The machine's host name, as results, store locks and logs record it.
#pragma once

#include <unistd.h>

#include <string>

namespace gib {

inline std::string hostName() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

}  // namespace gib
