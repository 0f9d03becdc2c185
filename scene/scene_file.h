// Scene files: a TOML file that places OBJ meshes and defines materials, lights, the camera and the
// sky of a scene (docs/architecture.md, "Scenes": users bring their own scenes).
//
// Format (units as in scene.h: radiance in linear Rec.709 RGB, spot intensity in W/sr,
// directional irradiance in W/m², angles in degrees, lengths in scene units):
//
//   name = "my_room"                      # optional, default: the file's stem
//
//   [camera]                              # required
//   position = [278.0, 273.0, -800.0]
//   look_at = [278.0, 273.0, 0.0]
//   up = [0.0, 1.0, 0.0]                  # optional, default +y
//   vertical_fov_deg = 39.3077            # in (0, 180)
//
//   [image]                               # optional: the default resolution of renders
//   width = 512                           # optional, default 512
//   height = 512                          # optional, default 512
//
//   [materials.white]                     # one table per material; the name is the key
//   type = "lambert"                      # "lambert" | "phong"
//   diffuse = [0.7, 0.7, 0.7]             # reflectance in [0, 1]
//
//   [materials.gloss]
//   type = "phong"                        # normalised modified Phong (scene.h)
//   diffuse = [0.3, 0.3, 0.3]
//   specular = [0.4, 0.4, 0.4]            # diffuse + specular <= 1 in every channel
//   exponent = 50.0                       # >= 0
//
//   [materials.lamp]
//   type = "lambert"
//   diffuse = [0.78, 0.78, 0.78]
//   emission = [17.0, 12.0, 4.0]          # optional: radiance of a one-sided emitter
//
//   [materials.gold]
//   type = "mirror"                       # an ideal specular conductor (scene.h)
//   metal = "gold"                        # perfect | aluminium | silver | gold | copper
//                                         # (scene/metals.h), or instead of metal:
//   # n = [0.14, 0.43, 1.38]              # the index n + iκ per channel: n > 0
//   # k = [3.70, 2.46, 1.91]              # κ >= 0 (both n and k, never with metal)
//
//   [materials.glass]
//   type = "glass"                        # a smooth dielectric; its meshes closed, facing out
//   ior = 1.5                             # optional, default 1.5, in [1, 4]
//   absorption = [0.0, 0.0, 0.0]          # optional: Beer–Lambert coefficient per scene unit
//
//   [[meshes]]                            # any number of meshes
//   file = "room.obj"                     # relative to the TOML file
//   material = "white"                    # a name from [materials]
//   translate = [0.0, 0.0, 0.0]           # optional, default 0
//   scale = 1.0                           # optional, a number or [x, y, z], > 0; default 1
//   flip_normals = false                  # optional: reverse the winding (the emitting side)
//   smooth = true                         # optional: shade with the OBJ's vn normals, if any
//
//   [[lights]]                            # any number of spot and directional lights
//   type = "spot"
//   position = [278.0, 548.0, 279.0]
//   direction = [0.0, -1.0, 0.0]          # the cone's axis, normalised on load
//   intensity = [100.0, 100.0, 100.0]     # W/sr on the axis
//   cone_angle_deg = 30.0                 # half angle, in (0, 180]
//   falloff_exponent = 2.0                # optional, default 0: I(θ) = intensity·cos(θ)^n
//
//   [[lights]]
//   type = "directional"
//   direction = [0.0, -1.0, 0.0]          # the direction the light travels, normalised on load
//   irradiance = [1.0, 1.0, 1.0]          # W/m² on a plane perpendicular to it
//
//   [sky]                                 # optional
//   radiance = [0.1, 0.1, 0.1]            # optional, default black
//
//   [environment]                         # optional; not with a [sky] of non-zero radiance
//   file = "sky.exr"                      # latitude-longitude EXR, relative to this file
//   rotation = 0.0                        # optional, degrees about +y from +x towards -z
//   intensity = 1.0                       # optional, >= 0, scales the texels
//
// OBJ files: every face is triangulated; vertex positions are read, and the normals of `vn` lines
// when the faces give them (f v//vn, f v/vt/vn) and `smooth` is true: then every face corner needs
// a normal and a position used with different normals becomes one vertex per normal (exact, not
// averaged); without normals a mesh is shaded flat. Texture coordinates and the OBJ's own
// materials (usemtl, mtllib) are ignored, since each [[meshes]] entry has exactly one material.
// A mesh's vertices are scaled, then translated; its normals follow the scale (inverse transpose)
// and turn with flip_normals. Numbers may be integers or floats; NaN and
// infinities are rejected everywhere. Materials keep the order of the file.
//
// Strictness: a key that is not listed above (or not allowed for the material's or light's
// type) is an error, so that a mistyped key is never silently ignored.
#pragma once

#include "scene/scene.h"

#include <filesystem>

namespace gib::scene {

// Loads and validates a scene file. Every problem throws gib::InputError with one line
// "<file>:<line>:<column>: <problem>; <fix>" (the position is that of the offending key or value
// in the TOML file, or of the table that lacks a key); problems found by validateScene() on the
// finished scene, which have no position, read "<file>: <problem>". The scene's provenance is
// "scene file <absolute path>".
Scene loadSceneFile(const std::filesystem::path& toml_path);

}  // namespace gib::scene
