// Named metals for mirror materials (docs/scenes.md, "Metals"): the complex index of refraction
// n + iκ of each metal at three wavelengths standing for the Rec.709 primaries, from which the
// mirror's Fresnel reflectance follows (scene/fresnel_shared.h), and the perfect reflector of the
// tests.
#pragma once

#include "scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace gib::scene {

// The wavelengths, in nm, at which the red, green and blue channels sample a metal's index: rows
// of Johnson & Christy's table (1972), the nearest to the 650/550/450 nm usually taken for the
// Rec.709 primaries, so that the noble metals' values are theirs unchanged.
inline constexpr float kMetalWavelengthsNm[3] = {659.5f, 548.6f, 450.9f};

struct Metal {
  std::string_view name;
  bool perfect = false;  // reflects everything at every angle (R = 1); n and κ are unused
  Rgb n{1.0f};           // real part of the index, per channel
  Rgb k{0.0f};           // extinction coefficient κ, per channel
  std::string_view source;
};

// Every named metal: "perfect", then aluminium, silver, gold and copper.
const std::vector<Metal>& metals();

// The metal of that name, or nullptr.
const Metal* findMetal(std::string_view name);

// The names in that order: a scene parameter's choices, the list an error message gives.
std::vector<std::string> metalNames();

// A mirror material of that metal (MaterialType::kMirror, black diffuse and no emission).
Material mirrorMaterial(std::string name, const Metal& metal);

}  // namespace gib::scene
