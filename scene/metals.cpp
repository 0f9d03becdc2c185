#include "scene/metals.h"

#include <utility>

namespace gib::scene {

const std::vector<Metal>& metals() {
  // Red, green, blue at kMetalWavelengthsNm (659.5, 548.6, 450.9 nm). The noble metals are rows of
  // P. B. Johnson and R. W. Christy, "Optical constants of the noble metals", Phys. Rev. B 6,
  // 4370–4379 (1972), Table I, as the refractiveindex.info database holds them (main/Ag, Au, Cu,
  // "Johnson"). Aluminium, which Johnson and Christy did not measure, is from A. D. Rakić,
  // "Algorithm for the determination of intrinsic optical constants of metal films: application
  // to aluminum", Appl. Opt. 34, 4755–4767 (1995) (refractiveindex.info main/Al "Rakic"),
  // interpolated linearly in wavelength between its rows to the same three wavelengths.
  static const std::vector<Metal> table = {
      {"perfect", true, Rgb(1.0f), Rgb(0.0f), "a perfect reflector (R = 1), for tests"},
      {"aluminium", false, Rgb(1.6235f, 1.0092f, 0.6364f), Rgb(7.7998f, 6.6111f, 5.4652f),
       "Rakić 1995"},
      {"silver", false, Rgb(0.05f, 0.06f, 0.04f), Rgb(4.483f, 3.586f, 2.657f),
       "Johnson & Christy 1972"},
      {"gold", false, Rgb(0.14f, 0.43f, 1.38f), Rgb(3.697f, 2.455f, 1.914f),
       "Johnson & Christy 1972"},
      {"copper", false, Rgb(0.22f, 1.02f, 1.24f), Rgb(3.747f, 2.577f, 2.397f),
       "Johnson & Christy 1972"},
  };
  return table;
}

const Metal* findMetal(std::string_view name) {
  for (const Metal& metal : metals())
    if (metal.name == name) return &metal;
  return nullptr;
}

std::vector<std::string> metalNames() {
  std::vector<std::string> names;
  for (const Metal& metal : metals()) names.emplace_back(metal.name);
  return names;
}

Material mirrorMaterial(std::string name, const Metal& metal) {
  Material m;
  m.name = std::move(name);
  m.type = MaterialType::kMirror;
  m.perfect_mirror = metal.perfect;
  // A perfect mirror keeps the defaults (n = 1, κ = 0), which validation accepts and the hash
  // records unchanged whatever the table says.
  if (!metal.perfect) {
    m.conductor_n = metal.n;
    m.conductor_k = metal.k;
  }
  return m;
}

}  // namespace gib::scene
