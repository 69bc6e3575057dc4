// Measurement lines (analysis/wrinkle_lines.hpp; docs/theory/wrinkles.md, W20-W26): on a
// sinusoid of known count, wavelength and height riding on a smooth stretch, bow and bend, the
// measure gives the crests, both wavelengths and the crest-to-trough height; a smooth or straight
// line has no crests; and through a shell's triangles and Taylor-Hood tetrahedra the gauge
// carries a nodal wave to the line with the element's interpolation error only.
#include "analysis/wrinkle_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>

#include "core/error.hpp"
#include "mesh/box_mesh.hpp"
#include "support/shell_mesh.hpp"

namespace plisse {
namespace {

constexpr double kPi = std::numbers::pi;

/// The smooth shape the measure takes off (W22): a 1 % stretch along x, a bow in y and a cubic
/// bend in z, the direction of the wrinkles.
Vec3d smooth_shape(double s) { return {1.01 * s, 0.002 * s * s, 1e-5 * s * s * s}; }

/// Arc length of smooth_shape from a to b (Simpson, 2000 intervals).
double smooth_arc(double a, double b) {
  const int n = 2000;
  const double h = (b - a) / n;
  const auto speed = [](double s) { return Vec3d(1.01, 0.004 * s, 3e-5 * s * s).norm(); };
  double sum = speed(a) + speed(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * speed(a + i * h);
  return sum * h / 3.0;
}

struct Samples {
  std::vector<double> s;
  std::vector<Vec3d> x;
};

/// n points on [0, L] of smooth_shape plus a sin(2 pi k s / L) along z.
Samples wavy_line(double L, int n, int k, double a) {
  Samples line;
  for (int i = 0; i < n; ++i) {
    const double s = L * i / (n - 1);
    line.s.push_back(s);
    line.x.push_back(smooth_shape(s) + Vec3d(0, 0, a * std::sin(2.0 * kPi * k * s / L)));
  }
  return line;
}

// k whole waves over L have 2k crests, 2a apart in height, and between them 2k - 1 zeros from
// L/(2k) to L - L/(2k) (W26): the reference wavelength is L / k and the one along the smooth shape
// the arc between the first and last zero over k - 1. The first cubic (W22) also takes the
// sinusoid's own projection on the cubics, a smooth term of relative size about 1/k that moved the
// heights by 5.6 % at k = 4; fitted again to the means over one wavelength (W22b), the measure is
// within 0.1 % on the wavelengths and 0.2 % on the height.
TEST(WrinkleLines, WholeWavesOnASmoothBendGiveTheirCrestsWavelengthAndHeight) {
  const double L = 60.0, a = 0.05;
  for (const int k : {4, 6, 11}) {
    const Samples line = wavy_line(L, 401, k, a);
    const LineMetrics m = measure_line(line.s, line.x, 4);
    EXPECT_EQ(m.crests, 2 * k) << "k = " << k;
    EXPECT_NEAR(m.reference_wavelength, L / k, 0.001 * L / k) << "k = " << k;
    const double first = L / (2.0 * k), last = L - first;  // the first and last zero
    const double seen = smooth_arc(first, last) / (k - 1.0);
    EXPECT_NEAR(m.wavelength, seen, 0.001 * seen) << "k = " << k;
    EXPECT_NEAR(m.amplitude, 2.0 * a, 0.002 * 2.0 * a) << "k = " << k;
    EXPECT_NEAR(m.deviation, 2.0 * a, 0.02 * 2.0 * a) << "k = " << k;
  }
}

// A line that ends in the middle of a wave: 7.5 waves give 15 crests, half a wavelength apart.
TEST(WrinkleLines, AWaveCutByTheLinesEndStillGivesItsWavelength) {
  const double L = 45.0, a = 0.02, lambda = 6.0;
  Samples line;
  for (int i = 0; i < 301; ++i) {
    const double s = L * i / 300;
    line.s.push_back(s);
    line.x.push_back(smooth_shape(s) + Vec3d(0, 0, a * std::sin(2.0 * kPi * s / lambda)));
  }
  const LineMetrics m = measure_line(line.s, line.x, 4);
  EXPECT_EQ(m.crests, 15);
  EXPECT_NEAR(m.reference_wavelength, lambda, 0.001 * lambda);
  EXPECT_NEAR(m.amplitude, 2.0 * a, 0.01 * 2.0 * a);
}

// Straight, or bent by a cubic alone: the line is its smooth shape to round-off, no crests. A
// wave of 3 crests is a smooth shape for min_crests 4, and wrinkles for min_crests 3.
TEST(WrinkleLines, ASmoothLineHasNoCrestsAndFewerThanMinCrestsAreNone) {
  Samples straight, bent;
  for (int i = 0; i < 101; ++i) {
    const double s = 0.3 * i;
    straight.s.push_back(s);
    straight.x.push_back(Vec3d(1.0, 2.0, 3.0) + s * Vec3d(0.6, 0.8, 0.0));
    bent.s.push_back(s);
    bent.x.push_back(smooth_shape(s));
  }
  for (const Samples* line : {&straight, &bent}) {
    const LineMetrics m = measure_line(line->s, line->x, 1);
    EXPECT_EQ(m.crests, 0);
    EXPECT_EQ(m.amplitude, 0.0);
    EXPECT_EQ(m.wavelength, 0.0);
    EXPECT_LT(m.deviation, 1e-11);
  }
  // 1.5 waves: 3 crests.
  const Samples wave = wavy_line(30.0, 201, 0, 0.0);
  Samples three = wave;
  for (std::size_t i = 0; i < three.s.size(); ++i)
    three.x[i].z() += 0.1 * std::sin(3.0 * kPi * three.s[i] / 30.0);
  EXPECT_EQ(measure_line(three.s, three.x, 4).crests, 0);
  const LineMetrics m3 = measure_line(three.s, three.x, 3);
  EXPECT_EQ(m3.crests, 3);
  EXPECT_GT(m3.amplitude, 0.0);
}

TEST(WrinkleLines, RefusesTooFewPointsAndDistancesThatDoNotIncrease) {
  Samples line = wavy_line(10.0, 7, 1, 0.1);
  const auto measure = [&line] { return measure_line(line.s, line.x, 4); };
  EXPECT_THROW(measure(), Error);
  line = wavy_line(10.0, 20, 1, 0.1);
  EXPECT_NO_THROW(measure());
  line.s[5] = line.s[4];
  EXPECT_THROW(measure(), Error);
  line = wavy_line(10.0, 20, 1, 0.1);
  line.s.pop_back();
  EXPECT_THROW(measure(), Error);
}

/// The nodal wave u = (0, 0, a sin(2 pi k (X - X0) / L)).
std::vector<Vec3d> nodal_wave(const Mesh& mesh, double X0, double L, int k, double a) {
  std::vector<Vec3d> u;
  for (const Vec3d& X : mesh.nodes)
    u.emplace_back(0.0, 0.0, a * std::sin(2.0 * kPi * k * (X.x() - X0) / L));
  return u;
}

// Through a shell's linear triangles (1 mm, 20 to a wavelength) the line sees the piecewise-linear
// interpolant: its crests are the nodes nearest the sine's, lower by at most 1 - cos(pi h / lambda)
// = 1.2 % (0.1 % more for the measure), and its wavelength within 0.1 %. A line beside the square
// is placed at its nearest points, and the gauge says how far.
TEST(WrinkleLines, TheGaugeCarriesANodalWaveThroughAShellsTriangles) {
  const Mesh mesh = test::flat_square(Mat3d::Identity(), 60, 0.1);  // [-30, 30]^2, z = 0
  const double a = 0.03;
  const LineGauge gauge(mesh, {-30.0, 4.3, 0.0}, {30.0, 4.3, 0.0}, 301);
  EXPECT_LT(gauge.outside().distance, 1e-12);
  ASSERT_EQ(gauge.distances().size(), 301u);
  EXPECT_NEAR(gauge.distances().back(), 60.0, 1e-12);
  const LineMetrics m =
      measure_line(gauge.distances(), gauge.deformed(nodal_wave(mesh, -30.0, 60.0, 3, a)), 4);
  EXPECT_EQ(m.crests, 6);
  EXPECT_NEAR(m.reference_wavelength, 20.0, 0.001 * 20.0);
  EXPECT_NEAR(m.wavelength, 20.0, 0.001 * 20.0);
  EXPECT_LE(m.amplitude, 2.0 * a * (1.0 + 1e-3));
  EXPECT_GE(m.amplitude, 2.0 * a * std::cos(kPi / 20.0) * (1.0 - 1e-3));

  const LineGauge off(mesh, {-30.0, 4.3, 0.5}, {30.0, 4.3, 0.5}, 50);
  EXPECT_NEAR(off.outside().distance, 0.5, 1e-12);
}

// A line from a mirror plane (W21): a cos(2 pi x / 12) on x in [0, 30], half of the symmetric
// pattern on [-30, 30], whose crest at x = 0 lies on the plane. Mirrored there, the line is
// [-30, 30] with 9 interior crests (x = 0, +-6, ..., +-24) of height 2a (at nodes: exact) and the
// wavelength 12; unmirrored, the 4 interior ones of [0, 30]. The mirrored end may be either.
TEST(WrinkleLines, AMirroredEndCountsTheCrestOnTheMirrorPlane) {
  const Mesh mesh = test::flat_square(Mat3d::Identity(), 60, 0.1);
  const double a = 0.02;
  std::vector<Vec3d> u;
  for (const Vec3d& X : mesh.nodes)
    u.emplace_back(0.0, 0.0, a * std::cos(2.0 * kPi * X.x() / 12.0));
  const Vec3d plane(0.0, 4.3, 0.0), far(30.0, 4.3, 0.0);
  for (const auto& [from, to, mirror] :
       {std::tuple{plane, far, LineMirror::from}, std::tuple{far, plane, LineMirror::to}}) {
    const LineSamples whole = LineGauge(mesh, from, to, 301, mirror).samples(u);
    ASSERT_EQ(whole.s.size(), 601u);
    const LineMetrics m = measure_line(whole.s, whole.x, 3);
    EXPECT_EQ(m.crests, 9);
    EXPECT_NEAR(m.reference_wavelength, 12.0, 0.001 * 12.0);
    EXPECT_NEAR(m.amplitude, 2.0 * a, 0.002 * 2.0 * a);
  }
  const LineSamples half = LineGauge(mesh, plane, far, 301).samples(u);
  EXPECT_EQ(measure_line(half.s, half.x, 3).crests, 4);
}

// Through Taylor-Hood tetrahedra (quadratic, 2 mm to a 15 mm wavelength), a line inside the wall
// sees the quadratic interpolant of the sine: the wavelength within 0.1 % and the height within
// 0.2 %.
TEST(WrinkleLines, TheGaugeCarriesANodalWaveThroughTaylorHoodTetrahedra) {
  const Mesh mesh = make_box_mesh({60.0, 10.0, 1.0}, {30, 5, 1}, 2);
  const double a = 0.05;
  const LineGauge gauge(mesh, {0.0, 3.7, 0.5}, {60.0, 3.7, 0.5}, 401);
  EXPECT_LT(gauge.outside().distance, 1e-12);
  const LineMetrics m =
      measure_line(gauge.distances(), gauge.deformed(nodal_wave(mesh, 0.0, 60.0, 4, a)), 4);
  EXPECT_EQ(m.crests, 8);
  EXPECT_NEAR(m.reference_wavelength, 15.0, 0.001 * 15.0);
  EXPECT_NEAR(m.amplitude, 2.0 * a, 0.002 * 2.0 * a);
}

}  // namespace
}  // namespace plisse
