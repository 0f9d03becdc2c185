// The notes' picture of the cache (course notes 001, the zones of influence): every pixel in the
// colour of the record that weighs most there, each record's own pixel marked white, pixels no
// record reaches black. An auxiliary image of both irradiance cache techniques.
#pragma once

#include "image/image.h"
#include "realtime/irradiance_cache/record_placement.h"
#include "realtime/technique.h"

#include <span>

namespace gib::rt {

// Pixel (0,0) at the top left, like every image the harness writes.
image::Image zoneIllustration(const SurfaceImage& surfaces, const CameraTransform& camera,
                              std::span<const gpu::IrradianceRecord> records, float accuracy);

// The illustration as both techniques' auxiliary image "zones", and its declaration.
AuxiliaryImage zonesAuxiliaryImage(const SurfaceImage& surfaces, const CameraTransform& camera,
                                   std::span<const gpu::IrradianceRecord> records, float accuracy);
DeclaredOutput zonesImageDeclaration();

}  // namespace gib::rt
