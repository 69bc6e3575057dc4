// Viscoelasticity and Mullins softening in whole runs (examples/cube-relaxation-viscoelastic.yaml,
// examples/cube-cycles-mullins.yaml): a cube with sliding ends deforms homogeneously, which both
// elements represent exactly, so the nominal stress of every step (the top's reaction over its
// 25 mm² reference area) must equal the closed forms of docs/theory/materials.md to 1e-11 of the
// stretched cube's equilibrium stress P∞(λ = 2), the accuracy docs/verification.md prints (Newton
// at rtol 1e-10 on the residual, whose last quadratic step lands far below it), and the Cauchy
// stress σzz = λ P of the output fields to 1e-10:
//  - relaxation after a stretch to 2 in the first step, held 20 s: P(t) = P∞ (1 + Σ β_i
//    exp(-(t - t_jump)/τ_i)), with the jump at the middle of the first step (V3), or its sum
//    over the steps that share the stretch when the first one is cut back;
//  - Ogden & Roxburgh's softening in cycles to stretch 2, 2 and 2.5: P = η P0 with η from the
//    largest energy reached so far (MR2): the virgin curve on first loading and past the old
//    maximum, the first unloading curve retraced by the second cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "output/history_writer.hpp"
#include "support/run_plisse.hpp"
#include "support/verification_record.hpp"

