// `gibench store verify`: a stored reference against a fresh render of the same spec, by the
// per-pixel Z-test of the metrics layer. A harness operation on the store (it needs both the
// renderer and the statistics), so it lives here rather than in the reference layer, which
// neither measures nor judges its own images (docs/architecture.md, "Layers").
#pragma once

#include "reference/reference_store.h"

#include <cstdint>
#include <string>

namespace gib::suites {

struct VerifyResult {
  std::string key;
  bool passed = false;
  std::string problem;  // why not: "scene changed (hash …)", "Z-test: 123 of 49152 values fail"
  std::size_t tested = 0, failing = 0;
  double min_p_value = 1;
  double seconds = 0;
};

// The fewest samples per pixel, of the fresh render and of the stored entry, at which the test
// holds its significance. Below it the means of the light's edge blocks are too skewed for the t
// approximation: measured on 300 intact 32×24 Cornell box entries each
// (scripts/verify-false-failure-rate.sh, family-wise significance 0.01), fresh renders failed 13%
// of them at 8 spp, 4.7% at 16 and 2% at 24, against 0.7% at 32, 1.3% at 64 and 1% at 128; entries
// stored at 16 spp failed 6% at 64 spp, entries stored at 32 spp 0.3% (docs/harness.md).
inline constexpr long long kMinVerifySpp = 32;

// Throws gib::InputError naming --spp or --significance when a verification with these settings
// would not hold its significance: fewer than `min_spp` samples, a significance outside (0, 1).
// `min_spp` is kMinVerifySpp but for measuring the floor itself (`--allow-few-samples`), where it
// is 2, the fewest with a variance.
void checkVerifySettings(long long spp, double significance, long long min_spp = kMinVerifySpp);

// Re-renders the entry's scene at `spp` samples with a seed of its own and Z-tests it against the
// stored mean and variance at family-wise `significance` (metrics/z_test.h): a changed renderer
// or scene fails, and so does an entry stored at fewer than `min_spp` samples, which the test
// cannot vouch for. Throws gib::InputError for bad settings and when the scene cannot be loaded.
VerifyResult verifyStoreEntry(const ref::ReferenceStore& store, const ref::StoreEntry& entry,
                              std::uint32_t spp, double significance = 0.01, bool progress = false,
                              long long min_spp = kMinVerifySpp);

}  // namespace gib::suites
