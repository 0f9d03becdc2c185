// Small reference store entries for the store's tests (library and command line): renders that
// take a fraction of a second, and the ways a stored entry goes wrong.
#pragma once

#include "reference/reference_store.h"

#include <filesystem>
#include <string>

namespace gib::test {

// `scene` at size×size pixels, `spp` samples, seed 0, all paths.
ref::ReferenceSpec smallReferenceSpec(const std::string& scene = "cornell", int size = 24,
                                      std::uint32_t spp = 64);

// Obtains `spec` (loading its scene) from a store at `root`.
ref::StoredReference obtainReference(const std::filesystem::path& root,
                                     const ref::ReferenceSpec& spec);

// Rewrites the entry's reference.exr with the mean multiplied by `factor` (variance, other
// layers and metadata kept) and records its content hash: what a changed renderer would have
// stored.
void scaleStoredMean(const ref::StoreEntry& entry, float factor);

// Rewrites the renderer_version field of the entry's entry.json: an entry made by another build.
void setStoredRendererVersion(const ref::StoreEntry& entry, const std::string& version);

// Sets one string field of the entry's entry.json.
void setStoredEntryField(const ref::StoreEntry& entry, const std::string& field,
                         const std::string& value);

// Writes `text` into `path`, creating its directory.
void writeFile(const std::filesystem::path& path, const std::string& text);

}  // namespace gib::test
