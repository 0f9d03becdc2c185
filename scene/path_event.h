// The alphabet of path expressions (scene/path_expression.h): what happens at a vertex of a light
// path, in Heckbert's notation as the book's §12.2 uses it.
#pragma once

#include <cstdint>

namespace gib::scene {

// L: emission at a light; D: a diffuse or glossy surface (Lambert, and Phong's glossy lobe);
// S: an ideal specular surface (mirror, glass); P: scattering in a participating medium; E: the
// eye. Read from the light to the eye, every light path is L, then D, S or P vertices, then E.
enum class PathEvent : std::uint8_t { kLight, kDiffuse, kSpecular, kMedium, kEye };  // L D S P E

}  // namespace gib::scene
