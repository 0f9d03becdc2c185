#include "realtime/techniques/stochastic_radiosity/shooter_visibility.h"

#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

namespace gib::rt {

namespace {

// Fractions of the scene's diagonal: the near plane, and the shooter's lift off its surface
// (below the near plane, so a surface meeting the shooter at a corner is drawn from its start).
constexpr float kNearFraction = 1e-4f;
constexpr float kLiftFraction = 1e-5f;
constexpr float kNothingDrawn = 1e30f;  // distance where no surface was drawn: visible

}  // namespace

ShooterVisibility::ShooterVisibility(ShooterProjection projection, int map_size, float extent)
    : projection_(projection),
      size_(map_size),
      near_(kNearFraction * extent),
      far_(2.0f * extent),
      lift_(kLiftFraction * extent) {
  const int layers = projection == ShooterProjection::kHemicube ? 5 : 1;
  distance_ = gl::Texture::make2DArray(GL_R32F, map_size, map_size, layers);
  distance_.setFilter(GL_NEAREST, GL_NEAREST);
  depth_ = gl::Texture::make2DArray(GL_DEPTH_COMPONENT32F, map_size, map_size, layers);
  // Every layer behind one framebuffer: one clear and one instanced draw for the five faces.
  framebuffer_.attachColor(0, distance_);
  framebuffer_.attachDepth(depth_);
  framebuffer_.setDrawBuffers(1);
  framebuffer_.checkComplete();
  program_ =
      gl::buildLayeredProgram({"realtime/techniques/stochastic_radiosity/visibility.vert.glsl",
                               "realtime/techniques/stochastic_radiosity/visibility.geom.glsl",
                               "realtime/techniques/stochastic_radiosity/visibility.frag.glsl"},
                              defines());
  program_.set("u_near", near_);
  program_.set("u_far", far_);
  program_.set("u_shooter_lift", lift_);
}

std::string ShooterVisibility::defines() const {
  return projection_ == ShooterProjection::kHemicube ? "#define HEMICUBE\n" : "";
}

void ShooterVisibility::render(const atlas::AtlasMesh& mesh) const {
  program_.use();
  // Every surface occludes, whichever side faces the shooter (no culling). The hemisphere's back
  // half-space, or the rows above a side face's half, are clipped.
  const gl::PipelineScope state({
      .depth_test = GL_LESS,
      .clip_distances = 1,
      .viewport = gl::PixelRect{0, 0, size_, size_},
  });
  const float clear_distance[4] = {kNothingDrawn, 0, 0, 0};
  const float clear_depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, clear_distance);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &clear_depth);
  framebuffer_.bind();
  mesh.draw(projection_ == ShooterProjection::kHemicube ? 5 : 1);
}

void ShooterVisibility::bindForLookup() const {
  distance_.bind(gpu::kVisibilityUnit);
}

void ShooterVisibility::setLookupConstants(const gl::Program& program) const {
  program.set("u_map_size", size_);
  program.set("u_shooter_lift", lift_);
}

}  // namespace gib::rt
