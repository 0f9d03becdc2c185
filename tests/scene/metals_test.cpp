#include "scene/metals.h"
#include "scene/fresnel_shared.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace gib::scene {
namespace {

// Published linear normal-incidence reflectances F0 of the metals, in Rec.709 RGB: T.
// Akenine-Möller et al., Real-Time Rendering, 4th ed. (2018), Table 9.2 (from N. Hoffman's
// spectral integration). Our F⊥ samples one wavelength per channel, theirs integrates each
// primary's band, so the two differ most where a metal's reflectance changes fastest: gold's blue
// (0.41 against 0.29, its absorption edge lies inside the blue band) and silver's blue (Johnson
// and Christy's silver reflects 0.98 at 451 nm). kChannelTolerance allows that; it still fails a
// swapped n and κ, a channel order turned round or a digit dropped.
constexpr float kChannelTolerance = 0.12f;

struct Published {
  const char* metal;
  Rgb f0;
};
constexpr Published kPublished[] = {
    {"aluminium", {0.91f, 0.92f, 0.92f}},
    {"silver", {0.95f, 0.93f, 0.88f}},
    {"gold", {1.00f, 0.71f, 0.29f}},
    {"copper", {0.95f, 0.64f, 0.54f}},
};

TEST(Metals, NormalIncidenceReflectanceMatchesPublishedValues) {
  for (const Published& p : kPublished) {
    const Metal* metal = findMetal(p.metal);
    ASSERT_NE(metal, nullptr) << p.metal;
    EXPECT_FALSE(metal->perfect);
    const Rgb f = fresnelAtNormalIncidence(metal->n, metal->k);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(f[c], p.f0[c], kChannelTolerance) << p.metal << " channel " << c;
  }
  // The colours a user sees: gold and copper redder than they are blue, aluminium and silver
  // nearly grey.
  for (const char* warm : {"gold", "copper"}) {
    const Rgb f = fresnelAtNormalIncidence(findMetal(warm)->n, findMetal(warm)->k);
    EXPECT_GT(f.r, f.g + 0.1f) << warm;
    EXPECT_GT(f.g, f.b) << warm;
  }
  for (const char* grey : {"aluminium", "silver"}) {
    const Rgb f = fresnelAtNormalIncidence(findMetal(grey)->n, findMetal(grey)->k);
    EXPECT_LT(std::max({f.r, f.g, f.b}) - std::min({f.r, f.g, f.b}), 0.03f) << grey;
  }
}

TEST(Metals, LookupByNameAndThePerfectReflector) {
  EXPECT_EQ(metalNames(),
            (std::vector<std::string>{"perfect", "aluminium", "silver", "gold", "copper"}));
  EXPECT_EQ(findMetal("tin"), nullptr);
  EXPECT_EQ(findMetal("Gold"), nullptr) << "names are exact";
  const Material perfect = mirrorMaterial("m", *findMetal("perfect"));
  EXPECT_EQ(perfect.type, MaterialType::kMirror);
  EXPECT_TRUE(perfect.perfect_mirror);
  const Material gold = mirrorMaterial("g", *findMetal("gold"));
  EXPECT_FALSE(gold.perfect_mirror);
  EXPECT_EQ(gold.name, "g");
  EXPECT_EQ(gold.conductor_k, findMetal("gold")->k);
}

}  // namespace
}  // namespace gib::scene
