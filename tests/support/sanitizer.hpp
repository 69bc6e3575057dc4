#pragma once
// Whether the test (and so plisse, built with the same flags) runs under AddressSanitizer. GCC
// defines __SANITIZE_ADDRESS__; clang, which the sanitizer build uses (scripts/sanitize), answers
// __has_feature(address_sanitizer) instead.

#if defined(__SANITIZE_ADDRESS__)
#define PLISSE_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PLISSE_TEST_ASAN 1
#endif
#endif
#ifndef PLISSE_TEST_ASAN
#define PLISSE_TEST_ASAN 0
#endif

namespace plisse::test {

/// AddressSanitizer reserves terabytes of address space for its shadow memory, so a test under
/// it leaves out address-space limits, and takes several times as long.
inline constexpr bool kAddressSanitizer = PLISSE_TEST_ASAN != 0;

}  // namespace plisse::test
