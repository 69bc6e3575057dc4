// The MINI and Taylor-Hood kernels (assemble, element fields) allocate nothing on the heap
// (docs/architecture.md, "Coding conventions"). Counted by interposing malloc in this test
// executable (glibc: forwarding to __libc_malloc); operator new and Eigen's aligned_malloc both end
// in malloc.
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>

#include "element/mini.hpp"
#include "element/taylor_hood.hpp"
#include "element_test_support.hpp"
#include "material/fung.hpp"
#include "material/neo_hookean.hpp"
#include "support/sanitizer.hpp"

// AddressSanitizer replaces malloc itself; interposing it there crashes at start-up.
#if defined(__GLIBC__) && !PLISSE_TEST_ASAN
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

template <class Material>
long allocations_during_taylor_hood_kernels(const Material& mat) {
  const auto corners = test::random_tet(3);
  std::array<Vec3d, taylor_hood::kNodes> X;
  for (int a = 0; a < 4; ++a) X[a] = corners[a];
  for (int k = 0; k < 6; ++k)
    X[4 + k] = 0.5 * (corners[kTetEdges[k][0]] + corners[kTetEdges[k][1]]);
  const taylor_hood::Geometry g = taylor_hood::compute_geometry(X);
  (void)taylor_hood::reference_derivatives();  // the table is built once, outside the count
  taylor_hood::ElemVec x = taylor_hood::ElemVec::Zero();
  for (int i = 0; i < taylor_hood::kDofU; ++i) x(i) = 0.01 * g.size * ((i * 7) % 5 - 2);
  taylor_hood::ElemVec r;
  taylor_hood::ElemMat K;
  counting = true;
  allocations = 0;
  const taylor_hood::ElementStatus s1 = taylor_hood::assemble(g, x, mat, 0.0, r, &K);
  const taylor_hood::ElementStatus s2 = taylor_hood::assemble(g, x, mat, 1e-3, r, nullptr);
  const ElementFields f = taylor_hood::compute_element_fields(g, x, mat);
  counting = false;
  EXPECT_TRUE(s1.ok && s2.ok);
  EXPECT_GT(f.J, 0.0);
  return allocations.load();
}

TEST(TaylorHoodElement, KernelsDoNotAllocate) {
  EXPECT_EQ(allocations_during_taylor_hood_kernels(NeoHookean{0.5}), 0);
  EXPECT_EQ(allocations_during_taylor_hood_kernels(Fung{1.0, 2.0}), 0);
}

}  // namespace
}  // namespace plisse::mini
#endif
