// Depth peeling (book §10.4; Everitt's "interactive order-independent transparency"): the scene
// drawn by an orthographic projection again and again, each pass keeping, per pixel, the nearest
// surface behind the one the previous pass kept, so that the layers together hold every surface a
// pixel's ray crosses, in order. A pixel is then a global ray of a bundle of parallel rays
// (§10.4: "global ray bundles"), and consecutive layers along it are consecutive surfaces.
//
// A shared block: the obscurances technique pairs consecutive layers into (patch, occluder); the
// multi-layer refraction and caustics of Ch. 6 read the same layers.
//
// The comparison that peels: a fragment of pass k survives when its depth exceeds the depth kept
// by pass k − 1 at its pixel by more than an epsilon (the book's `depth < lastDepth` would keep
// the surface found last, which then wins the depth test again, forever). The epsilon is a
// fraction kPeelEpsilonFraction of the bundle's depth range (the scene's bounding-sphere
// diameter): it lies far above the rounding of an interpolated depth (a few ulps, ~1e-7 of the
// range) and far below any distance that matters to a fall-off ρ(d) (ρ of 1e-5 of the diameter is
// below 1% for any d_max of 1% of the diameter or more). Its effect: two surfaces that a ray
// crosses less than an epsilon apart (a wall and the wall it meets, within that distance of the
// corner line) count as one, the nearer (tested).
#pragma once

#include "image/image.h"
#include "realtime/atlas/atlas_mesh.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/program.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace gib::rt {

inline constexpr float kPeelEpsilonFraction = 1e-5f;

// One bundle of parallel rays: the orthographic view of the scene's bounding sphere along
// `direction`, its pixel grid shifted by `offset` pixels (each component in [0, 1)): a uniform
// random offset makes the number of rays crossing a patch of area A an unbiased A·|cos θ|/s²
// (s: pixelSize), whatever the patch's place.
struct PeelBundle {
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit: the rays' direction, from the projection plane
  glm::vec2 offset{0.0f};
  // Which way is up in the layers' pictures (the rays do not depend on it): the projection's y
  // axis is `up` made perpendicular to the direction (any other axis where they are parallel).
  glm::vec3 up{0.0f, 1.0f, 0.0f};
};

// The projection of a bundle: where a world point lands (clip space) and its depth along the
// bundle.
struct PeelProjection {
  glm::mat4 clip_from_world{1.0f};
  glm::vec3 plane_origin{0.0f};  // a point of the projection plane (depth 0)
  glm::vec3 direction{0.0f};
};

class DepthPeeler {
 public:
  // `resolution`: pixels (rays) per side of a bundle; `max_layers`: layers peeled at most per
  // bundle (a ray crossing more surfaces loses the farthest). The bundle covers the sphere of
  // `centre` and `radius` (the scene's bounding sphere) whatever its direction and offset.
  DepthPeeler(int resolution, int max_layers, glm::vec3 centre, float radius);

  int resolution() const { return resolution_; }
  int maxLayers() const { return max_layers_; }
  // The side s of a pixel in scene units: the rays of a bundle are s apart.
  float pixelSize() const { return pixel_size_; }
  // The depth difference below which two surfaces are one layer (kPeelEpsilonFraction of the
  // depth range).
  float epsilon() const { return epsilon_; }
  PeelProjection projection(const PeelBundle& bundle) const;

  // Peels `mesh` along the bundle into layers() (GL state: the caller's framebuffer binding is
  // left changed). Returns the number of layers that hold a surface in some pixel: peeling stops
  // at the first pass in which no fragment survives (an occlusion query), or at max_layers.
  int peel(const atlas::AtlasMesh& mesh, const PeelBundle& bundle);

  // The layers of the last peel: a GL_RGBA32F 2D array of max_layers layers, resolution² texels,
  // records of depth_peeling_shared.h; layers at and after the count returned are empty.
  const gl::Texture& layers() const { return layers_; }
  int layerCount() const { return layer_count_; }

  // Read back, for tests and figures: how many layers hold a surface at each pixel (row 0 at the
  // bottom, GL's order), and one layer as a picture of its depth (near white, far dark, empty
  // black; top row first), book Fig. 10.9.
  std::vector<int> surfacesPerPixel() const;
  std::vector<glm::vec4> layerTexels(int layer) const;  // row 0 at the bottom
  image::Image layerDepthImage(int layer) const;

 private:
  int resolution_, max_layers_;
  glm::vec3 centre_;
  float radius_, pixel_size_, epsilon_;
  gl::Texture layers_;
  std::array<gl::Texture, 2> depth_;  // the depth of the layer peeled last, ping-pong
  gl::Texture depth_buffer_;
  gl::Framebuffer framebuffer_;
  gl::Query any_samples_;
  gl::Program program_;
  int layer_count_ = 0;
};

}  // namespace gib::rt
