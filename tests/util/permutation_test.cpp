// Kensler's permutation as cl/util/hash.h evaluates it (two rounds before the first test, the
// key's remainder taken off the walk, a batch's elements vectorized) gives the values of the
// plain cycle walk, for every element of every size the renderer uses and keys whose sum
// with an element wraps past 2^32.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "cl/util/hash.h"

namespace {

// The walk as Kensler wrote it (and as this project drew its strata before).
uint PlainWalk(uint i, uint n, uint key) {
  uint w = PermutationMask(n);
  do {
    i = PermutationRound(i, w, key);
  } while (i >= n);
  return (i + key) % n;
}

std::vector<uint> Keys() {
  std::vector<uint> keys = {0u, 1u, 0xdeadbeefu, 0x80000000u, 0xfffffff0u, 0xffffffffu};
  for (uint k = 0; k < 40; ++k) keys.push_back(HashUint(k));
  return keys;
}

TEST(Permutation, ElementsMatchThePlainWalk) {
  for (uint n = 1; n <= 1100; ++n)
    for (uint key : Keys())
      for (uint i = 0; i < n; ++i)
        ASSERT_EQ(PermutationElement(i, n, key), PlainWalk(i, n, key))
            << "n " << n << " key " << key << " i " << i;
}

TEST(Permutation, BatchesMatchThePlainWalk) {
  for (uint n = 1; n <= 300; ++n)
    for (uint key : Keys())
      for (uint first = 0; first < n; ++first) {
        const int count = static_cast<int>(std::min<uint>(RT_PERMUTATION_BATCH, n - first));
        uint out[RT_PERMUTATION_BATCH];
        PermutationElements(first, count, n, key, out);
        for (int k = 0; k < count; ++k)
          ASSERT_EQ(out[k], PlainWalk(first + k, n, key))
              << "n " << n << " key " << key << " element " << first + k;
      }
}

// A key within n of 2^32 wraps the rotation for some elements: the case the division keeps.
TEST(Permutation, RotationWrapsLikeTheDivision) {
  for (uint n : {3u, 9u, 100u, 1000u})
    for (uint key = 0xffffffffu - n; key != 0u; ++key)
      for (uint i = 0; i < n; ++i)
        ASSERT_EQ(PermutationRotate(i, n, key, key % n), (i + key) % n) << n << " " << key;
}

}  // namespace
