// The OBJ files of a scene file's [[meshes]] (format: scene_file.h): triangles, and the shading
// normals of `vn` lines when asked for.
#pragma once

#include "scene/scene_file_reader.h"

#include <filesystem>

namespace gib::scene {

// The triangles of the OBJ file at `path`; `where` is the [[meshes]] entry's `file` value, which
// errors point at. With `read_normals`, an OBJ whose faces give normals (f v//vn) yields one unit
// normal per vertex: a position used with different normals becomes one vertex per normal. An
// OBJ with some corners without a normal, an index beyond its `vn` lines or a zero normal is an
// error; one without any normals is shaded flat.
Mesh loadObjMesh(const SceneTableReader& t, const toml::node& where,
                 const std::filesystem::path& path, bool read_normals);

}  // namespace gib::scene
