// Throughput of the MINI element kernel on one core (items_per_second = element evaluations per
// second). Run: build/bin/plisse-bench [--benchmark_filter=Tangent]
//
//   MiniTangent/..        residual + condensed tangent, bubble warm-started at its converged value
//                         (one element evaluation per call: the state of a converged Newton
//                         iteration, and of the repeated calls a line search makes)
//   MiniResidual/..       the same, residual only
//   MiniNewtonUpdate/..   residual + tangent after every nodal unknown moved by ~1e-3 h_e: the
//                         local bubble Newton needs 2-3 evaluations (a typical global iteration)
//   MaterialEvaluate/..   one material point (W, P, A) for comparison
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "element/mini.hpp"
#include "material/fung.hpp"
#include "material/mooney_rivlin.hpp"
#include "material/neo_hookean.hpp"
#include "material/ogden.hpp"

namespace plisse::mini {
namespace {

constexpr int kElements = 64;  // cycled so that the data of one call is not the previous call's

struct BenchElement {
  TetGeometry g;
  ElemVec x;
  ElemVec x_next;  // x moved by ~1e-3 h_e (MiniNewtonUpdate)
  BubbleVec bubble = BubbleVec::Zero();
};

/// Distorted elements at random moderate states (|u| <= 0.1 h_e, |p| <= c1), bubbles converged.
template <class Material>
std::vector<BenchElement> make_elements(const Material& mat, double c1) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<BenchElement> elements;
  while (static_cast<int>(elements.size()) < kElements) {
    std::array<Vec3d, 4> X = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)};
    for (auto& p : X) p += 0.25 * Vec3d(unit(rng), unit(rng), unit(rng));
    if ((X[1] - X[0]).cross(X[2] - X[0]).dot(X[3] - X[0]) <= 0.05) continue;
    BenchElement e;
    e.g = compute_tet_geometry(X);
    for (int i = 0; i < kDof; ++i) {
      const double scale = i < kDofU ? 0.1 * e.g.size : c1;
      e.x(i) = scale * unit(rng);
      e.x_next(i) = e.x(i) + 1e-3 * scale * unit(rng);
    }
    ElemVec r;
    ElemMat K;
    if (assemble_mini(e.g, e.x, mat, 0.0, e.bubble, r, &K).ok) elements.push_back(e);
  }
  return elements;
}

template <class Material>
void MiniTangent(benchmark::State& state, Material mat, double c1) {
  std::vector<BenchElement> elements = make_elements(mat, c1);
  ElemVec r;
  ElemMat K;
  int e = 0;
  for (auto _ : state) {
    BenchElement& el = elements[e];
    benchmark::DoNotOptimize(assemble_mini(el.g, el.x, mat, 0.0, el.bubble, r, &K));
    benchmark::DoNotOptimize(K.data());
    e = (e + 1) % kElements;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class Material>
void MiniResidual(benchmark::State& state, Material mat, double c1) {
  std::vector<BenchElement> elements = make_elements(mat, c1);
  ElemVec r;
  int e = 0;
  for (auto _ : state) {
    BenchElement& el = elements[e];
    benchmark::DoNotOptimize(assemble_mini(el.g, el.x, mat, 0.0, el.bubble, r, nullptr));
    benchmark::DoNotOptimize(r.data());
    e = (e + 1) % kElements;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class Material>
void MiniNewtonUpdate(benchmark::State& state, Material mat, double c1) {
  const std::vector<BenchElement> elements = make_elements(mat, c1);
  ElemVec r;
  ElemMat K;
  int e = 0;
  long evaluations = 0;
  for (auto _ : state) {
    const BenchElement& el = elements[e];
    BubbleVec bubble = el.bubble;  // converged at x; x_next needs a new bubble
    const ElementStatus s = assemble_mini(el.g, el.x_next, mat, 0.0, bubble, r, &K);
    evaluations += s.bubble_iterations;
    benchmark::DoNotOptimize(K.data());
    e = (e + 1) % kElements;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["bubble_iterations"] =
      static_cast<double>(evaluations) / static_cast<double>(state.iterations());
}

template <class Material>
void MaterialEvaluate(benchmark::State& state, Material mat) {
  Mat3d F;
  F << 1.1, 0.05, -0.02, 0.03, 0.95, 0.04, -0.01, 0.02, 0.97;
  for (auto _ : state) {
    benchmark::DoNotOptimize(F.data());
    benchmark::DoNotOptimize(mat.evaluate(F));
  }
  state.SetItemsProcessed(state.iterations());
}

constexpr double kC1 = 0.0033;  // [MPa], the paper's neo-Hookean constant

BENCHMARK_CAPTURE(MiniTangent, neo_hookean, NeoHookean{kC1}, kC1);
BENCHMARK_CAPTURE(MiniResidual, neo_hookean, NeoHookean{kC1}, kC1);
BENCHMARK_CAPTURE(MiniNewtonUpdate, neo_hookean, NeoHookean{kC1}, kC1);
BENCHMARK_CAPTURE(MiniTangent, mooney_rivlin, MooneyRivlin{0.7 * kC1, 0.3 * kC1}, kC1);
BENCHMARK_CAPTURE(MiniTangent, fung, Fung{2 * kC1, 1.0}, kC1);
BENCHMARK_CAPTURE(MaterialEvaluate, neo_hookean, NeoHookean{kC1});
BENCHMARK_CAPTURE(MaterialEvaluate, mooney_rivlin, MooneyRivlin{0.7 * kC1, 0.3 * kC1});
// Ogden: a spectral decomposition of C and three terms of powers per point.
const Ogden kOgden{2 * 0.4 * kC1, 1.3, 2 * 0.3 * kC1, 5.0, -2 * 0.3 * kC1, -2.0};
BENCHMARK_CAPTURE(MiniTangent, ogden, kOgden, kC1);
BENCHMARK_CAPTURE(MaterialEvaluate, ogden, kOgden);

}  // namespace
}  // namespace plisse::mini
