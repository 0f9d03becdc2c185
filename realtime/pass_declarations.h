// The passes a technique's frames and iterations may contain, declared by path before anything
// runs (Falcor's habit: a pass declares, then executes). The declaration is an interface: suites
// name passes in [[paper]] and [[chart]] entries ("frame/lights/shadow map", "iteration/update"),
// and a suite that names a pass its technique does not declare is refused when it loads; the
// runner refuses a profile with a pass that was not declared, so the declaration cannot drift
// from what the code times. A pass's name (the last part of its path) is unique under its root,
// so a suite may also name a pass by its name alone.
#pragma once

#include "realtime/gl/pass_record.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

// "frame/lights/shadow map" from {"frame", "lights", "shadow map"}.
std::string passPath(std::initializer_list<std::string_view> names);

struct DeclaredPass {
  std::string path;         // "frame/lights/shadow map"
  std::string description;  // one line, for `gibench list techniques` and the technique's README
};

class PassDeclarations {
 public:
  // Declares the root "frame".
  PassDeclarations();

  // Declares `path` below an already declared parent (or a root). Throws std::logic_error when the
  // parent is not declared, or when the name is already declared elsewhere under the same root:
  // both are mistakes in the technique's code, not in anyone's input.
  PassDeclarations& add(std::string path, std::string description);

  const std::vector<DeclaredPass>& passes() const { return passes_; }
  // The pass with this path, or with this name ("shadow map" finds "frame/lights/shadow map");
  // nullptr when there is none.
  const DeclaredPass* find(std::string_view path_or_name) const;
  bool declares(std::string_view path_or_name) const { return find(path_or_name) != nullptr; }

 private:
  std::vector<DeclaredPass> passes_;
};

}  // namespace gib::rt
