// An entry of the reference store as files: entry.json (what was rendered, how, by which renderer
// version, when), its size on disk, and the render settings its spec stands for. Shared by the
// store's implementation and `gibench store list --json`.
#pragma once

#include "reference/progressive_renderer.h"
#include "reference/reference_store.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>

namespace gib::ref {

// entry.json's "format": bumped when a field changes meaning, so that an older gibench does not
// misread a newer entry. Format 2 added "reference_exr_hash"; entries of format 1 are still read
// (listed, collected) but are never current: without the hash their image cannot be checked.
inline constexpr const char* kStoreEntryFormat = "gibench-reference-entry/2";
inline constexpr const char* kStoreEntryFormatWithoutHash = "gibench-reference-entry/1";

// What entry.json holds: every field of `entry` except those that describe the copy on disk
// (dir, size_bytes, current).
nlohmann::ordered_json entryToJson(const StoreEntry& entry);

// Reads `<dir>/entry.json` and fills in dir, size_bytes and current. Throws gib::InputError naming
// the file when it is missing, malformed, of another format, or of another key than `dir`'s name.
StoreEntry readStoreEntry(const std::filesystem::path& dir);

// The sum of the sizes of the regular files under `dir`.
std::uint64_t directoryBytes(const std::filesystem::path& dir);

// The settings that render `spec` (with the renderer's default thread count).
RenderSettings renderSettingsOf(const ReferenceSpec& spec, bool progress);

}  // namespace gib::ref
