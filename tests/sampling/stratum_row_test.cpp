// The camera sample's stratum row as a multiply (StrataMagic, StratumRow in cl/sampling/sampler.h):
// it must give the division's integer for every stratum of every pattern it is used for,
// or the two devices' pixels would move.
#include <gtest/gtest.h>

#include <cstdint>

#include "cl/sampling/sampler.h"

namespace {

TEST(SamplerMagic, RowEqualsTheDivisionForEveryStratumOfStrata2To1024) {
  for (uint strata = 2u; strata <= 1024u; ++strata) {
    uint magic = StrataMagic(strata);
    ASSERT_NE(magic, 0u) << strata;
    uint wrong = 0u;
    for (uint stratum = 0u; stratum < strata * strata; ++stratum)
      wrong += StratumRow(stratum, strata, magic) != stratum / strata;
    ASSERT_EQ(wrong, 0u) << "strata " << strata;
  }
}

TEST(SamplerMagic, OutsideItsRangeTheDivisionStays) {
  EXPECT_EQ(StrataMagic(0u), 0u);
  EXPECT_EQ(StrataMagic(1u), 0u);
  EXPECT_EQ(StrataMagic(1025u), 0u);
  // The bound is needed: at strata 1649 the multiply is off by one for some stratum.
  uint strata = 1649u, magic = 0xffffffffu / strata + 1u, wrong = 0u;
  for (uint stratum = 0u; stratum < strata * strata; ++stratum)
    wrong += (uint)(((std::uint64_t)stratum * magic) >> 32) != stratum / strata;
  EXPECT_GT(wrong, 0u);
  for (uint stratum = 0u; stratum < strata * strata; stratum += 997u)
    EXPECT_EQ(StratumRow(stratum, strata, StrataMagic(strata)), stratum / strata);
}

TEST(SamplerMagic, KeysCarryThePixelsMagic) {
  SampleKey k = MakeSampleKey(5u, 3u, 16u, 4u, 0u);
  EXPECT_EQ(k.strata_magic, StrataMagic(4u));
  EXPECT_EQ(MakeSampleKey(5u, 3u, 7u, 0u, 0u).strata_magic, 0u);
}

}  // namespace
