// Indentation stiffness of a thin spherical shell, unpressurised and pressurised
// (validation/pressurised-shell-indentation.yaml; study, derivation, R/t series and mesh
// convergence in docs/studies/shell-indentation.md): mid-surface radius R = 200 mm, wall
// t = 1 mm, neo-Hookean c1 = 1 MPa (E = 6 MPa, nu = 1/2), octant of one Taylor-Hood layer refined
// to 0.25 mm about the pole, a rigid sphere of 1 mm radius pushing the pole in by up to 0.3 t
// (two runs). Measured as scripts/shell-indentation measures it: the
// force on the whole sphere F = 4 force_y:indenter against the inward displacement w0 of the
// mid-surface pole from its inflated position, k the linear coefficient of a least-squares fit
// F = k w0 + c w0^2 over w0 <= 0.2 t. Shell theory for a point force:
//   k0 = 8 sqrt(B Y) / R = (8/3) E t^2 / R                      (Reissner 1946)
//   k  = k0 (pi/2) sqrt(tau^2 - 1) / artanh(sqrt(1 - 1/tau^2)),  tau = p R^2 / (4 sqrt(B Y))
//                                  (Vella, Ajdari, Vaziri & Boudaoud 2012, J. R. Soc. Interface
//                                   9, 448-455), here tau = 4 (k = 2.949 k0).
// Tolerances. The solid wall is softer than shell theory by its transverse shear, which shell
// theory leaves out: the shear deflection under a force spread over a patch of radius c adds
// about F ln(l / c) / (2 pi kappa G t) (kappa = 5/6, G = E/3, l the decay length of the dimple),
// a fraction 1.5 (t/R) (k/k0) ln(l/c) of the bending-stretching deflection: about 2 % at tau = 0
// (l = l_b = 8.2 mm, c = 0.4 mm) and 4 % at tau = 4 (l = l_b / sqrt(2 tau) = 2.9 mm); the study
// measures 3 % and 6.5 % on converged meshes, halving with t/R. The rows of docs/validation.md
// (validation_claim.hpp) claim k / k_theory 2 to 4 % below 1 at tau = 0 and 5.5 to 7.5 % below
// at tau = 4 (this mesh's numbers, 1 % either way: the shear estimate above explains their size,
// not their last digit), with the difference larger under pressure; and the stiffening by the
// pressure, k(4) / k(0), 2.5 to 5 % below the theory's 2.949 (the two shear shares' ratio).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "output/history_writer.hpp"
#include "support/run_case.hpp"
#include "support/run_plisse.hpp"
#include "support/validation_claim.hpp"
#include "verification/wrinkling/indented_sphere.hpp"

