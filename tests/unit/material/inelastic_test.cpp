// Viscoelasticity and Mullins softening at one material point (material/inelastic.hpp;
// docs/theory/materials.md V1-V7, MR1-MR6), in incompressible uniaxial tension, where the lateral
// faces are free: F = diag(λ, λ^-1/2, λ^-1/2), the pressure makes P22 = 0, and the nominal stress
// is P11 - P22 F22 / F11 of the isochoric response.
//  - the tangent is the derivative of the stress for the converged history held fixed (central
//    differences), and symmetric;
//  - relaxation after a step stretch follows the closed form P(t) = P∞(λ) (1 + Σ β_i
//    exp(-(t - t_jump) / τ_i)) (the relaxation function of the Prony series) to rounding, since the
//    update integrates a jump at the middle of its step exactly;
//  - under a ramp, the overstress converges at order 2 in the time step to the convolution
//    integral Q(T) = β ∫ exp(-(T - s)/τ) dS(s), computed here independently by Simpson's rule on a
//    fine grid; a load-unload cycle dissipates energy (loading above unloading) and its loop area
//    converges at the same order;
//  - Mullins (Ogden & Roxburgh 1999, with the energy scale m + β Wmax): the virgin curve on first
//  loading, η P0 with
//    η = 1 - erf((Wmax - W0)/(m + β Wmax))/r on unloading, the same curve on reloading (stable from
//    the second cycle on), the virgin curve again past the largest stretch so far.
#include "material/inelastic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "material/registry.hpp"
#include "material_test_utils.hpp"

namespace plisse {
namespace {

Mat3d uniaxial(double l) { return Vec3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal(); }

/// Nominal stress of an incompressible bar with free lateral faces, from the isochoric P.
double nominal(const Mat3d& P, const Mat3d& F) { return P(0, 0) - P(1, 1) * F(1, 1) / F(0, 0); }

/// A material point: the base model, its law and its converged history.
struct Point {
  NeoHookean base{0.2};
  InelasticLaw law;
  std::vector<double> history;

  explicit Point(InelasticLaw l) : law(l), history(static_cast<std::size_t>(l.history_size())) {}

