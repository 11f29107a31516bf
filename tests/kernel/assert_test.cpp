// SF_ASSERT: on in Debug and sanitizer builds, where a broken invariant
// aborts naming itself; gone in Release, where the condition is not evaluated.
#include <gtest/gtest.h>

#include "sandflow/core/assert.hpp"

namespace sf {
namespace {

TEST(Assert, HoldsQuietly) {
  int evaluated = 0;
  SF_ASSERT(++evaluated == 1);
#ifdef NDEBUG
  EXPECT_EQ(evaluated, 0);
#else
  EXPECT_EQ(evaluated, 1);
#endif
}

#ifndef NDEBUG
TEST(AssertDeathTest, ABrokenInvariantAbortsNamingItself) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const int slots = 3;
  EXPECT_DEATH(SF_ASSERT(slots < 2), "SF_ASSERT\\(slots < 2\\) failed");
}
#endif

}  // namespace
}  // namespace sf
