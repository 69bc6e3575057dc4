// assemble_mini and compute_element_fields allocate nothing on the heap (docs/architecture.md,
// "Coding conventions"). Counted by interposing malloc in this test executable (glibc: forwarding
// to __libc_malloc); operator new and Eigen's aligned_malloc both end in malloc.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>

#include "element/mini.hpp"
#include "element_test_support.hpp"
#include "material/fung.hpp"
#include "material/neo_hookean.hpp"

// AddressSanitizer replaces malloc itself; interposing it there crashes at start-up.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PLISSE_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define PLISSE_ASAN 1
#endif

#if defined(__GLIBC__) && !defined(PLISSE_ASAN)
namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* __libc_calloc(std::size_t count, std::size_t size);
extern "C" void* __libc_realloc(void* pointer, std::size_t size);

extern "C" void* malloc(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t count, std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  return __libc_calloc(count, size);
}
extern "C" void* realloc(void* pointer, std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  return __libc_realloc(pointer, size);
}

namespace plisse::mini {
namespace {

template <class Material>
long allocations_during_kernels(const Material& mat) {
  const auto X = test::random_tet(3);
  const TetGeometry g = compute_tet_geometry(X);
  const ElemVec x = test::random_state(3, g, 0.1, 0.5);
  ElemVec r;
  ElemMat K;
  BubbleVec b = BubbleVec::Zero();
  counting = true;
  allocations = 0;
  const ElementStatus s1 = assemble_mini(g, x, mat, 0.0, b, r, &K);        // several iterations
  const ElementStatus s2 = assemble_mini(g, x, mat, 1e-3, b, r, nullptr);  // residual only
  const ElementFields f = compute_element_fields(g, x, mat, b);
  counting = false;
  EXPECT_TRUE(s1.ok && s2.ok);
  EXPECT_GT(s1.bubble_iterations, 1);
  EXPECT_GT(f.J, 0.0);
  return allocations.load();
}

TEST(MiniElement, KernelsDoNotAllocate) {
  {  // the counter works
    counting = true;
    allocations = 0;
    void* volatile p = std::malloc(64);
    counting = false;
    std::free(p);
    ASSERT_EQ(allocations.load(), 1);
  }
  EXPECT_EQ(allocations_during_kernels(NeoHookean{0.5}), 0);
  EXPECT_EQ(allocations_during_kernels(Fung{1.0, 2.0}), 0);
}

}  // namespace
}  // namespace plisse::mini
#endif