  /// The response at F after dt, without changing the history.
  PointResponse at(const Mat3d& F, double dt) const {
    return evaluate_inelastic(law, base.evaluate(F), F, history, {}, dt);
  }
  /// A converged step to F after dt: the response, and the history moves on.
  PointResponse step(const Mat3d& F, double dt) {
    std::vector<double> now(history.size());
    const PointResponse r = evaluate_inelastic(law, base.evaluate(F), F, history, now, dt);
    history = now;
    return r;
  }
};

InelasticLaw two_term_law() {
  InelasticLaw law;
  law.viscoelastic = {0.8, 0.5, 0.3, 4.0};
  return law;
}

InelasticLaw mullins_law() {
  InelasticLaw law;
  law.mullins = {1.8, 0.05, 0.1};
  return law;
}

TEST(Inelastic, HistorySizesFollowTheLaw) {
  EXPECT_EQ(InelasticLaw{}.history_size(), 0);
  EXPECT_TRUE(InelasticLaw{}.elastic());
  EXPECT_EQ(mullins_law().history_size(), 1);
  EXPECT_EQ(two_term_law().history_size(), 6 * 3);
  InelasticLaw both = two_term_law();
  both.mullins = mullins_law().mullins;
  EXPECT_EQ(both.history_size(), 1 + 6 * 3);
  // A term with beta = 0 ends the series.
  InelasticLaw gap;
  gap.viscoelastic = {0.5, 1.0, 0.0, 0.0, 0.4, 2.0};
  EXPECT_EQ(gap.viscoelastic.n_terms(), 1);
}

// The tangent is dP/dF at fixed converged history, for states on and off the primary curve and
// time steps from 0 to several relaxation times: central differences agree to 1e-6 (their own
// error is O(h²) with h = 1e-5), and A is symmetric (V6: the step derives from a potential).
TEST(Inelastic, TangentIsTheDerivativeOfTheStressAndSymmetric) {
  InelasticLaw both = two_term_law();
  both.mullins = mullins_law().mullins;
  for (const InelasticLaw& law : {two_term_law(), mullins_law(), both}) {
    Point point(law);
    // A history off the virgin state: stretch to 2.2 along a random path, come back part way.
    point.step(test::random_deformation(3, 0.2) * uniaxial(1.6), 0.3);
    point.step(uniaxial(2.2) * test::random_rotation(5), 0.4);
    point.step(uniaxial(1.7), 0.2);
    for (const double dt : {0.0, 0.05, 1.0, 20.0}) {
      for (const Mat3d& F : {Mat3d(uniaxial(1.3)), test::random_deformation(11, 0.3),
                             Mat3d(uniaxial(2.6) * test::random_rotation(12))}) {
        const PointResponse r = point.at(F, dt);
        Mat9d fd;
        const double h = 1e-5;
        for (int k = 0; k < 9; ++k) {
          Mat3d Fp = F, Fm = F;
          Fp.data()[k] += h;
          Fm.data()[k] -= h;
          const Mat3d dP = (point.at(Fp, dt).P - point.at(Fm, dt).P) / (2 * h);
          fd.col(k) = Eigen::Map<const Vec9d>(dP.data());
        }
        EXPECT_LT((r.A - fd).norm(), 1e-6 * r.A.norm()) << "dt " << dt;
        EXPECT_LT((r.A - r.A.transpose()).norm(), 1e-12 * r.A.norm()) << "dt " << dt;
      }
    }
  }
}

// With dt = 0 at the converged deformation the response is that of the converged state: the
// history does not move (what the output fields evaluate).
TEST(Inelastic, ZeroStepAtTheConvergedStateChangesNothing) {
  InelasticLaw both = two_term_law();
  both.mullins = mullins_law().mullins;
  Point point(both);
  point.step(uniaxial(2.0), 0.4);
  const Mat3d F = uniaxial(1.5);
  const PointResponse converged = point.step(F, 0.7);
  const std::vector<double> before = point.history;
  const PointResponse again = point.step(F, 0.0);
  EXPECT_LT((again.P - converged.P).norm(), 1e-14 * converged.P.norm());
  for (std::size_t k = 0; k < before.size(); ++k)
    EXPECT_NEAR(point.history[k], before[k], 1e-14 * (1 + std::abs(before[k]))) << k;
}

// A step stretch applied in the first step (duration dt0, so the jump is at dt0 / 2) and held:
// the nominal stress relaxes as P∞ (1 + Σ β_i exp(-(t - dt0/2)/τ_i)), exactly, whatever the
// holding steps.
TEST(Inelastic, RelaxationAfterAStepStretchFollowsTheClosedForm) {
  const InelasticLaw law = two_term_law();
  for (const double l : {0.7, 1.5, 3.0}) {
    Point point(law);
    const Mat3d F = uniaxial(l);
    const double equilibrium = nominal(point.base.evaluate(F).P, F);
    const double dt0 = 0.01;
    double t = dt0;
    double P = nominal(point.step(F, dt0).P, F);
    const auto closed_form = [&](double time) {
      const double since = time - 0.5 * dt0;
      return equilibrium * (1.0 + 0.8 * std::exp(-since / 0.5) + 0.3 * std::exp(-since / 4.0));
    };
    for (const double dt : {0.01, 0.05, 0.2, 0.7, 1.5, 3.0, 6.0, 12.0, 30.0, 50.0}) {
      EXPECT_NEAR(P, closed_form(t), 1e-13 * std::abs(equilibrium)) << "λ " << l << " t " << t;
      P = nominal(point.step(F, dt).P, F);
      t += dt;
    }
    // Long after (t = 110 s, 27 τ2), the equilibrium response alone.
    EXPECT_NEAR(P, closed_form(t), 1e-13 * std::abs(equilibrium));
    EXPECT_NEAR(P, equilibrium, 1e-11 * std::abs(equilibrium));
  }
}

/// The isochoric second Piola-Kirchhoff stress of neo-Hookean c1 in uniaxial tension λ, closed
/// form: S = 2 c1 (I - Ī1/3 C⁻¹), Ī1 = λ² + 2/λ (the references below use it, not the model).
Vec3d uniaxial_S(double c1, double l) {
  const double I1 = l * l + 2.0 / l;
  return 2.0 * c1 * Vec3d(1.0 - I1 / (3.0 * l * l), 1.0 - I1 * l / 3.0, 1.0 - I1 * l / 3.0);
}

/// Simpson's rule for ∫_a^b f on n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return sum * h / 3.0;
}

/// Stretch of a load-unload cycle over [0, 2 T]: up to lmax at T, back to 1 at 2 T.
double cycle_stretch(double t, double T, double lmax) {
  return 1.0 + (lmax - 1.0) * (t <= T ? t / T : (2.0 * T - t) / T);
}

// One Maxwell element, β = 1, τ = 1 s, a stretch ramp 1 -> 2.5 over T = 2 s. Reference: the
// convolution integral (V2) Q(T) = β (S(T) - ∫_0^T S(s) exp(-(T - s)/τ)/τ ds) (by parts, S(0) = 0),
// component 11 of Se, by Simpson's rule on 20 000 intervals (error < 1e-12 here).
TEST(Inelastic, RampConvergesAtOrderTwoToTheConvolutionIntegral) {
  InelasticLaw law;
  law.viscoelastic = {1.0, 1.0};
  const double T = 2.0, lmax = 2.5;
  const auto S11 = [&](double t) { return uniaxial_S(0.2, cycle_stretch(t, T, lmax))[0]; };
  const double reference =
      S11(T) - simpson([&](double s) { return S11(s) * std::exp(-(T - s)); }, 0.0, T, 20000);
  std::vector<double> errors;
  for (const int n : {8, 16, 32, 64, 128}) {
    Point point(law);
    for (int k = 1; k <= n; ++k) point.step(uniaxial(cycle_stretch(T * k / n, T, lmax)), T / n);
    errors.push_back(std::abs(point.history[6] - reference));  // Q_1, xx
  }
  EXPECT_NEAR(test::observed_order(errors), 2.0, 0.1);
  EXPECT_LT(errors.back(), 1e-4 * std::abs(reference));
}

// A load-unload cycle 1 -> 2.5 -> 1 over 2 x 2 s with one Maxwell element: at every stretch the
// loading stress is above the unloading one, and the loop area ∮ P dλ (energy dissipated per unit
// volume) converges at order 2 to the reference from the convolution integral on a fine grid.
TEST(Inelastic, LoadUnloadCycleDissipatesTheReferenceEnergy) {
  InelasticLaw law;
  law.viscoelastic = {1.0, 1.0};
  const double T = 2.0, lmax = 2.5;
  const NeoHookean base{0.2};
  // Reference nominal stress at time t: Q from the convolution integral of S (all components,
  // diagonal), then P = Pe + F Q through the free lateral faces.
  const auto reference_nominal = [&](double t) {
    const auto S = [&](double s) { return uniaxial_S(0.2, cycle_stretch(s, T, lmax)); };
    Vec3d Q;
    for (int i = 0; i < 3; ++i)
      Q[i] = S(t)[i] - simpson([&](double s) { return S(s)[i] * std::exp(-(t - s)); }, 0.0, t,
                               2 * std::max(2, static_cast<int>(500 * t)));
    const Mat3d F = uniaxial(cycle_stretch(t, T, lmax));
    return nominal(base.evaluate(F).P + F * Mat3d(Q.asDiagonal()), F);
  };
  // Loop area by the trapezoidal rule on 1600 intervals of time (its own error ~1e-7 relative).
  const auto loop_area = [&](const std::function<double(double)>& P, int n) {
    double area = 0.0;
    for (int k = 0; k < n; ++k) {
      const double t0 = 2 * T * k / n, t1 = 2 * T * (k + 1) / n;
      area += 0.5 * (P(t0) + P(t1)) * (cycle_stretch(t1, T, lmax) - cycle_stretch(t0, T, lmax));
    }
    return area;
  };
  const double reference = loop_area(reference_nominal, 1600);
  ASSERT_GT(reference, 0.0);
  std::vector<double> errors;
  for (const int n : {16, 32, 64, 128}) {  // steps per cycle
    Point point(law);
    std::vector<double> P(n + 1, 0.0);
    for (int k = 1; k <= n; ++k) {
      const Mat3d F = uniaxial(cycle_stretch(2 * T * k / n, T, lmax));
      P[k] = nominal(point.step(F, 2 * T / n).P, F);
    }
    for (int k = 1; k < n / 2; ++k)  // same stretch on the way up (k) and down (n - k)
      EXPECT_GT(P[k], P[n - k]) << "steps " << n << " k " << k;
    double area = 0.0;
    for (int k = 0; k < n; ++k)
      area += 0.5 * (P[k] + P[k + 1]) *
              (cycle_stretch(2 * T * (k + 1) / n, T, lmax) - cycle_stretch(2 * T * k / n, T, lmax));
    errors.push_back(std::abs(area - reference));
  }
  EXPECT_NEAR(test::observed_order(errors), 2.0, 0.2);
  EXPECT_LT(errors.back(), 1e-3 * reference);
}

// Ogden-Roxburgh in uniaxial cycles to λ = 2, 2, then 2.6.
TEST(Inelastic, MullinsCurveIsStableFromTheSecondCycle) {
  const InelasticLaw law = mullins_law();
  const MullinsSoftening& mu = law.mullins;
  Point point(law);
  const NeoHookean& base = point.base;
  const auto W0 = [&](double l) { return base.evaluate(uniaxial(l)).W; };
  const auto virgin = [&](double l) { return nominal(base.evaluate(uniaxial(l)).P, uniaxial(l)); };
  std::vector<double> grid;
  for (int k = 0; k <= 20; ++k) grid.push_back(1.0 + 0.05 * k);  // 1 .. 2
  const auto go = [&](double l) { return nominal(point.step(uniaxial(l), 0.1).P, uniaxial(l)); };
  // Cycle 1, loading: the virgin curve.
  for (const double l : grid) EXPECT_NEAR(go(l), virgin(l), 1e-14 * (1 + virgin(l))) << l;
  // Unloading: η P0 with Wmax = W0(2).
  std::vector<double> unloading;
  for (auto it = grid.rbegin(); it != grid.rend(); ++it) {
    const double Wmax = W0(2.0);
    const double eta = 1.0 - std::erf((Wmax - W0(*it)) / (mu.m + mu.beta * Wmax)) / mu.r;
    const double P = go(*it);
    EXPECT_NEAR(P, eta * virgin(*it), 1e-13 * (1 + std::abs(virgin(*it)))) << *it;
    EXPECT_GE(eta, 1.0 - 1.0 / mu.r);
    unloading.push_back(P);
  }
  EXPECT_LT(unloading[10], 0.8 * virgin(1.5));  // the softening is visible at mid-stretch
  // Cycle 2: reloading and unloading retrace cycle 1's unloading curve.
  for (std::size_t k = 0; k < grid.size(); ++k)
    EXPECT_NEAR(go(grid[k]), unloading[grid.size() - 1 - k], 1e-14) << grid[k];
  for (std::size_t k = 0; k < grid.size(); ++k)
    EXPECT_NEAR(go(grid[grid.size() - 1 - k]), unloading[k], 1e-14) << grid[k];
  // Cycle 3 beyond 2: back on the virgin curve past the old maximum.
  for (const double l : grid) go(l);
  for (const double l : {2.1, 2.3, 2.6}) EXPECT_NEAR(go(l), virgin(l), 1e-14 * virgin(l)) << l;
}

}  // namespace
}  // namespace plisse
