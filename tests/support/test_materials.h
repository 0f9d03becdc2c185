// The materials tests build scenes of: a grey Lambertian, a perfect mirror (R = 1 at every
// angle) and a smooth glass of a given index, each named by its kind.
#pragma once

#include "scene/scene.h"

namespace gib::test {

inline scene::Material lambertMaterial(float albedo) {
  scene::Material m;
  m.name = "lambert";
  m.diffuse = scene::Rgb(albedo);
  return m;
}

inline scene::Material perfectMirrorMaterial() {
  scene::Material m;
  m.name = "mirror";
  m.type = scene::MaterialType::kMirror;
  m.perfect_mirror = true;
  return m;
}

inline scene::Material glassMaterial(float ior) {
  scene::Material m;
  m.name = "glass";
  m.type = scene::MaterialType::kGlass;
  m.ior = ior;
  return m;
}

}  // namespace gib::test