namespace plisse {
namespace {

std::size_t column(const HistoryTable& h, const std::string& name) {
  for (std::size_t i = 0; i < h.columns.size(); ++i)
    if (h.columns[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

HistoryTable run_example(const std::string& example, const std::string& element) {
  const auto dir = test::scratch_directory(example + "-" + element);
  const int status = test::run_plisse(
      "run " + test::example(example) + " -o " + dir.string() + " --set element=" + element,
      dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  return read_history(dir / "history.csv");
}

constexpr double kC1 = 0.25, kArea = 25.0;  // the examples' neo-Hookean c1 [MPa], top area [mm²]
/// Largest difference of the nominal stress (the top's reaction) from the closed forms, in units
/// of P∞(λ = 2): docs/verification.md's claim.
constexpr double kTolerance = 1e-11;
/// The same for the Cauchy stress of the fields, which the page does not print: it holds the
/// pressure unknowns, which the Newton tolerance leaves at about 2e-11 of P∞ (measured).
constexpr double kFieldTolerance = 1e-10;

double virgin_nominal(double l) { return 2 * kC1 * (l - 1 / (l * l)); }

class InelasticRun : public ::testing::TestWithParam<const char*> {};

TEST_P(InelasticRun, RelaxationFollowsTheClosedFormAtEveryStep) {
  const HistoryTable h = run_example("cube-relaxation-viscoelastic.yaml", GetParam());
  // The steps and Newton iterations docs/verification.md prints for the run (regression guard).
  test::expect_newton_as_printed(
      h,
      test::verification_row("inelastic_cubes",
                             {{"case", "cube-relaxation-viscoelastic"}, {"element", GetParam()}}),
      std::string("cube-relaxation-viscoelastic, ") + GetParam());
  ASSERT_GE(h.rows.size(), 20u);
  const std::size_t time = column(h, "time"), force = column(h, "force_z:top"),
                    stretch = column(h, "stretch_z"), szz = column(h, "cauchy_zz");
  const double scale = virgin_nominal(2.0);
  const double beta[2] = {0.8, 0.3}, tau[2] = {0.5, 4.0};
  // The isochoric S of neo-Hookean in uniaxial tension λ: 2 c1 (1 - Ī1 / (3 λ_a²)) along a.
  const auto S = [](double l) {
    const double I1 = l * l + 2 / l;
    return std::array<double, 2>{2 * kC1 * (1 - I1 / (3 * l * l)), 2 * kC1 * (1 - I1 * l / 3)};
  };
  // A step that cuts back (Taylor-Hood's first one) applies the stretch in more than one step;
  // each step's change of S acts from the middle of its step (V3), so at time t
  //   Q = Σ_i β_i Σ_k exp(-(t - t_k^mid)/τ_i) (S(λ_k) - S(λ_k-1)),
  // and the free lateral faces give P = λ (S + Q)_axial - (S + Q)_lateral / λ².
  std::vector<double> times = {0.0}, stretches = {1.0};
  for (const auto& row : h.rows) {
    times.push_back(row[time]);
    stretches.push_back(row[stretch]);
    const double t = row[time], l = row[stretch];
    std::array<double, 2> total = S(l);
    for (std::size_t k = 1; k < times.size(); ++k)
      for (int i = 0; i < 2; ++i) {
        const double decay = beta[i] * std::exp(-(t - 0.5 * (times[k - 1] + times[k])) / tau[i]);
        for (int a = 0; a < 2; ++a)
          total[a] += decay * (S(stretches[k])[a] - S(stretches[k - 1])[a]);
      }
    const double expected = l * total[0] - total[1] / (l * l);
    EXPECT_NEAR(row[force] / kArea, expected, kTolerance * scale) << "t " << t;
    EXPECT_NEAR(row[szz], l * expected, kFieldTolerance * l * scale) << "t " << t;
    if (t >= 0.02) {
      EXPECT_NEAR(l, 2.0, 1e-9) << "t " << t;
    }
  }
  EXPECT_NEAR(h.rows.back()[time], 20.0, 1e-12);
  // Relaxed to within 1 % of the equilibrium stress after 5 τ2.
  EXPECT_LT(h.rows.back()[force] / kArea, 1.01 * virgin_nominal(2.0));
  EXPECT_GT(h.rows.back()[force] / kArea, virgin_nominal(2.0));
}

// With the stretch in one step (MINI's run: no cut-back) the sum above is the textbook closed form
// P(t) = P∞ (1 + Σ β_i exp(-(t - dt0/2)/τ_i)).
TEST(InelasticRunMini, OneStepStretchRelaxesAsTheTextbookClosedForm) {
  const HistoryTable h = run_example("cube-relaxation-viscoelastic.yaml", "mini");
  ASSERT_GE(h.rows.size(), 20u);
  const std::size_t time = column(h, "time"), force = column(h, "force_z:top");
  ASSERT_NEAR(h.rows.front()[time], 0.02, 1e-12) << "the stretch took more than one step";
  for (const auto& row : h.rows) {
    const double since = row[time] - 0.01;
    const double expected =
        virgin_nominal(2.0) * (1 + 0.8 * std::exp(-since / 0.5) + 0.3 * std::exp(-since / 4.0));
    EXPECT_NEAR(row[force] / kArea, expected, kTolerance * virgin_nominal(2.0))
        << "t " << row[time];
  }
}

TEST_P(InelasticRun, MullinsCyclesFollowTheClosedFormAndRetraceTheFirstUnloading) {
  const HistoryTable h = run_example("cube-cycles-mullins.yaml", GetParam());
  // The steps and Newton iterations docs/verification.md prints for the run (regression guard).
  test::expect_newton_as_printed(
      h,
      test::verification_row("inelastic_cubes",
                             {{"case", "cube-cycles-mullins"}, {"element", GetParam()}}),
      std::string("cube-cycles-mullins, ") + GetParam());
  ASSERT_GE(h.rows.size(), 60u);
  const std::size_t time = column(h, "time"), force = column(h, "force_z:top"),
                    stretch = column(h, "stretch_z"), szz = column(h, "cauchy_zz");
  const double r = 2.0, m = 0.05, beta = 0.1;
  double Wmax = 0.0;
  double first_unloading_at_1_5 = NAN, second_loading_at_1_5 = NAN;
  for (const auto& row : h.rows) {
    const double l = row[stretch], t = row[time];
    const double W = kC1 * (l * l + 2 / l - 3);
    Wmax = std::max(Wmax, W);
    const double eta = 1 - std::erf((Wmax - W) / (m + beta * Wmax)) / r;
    const double expected = eta * virgin_nominal(l);
    const double tolerance = kTolerance * virgin_nominal(2.0);
    EXPECT_NEAR(row[force] / kArea, expected, tolerance) << "t " << t;
    EXPECT_NEAR(row[szz], l * expected, kFieldTolerance / kTolerance * l * tolerance) << "t " << t;
    if (std::abs(t - 1.5) < 1e-9) first_unloading_at_1_5 = row[force] / kArea;
    if (std::abs(t - 2.5) < 1e-9) second_loading_at_1_5 = row[force] / kArea;
  }
  // t = 1.5 (unloading) and 2.5 (reloading) are both at stretch 1.5: the same softened stress,
  // well below the virgin one.
  ASSERT_FALSE(std::isnan(first_unloading_at_1_5));
  ASSERT_FALSE(std::isnan(second_loading_at_1_5));
  EXPECT_NEAR(second_loading_at_1_5, first_unloading_at_1_5, kTolerance * virgin_nominal(2.0));
  EXPECT_LT(first_unloading_at_1_5, 0.8 * virgin_nominal(1.5));
}

INSTANTIATE_TEST_SUITE_P(Elements, InelasticRun, ::testing::Values("mini", "taylor-hood"),
                         [](const auto& info) {
                           return std::string(info.param) == "mini" ? "Mini" : "TaylorHood";
                         });

}  // namespace
}  // namespace plisse
