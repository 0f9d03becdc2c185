#include "realtime/pass_declarations.h"

#include <fmt/format.h>

#include <stdexcept>

namespace gib::rt {

namespace {

std::string_view rootOf(std::string_view path) {
  return path.substr(0, path.find('/'));
}

std::string_view nameOf(std::string_view path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

std::string_view parentOf(std::string_view path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string_view::npos ? std::string_view() : path.substr(0, slash);
}

}  // namespace

std::string passPath(std::initializer_list<std::string_view> names) {
  std::string path;
  for (std::string_view name : names) {
    if (!path.empty()) path += '/';
    path += name;
  }
  return path;
}

PassDeclarations::PassDeclarations() {
  passes_.push_back({std::string(kFramePass), "the whole frame"});
}

PassDeclarations& PassDeclarations::add(std::string path, std::string description) {
  const std::string_view parent = parentOf(path);
  const bool root = parent.empty();
  if (root && path != kFramePass && path != kIterationPass)
    throw std::logic_error(
        fmt::format("pass '{}' is not under '{}' or '{}'", path, kFramePass, kIterationPass));
  if (!root && !declares(parent))
    throw std::logic_error(
        fmt::format("pass '{}' is declared before its parent '{}'", path, parent));
  for (const DeclaredPass& pass : passes_)
    if (rootOf(pass.path) == rootOf(path) && nameOf(pass.path) == nameOf(path))
      throw std::logic_error(fmt::format("pass name '{}' is declared twice: '{}' and '{}'",
                                         nameOf(path), pass.path, path));
  passes_.push_back({std::move(path), std::move(description)});
  return *this;
}

const DeclaredPass* PassDeclarations::find(std::string_view path_or_name) const {
  for (const DeclaredPass& pass : passes_)
    if (pass.path == path_or_name) return &pass;
  // A bare name means a pass of a frame, as quantities use it ("shadow map" for
  // "frame/lights/shadow map"); iteration passes are named with their root.
  if (path_or_name.find('/') != std::string_view::npos) return nullptr;
  for (const DeclaredPass& pass : passes_)
    if (rootOf(pass.path) == kFramePass && nameOf(pass.path) == path_or_name) return &pass;
  return nullptr;
}

}  // namespace gib::rt
