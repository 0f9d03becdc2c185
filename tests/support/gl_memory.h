// What GL allocated, asked of GL: for checking a memory figure against the storage GL reports
// rather than against the figure's own formula.
#pragma once

#include "realtime/gl/objects.h"

#include <cstdint>

namespace gib::test {

// The bytes of level 0 of a 2D, 2D-array or 3D `texture`: its width, height and depth (layers)
// and the bits of each of its components, all as GL reports them. Needs a current GL context.
std::int64_t allocatedTextureBytes(const rt::gl::Texture& texture);

}  // namespace gib::test
