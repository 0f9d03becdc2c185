#include "suites/store_verification.h"

#include "common/input_error.h"
#include "common/splitmix.h"
#include "metrics/z_test.h"
#include "reference/progressive_renderer.h"
#include "reference/reference_store_entry.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

namespace gib::suites {

void checkVerifySettings(long long spp, double significance, long long min_spp) {
  if (spp < std::max(min_spp, 2LL))
    throw InputError(fmt::format(
        "--spp {} is too few for the Z-test: below {} samples intact entries fail more often than "
        "the significance says; give {} or more",
        spp, std::max(min_spp, 2LL), std::max(min_spp, 2LL)));
  if (!(significance > 0 && significance < 1))
    throw InputError(
        fmt::format("--significance {} is not in (0, 1); 0.01 is usual", significance));
}

VerifyResult verifyStoreEntry(const ref::ReferenceStore& store, const ref::StoreEntry& entry,
                              std::uint32_t spp, double significance, bool progress,
                              long long min_spp) {
  checkVerifySettings(spp, significance, min_spp);
  const auto start = std::chrono::steady_clock::now();
  VerifyResult result;
  result.key = entry.key;
  auto finish = [&] {
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  };

  // Step 1: the scene must still be the one that was rendered, or nothing can be concluded.
  scene::Scene scene = scene::loadScene(entry.spec.scene, entry.spec.scene_parameters);
  scene::applyLens(scene.camera, entry.spec.lens, "lens.radius", "lens.focus_distance");
  if (const std::string hash = scene::hashScene(scene); hash != entry.scene_hash) {
    result.problem =
        fmt::format("scene changed since the reference was stored (hash {} then, {} now)",
                    entry.scene_hash.substr(0, 12), hash.substr(0, 12));
    return finish();
  }
  const std::optional<ref::StoredReference> stored = store.find(entry.key);
  if (!stored) {
    result.problem = "the entry is no longer in the store";
    return finish();
  }
  if (stored->variance.pixelCount() == 0) {
    result.problem = "stored at 1 sample per pixel (one replica): no variance to test against";
    return finish();
  }
  if (entry.spec.spp < min_spp) {
    result.problem = fmt::format(
        "stored at {} spp, too few for the Z-test to vouch for it (it needs {}); render it again "
        "at {} spp or more to verify it",
        entry.spec.spp, min_spp, min_spp);
    return finish();
  }

  // Step 2: a fresh render with independent noise, Z-tested against the stored mean.
  ref::ReferenceSpec fresh_spec = entry.spec;
  fresh_spec.spp = spp;
  // The fresh render's noise is independent of the stored one's, which the Z-test's combined
  // variance assumes.
  fresh_spec.seed = independentSeed(entry.spec.seed);
  const ref::RenderResult fresh =
      ref::renderReference(scene, ref::renderSettingsOf(fresh_spec, progress));
  metrics::ZTestOptions options;
  options.significance = significance;
  options.reference_variance_dof = stored->variance_dof;
  options.test_variance_dof = fresh.variance_dof;
  // 4×4 blocks: a renderer change moves whole regions, and the far tail the family-wise test
  // reads is trustworthy for block means of a few hundred samples per pixel, not for a single
  // pixel's mean of a skewed estimator (an intact 1024-spp furnace entry failed a per-pixel
  // test at 64 spp; docs/rendering.md, "Error bars").
  options.block = 4;
  const metrics::ZTestResult z =
      metrics::zTest(stored->mean, stored->variance, fresh.mean, fresh.variance, options);
  result.passed = z.passed;
  result.tested = z.tested;
  result.failing = z.failing;
  result.min_p_value = z.min_p_value;
  if (!z.passed)
    result.problem =
        fmt::format("Z-test: {} of {} values fail at family-wise significance {} (min p {:.2g})",
                    z.failing, z.tested, significance, z.min_p_value);
  return finish();
}

}  // namespace gib::suites
