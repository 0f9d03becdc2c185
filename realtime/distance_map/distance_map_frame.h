// The part of a frame every distance-map technique draws before its own pass (book §6.1, §7.3):
// the camera's surfaces (SurfaceLighting), the maps' views, the same light-sample batches lighting
// both, and the maps composed. Its pass names are the block's, declared once here, so that every
// technique that composes the block times the same passes under the same names.
#pragma once

#include "image/image.h"
#include "realtime/distance_map/distance_maps.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/pass_declarations.h"
#include "realtime/technique.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

inline constexpr std::string_view kMapViewsPass = "map views";  // the maps' G-buffer
inline constexpr std::string_view kMapLightPass = "map light";  // the batches' light in them
inline constexpr std::string_view kComposeMapsPass = "compose maps";
inline constexpr std::string_view kDownsamplePass = "downsample";  // the maps averaged (§7.3)

// What each of the block's passes does, in the words of the technique that declares them.
struct DistanceMapPassDescriptions {
  std::string map_views;
  std::string compose_maps;
};

// SurfaceLighting's passes with the maps' light among the batches' views, then the maps' views
// and their composing under "frame".
void declareDistanceMapPasses(PassDeclarations& passes,
                              const DistanceMapPassDescriptions& descriptions);

// The camera's G-buffer and emission, the maps' views, the batches' direct light into the camera
// and the maps' views, then the maps composed `rounds` times.
void drawSurfacesAndMaps(SurfaceLighting& surface_lighting, const GpuScene& scene,
                         DistanceMaps& maps, int rounds, Frame& frame);

// Draws `draw` (a full-screen pass of a technique built with its capture outputs) into a
// width × height RGBA32F colour target and `extra` more, all cleared to zero, and reads them back
// (pixel (0,0) at the top left; the colour's RGB, the others' RGBA): what a technique's auxiliary
// images capture after the last frame.
std::vector<image::Image> drawCaptured(int width, int height, int extra,
                                       const std::function<void()>& draw);

// The radiance of a cube-map array unfolded as the book's Fig. 6.3 lays one out: cube k in row k,
// its faces +x −x +y −y +z −z from the left.
image::Image unfoldCubes(const gl::Texture& cubes);

}  // namespace gib::rt
