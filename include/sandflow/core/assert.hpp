#pragma once
// Cheap checks of the kernel's own invariants (style.md 17): on in Debug and
// sanitizer builds, gone in Release (NDEBUG), where the condition is not even
// evaluated. A broken invariant is a bug in sandflow, never a user's input
// (those get an sf::Error with the numbers): it prints the condition and
// where, and aborts. The costly checks are the parts' validate() passes.
#include <cstdio>
#include <cstdlib>

namespace sf::detail {
[[noreturn]] inline void assertFailed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: SF_ASSERT(%s) failed\n", file, line, condition);
  std::abort();
}
}  // namespace sf::detail

#ifdef NDEBUG
#define SF_ASSERT(condition) ((void)0)
#else
#define SF_ASSERT(condition) \
  ((condition) ? (void)0 : ::sf::detail::assertFailed(#condition, __FILE__, __LINE__))
#endif
