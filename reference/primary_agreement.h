// Whether a rasteriser and the reference see the same surface through each pixel centre
// (docs/rendering.md, "Pixel sampling"). A pixel-centre reference spends all its samples on the
// lighting of its camera ray's hit; a technique's frame is measured against it, so where the two
// see different surfaces (a silhouette or a crease the rasteriser's edge rules cut differently
// from the ray tracer's) the difference is geometry, not lighting. Those pixels are counted and
// shown as a mask, not hidden.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

#include <glm/vec2.hpp>

#include <cstddef>

namespace gib::ref {

// A pixel agrees when both see nothing, or both see a surface of the same material with the same
// geometric normal (cosine above 0.999) at the same distance (within 1e-3 relative). Triangles
// that share a plane and a material (the two halves of a quad) are one surface here: a rasteriser
// and a ray tracer may split their shared edge differently without changing any lighting.
struct PrimaryAgreement {
  image::Image mask;  // one channel: 1 where they disagree, 0 elsewhere
  std::size_t pixels = 0;
  std::size_t hits = 0;  // pixels whose ray hits a surface
  std::size_t disagreements = 0;
  double disagreementFraction() const { return pixels ? double(disagreements) / pixels : 0.0; }
};

// `position` and `normal` are RGBA images of what the rasteriser saw (rt::PrimarySurfaces):
// world position with the distance in w (negative: no surface), and the normal with the material
// index in w. Each pixel (x, y) is compared with Embree's camera ray through the image point
// (x, y) + `offset` ((0.5, 0.5): the pixel centre, as a pixel-centre reference traces it).
// Throws std::invalid_argument when the images differ in size or are not RGBA.
PrimaryAgreement comparePrimarySurfaces(const scene::Scene& scene, const image::Image& position,
                                        const image::Image& normal,
                                        glm::vec2 offset = glm::vec2(0.5f));

}  // namespace gib::ref
