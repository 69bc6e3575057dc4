// Throughput of the Taylor-Hood (P2/P1) element kernel on one core (items_per_second = element
// evaluations per second), beside the MINI kernel's in mini_bench.cpp. Run:
// build/bin/plisse-bench --benchmark_filter=TaylorHood
//
//   TaylorHoodTangent/..    residual + tangent of a 10-node element at a moderate random state
//   TaylorHoodResidual/..   residual only
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "element/taylor_hood.hpp"
#include "material/fung.hpp"
#include "material/mooney_rivlin.hpp"
#include "material/neo_hookean.hpp"

namespace plisse::taylor_hood {
namespace {

constexpr int kElements = 64;  // cycled so that the data of one call is not the previous call's

struct BenchElement {
  Geometry g;
  ElemVec x;
};

/// Distorted straight-sided elements (edge nodes at the midpoints) at random moderate states
/// (|u| <= 0.05 h_e, |p| <= c1).
template <class Material>
std::vector<BenchElement> make_elements(const Material& mat, double c1) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<BenchElement> elements;
  while (static_cast<int>(elements.size()) < kElements) {
    std::array<Vec3d, kNodes> X;
    X[0] = Vec3d(0, 0, 0);
    X[1] = Vec3d(1, 0, 0);
    X[2] = Vec3d(0, 1, 0);
    X[3] = Vec3d(0, 0, 1);
    for (int a = 0; a < 4; ++a) X[a] += 0.25 * Vec3d(unit(rng), unit(rng), unit(rng));
    if ((X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) <= 0.05) continue;
    for (int k = 0; k < 6; ++k) X[4 + k] = 0.5 * (X[kTetEdges[k][0]] + X[kTetEdges[k][1]]);
    BenchElement e;
    e.g = compute_geometry(X);
    for (int i = 0; i < kDof; ++i) e.x(i) = (i < kDofU ? 0.05 * e.g.size : c1) * unit(rng);
    ElemVec r;
    ElemMat K;
    if (assemble(e.g, e.x, mat, 0.0, r, &K).ok) elements.push_back(e);
  }
  return elements;
}

template <class Material>
void TaylorHoodTangent(benchmark::State& state, Material mat, double c1) {
  const std::vector<BenchElement> elements = make_elements(mat, c1);
  ElemVec r;
  ElemMat K;
  int e = 0;
  for (auto _ : state) {
    const BenchElement& el = elements[e];
    benchmark::DoNotOptimize(assemble(el.g, el.x, mat, 0.0, r, &K));
    benchmark::DoNotOptimize(K.data());
    e = (e + 1) % kElements;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class Material>
void TaylorHoodResidual(benchmark::State& state, Material mat, double c1) {
  const std::vector<BenchElement> elements = make_elements(mat, c1);
  ElemVec r;
  int e = 0;
  for (auto _ : state) {
    const BenchElement& el = elements[e];
    benchmark::DoNotOptimize(assemble(el.g, el.x, mat, 0.0, r, nullptr));
    benchmark::DoNotOptimize(r.data());
    e = (e + 1) % kElements;
  }
  state.SetItemsProcessed(state.iterations());
}

constexpr double kC1 = 0.0033;  // [MPa], the paper's neo-Hookean constant

BENCHMARK_CAPTURE(TaylorHoodTangent, neo_hookean, NeoHookean{kC1}, kC1);
BENCHMARK_CAPTURE(TaylorHoodResidual, neo_hookean, NeoHookean{kC1}, kC1);
BENCHMARK_CAPTURE(TaylorHoodTangent, mooney_rivlin, MooneyRivlin{0.7 * kC1, 0.3 * kC1}, kC1);
BENCHMARK_CAPTURE(TaylorHoodTangent, fung, Fung{2 * kC1, 1.0}, kC1);

}  // namespace
}  // namespace plisse::taylor_hood