namespace plisse {
namespace {

constexpr double kRadius = 200.0;
using test::indent;
using test::Indentation;

double reissner() { return test::reissner(kRadius); }
double tau_of(double pressure) { return test::tau_of(pressure, kRadius); }
double vella(double tau) { return test::vella(tau, kRadius); }

/// The rows of one element's runs: k(0) against Reissner's k0 within `reissner_band` and k(4)
/// against Vella et al.'s within `vella_band` (relative differences). `suffix` ends the row names.
void expect_stiffness_claims(const std::string& suffix, const char* subject, const char* mesh,
                             const char* why, const Indentation& bare,
                             const Indentation& pressurised,
                             std::pair<double, double> reissner_band,
                             std::pair<double, double> vella_band) {
  test::expect_claim({.row = "shell-indentation/reissner" + suffix,
                      .subject = subject,
                      .quantity = "stiffness without pressure k [N/mm], fit over w0 ≤ 0.2 t",
                      .mesh = mesh,
                      .measured = bare.stiffness,
                      .reference = reissner(),
                      .source = "Reissner 1946, k0 = 8√(BY)/R",
                      .low = reissner_band.first,
                      .high = reissner_band.second,
                      .why = why});
  test::expect_claim({.row = "shell-indentation/vella" + suffix,
                      .subject = subject,
                      .quantity = "stiffness at τ = pR²/(4√(BY)) = 4 [N/mm]",
                      .mesh = mesh,
                      .measured = pressurised.stiffness,
                      .reference = vella(tau_of(pressurised.pressure)),
                      .source = "Vella, Ajdari, Vaziri & Boudaoud 2012, k0 (π/2)√(τ²−1) / "
                                "artanh√(1−τ⁻²)",
                      .low = vella_band.first,
                      .high = vella_band.second,
                      .why = why});
}

TEST(ShellIndentationSlow, StiffnessFollowsReissnerAndVellaWithinTheWallsShear) {
  // tau = 0: no pressure, the indenter 0.05 mm above the undeformed outer pole (200.5 mm).
  const Indentation bare =
      indent("shell-indentation-tau0", " --set loads[0].value=0 --set dies[0].point=[0,201.55,0]");
  const Indentation pressurised = indent("shell-indentation-tau4", "");
  ASSERT_GE(bare.fitted, 10);
  ASSERT_GE(pressurised.fitted, 10);
  const double tau = tau_of(pressurised.pressure);
  EXPECT_NEAR(tau, 4.0, 1e-9);
  const double bare_ratio = bare.stiffness / reissner();
  const double pressurised_ratio = pressurised.stiffness / vella(tau);
  const double stiffening = pressurised.stiffness / bare.stiffness;
  std::cout << "k(0) = " << bare.stiffness << " N/mm, " << bare_ratio << " x Reissner's "
            << reissner() << "; k(4) = " << pressurised.stiffness << " N/mm, " << pressurised_ratio
            << " x Vella et al.'s " << vella(tau) << "; k(4)/k(0) = " << stiffening << " (theory "
            << vella(tau) / reissner() << ")\n";
  const char* subject = "indented sphere, R/t = 200, rigid sphere of radius t, neo-Hookean";
  const char* mesh = "0.25 mm at the pole to 10 mm, 1 TH layer";
  const char* why =
      "this mesh's number ± 1 %: the wall's transverse shear, which shell theory "
      "leaves out";
  expect_stiffness_claims("", subject, mesh, why, bare, pressurised, {-0.04, -0.02},
                          {-0.075, -0.055});
  EXPECT_LT(pressurised_ratio, bare_ratio);  // the shear's share grows with the pressure
  test::expect_claim({.row = "shell-indentation/stiffening",
                      .subject = subject,
                      .quantity = "stiffening by the pressure k(τ = 4) / k(0)",
                      .mesh = mesh,
                      .measured = stiffening,
                      .reference = vella(tau) / reissner(),
                      .source = "the ratio of the two laws above",
                      .low = -0.05,
                      .high = -0.025,
                      .why = "the ratio of the two rows' shear shares"});
}

// The same sphere with the rotation-free shell triangle (validation/
// pressurised-shell-indentation-shell.yaml: the mid-surface meshed as the solid's, 1 133 nodes; the
// die meets the face t/2 above the nodes, contact.md D23). Kirchhoff-Love normals do not shear,
// so the solid's main difference is gone; what is left falls with t/R, about as (t/R)^0.55 at
// tau = 0 and (t/R)^0.8 at tau = 4 (study, "The shell"): on this mesh -1.5 % and -3.0 %, at
// R/t = 100 -2.3 % and -5.1 %, at R/t = 1000 -0.6 % and -0.9 %. Halving every element size moves
// them by 0.2 % and 0.1 % (0.25 -> 0.125 mm at the pole, 10 -> 5 mm far away), halving again by
// less than 0.01 % (tau = 0). The claims: this mesh's numbers ± 0.5 %, the difference smaller than
// the solid's at each tau, and growing with the pressure.
TEST(ShellIndentationSlow, ShellTriangleFollowsReissnerAndVellaToOrderTOverR) {
  const std::string file = "pressurised-shell-indentation-shell.yaml";
  // tau = 0: the indenter 0.05 mm above the undeformed outer face (200.5 mm).
  const Indentation bare = indent("shell-triangle-tau0",
                                  " --set loads[0].value=0 --set dies[0].point=[0,201.55,0]", file);
  const Indentation pressurised = indent("shell-triangle-tau4", "", file);
  ASSERT_GE(bare.fitted, 10);
  ASSERT_GE(pressurised.fitted, 10);
  const double tau = tau_of(pressurised.pressure);
  EXPECT_NEAR(tau, 4.0, 1e-9);
  const double bare_ratio = bare.stiffness / reissner();
  const double pressurised_ratio = pressurised.stiffness / vella(tau);
  std::cout << "shell triangle: k(0) = " << bare.stiffness << " N/mm, " << bare_ratio
            << " x Reissner's; k(4) = " << pressurised.stiffness << " N/mm, " << pressurised_ratio
            << " x Vella et al.'s\n";
  const char* subject = "indented sphere, R/t = 200, rigid sphere of radius t, shell triangle";
  const char* mesh = "0.25 mm at the pole to 10 mm, mid-surface";
  const char* why =
      "this mesh's number ± 0.5 %: not discretisation; falls with t/R (study, \"The shell\")";
  expect_stiffness_claims("-shell", subject, mesh, why, bare, pressurised, {-0.02, -0.01},
                          {-0.035, -0.025});
  EXPECT_LT(pressurised_ratio, bare_ratio);
  // Closer than the solid wall's rows above (-3 % and -6.5 % on the same mesh in millimetres).
  EXPECT_GT(bare_ratio, 0.98);
  EXPECT_GT(pressurised_ratio, 0.965);
}

}  // namespace
}  // namespace plisse
