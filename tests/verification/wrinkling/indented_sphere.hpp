#pragma once
/// The indented spherical shell of docs/studies/shell-indentation.md, as its tests run it: a run
/// of validation/pressurised-shell-indentation*.yaml shortened to w0 = 0.2 t, the stiffness fitted
/// as scripts/shell-indentation fits it, and the thin-shell laws it is measured against at any
/// mid-surface radius R (wall t = 1 mm, neo-Hookean c1 = 1 MPa).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "output/history_writer.hpp"
#include "support/run_case.hpp"
#include "support/run_plisse.hpp"

namespace plisse::test {

inline constexpr double kThickness = 1.0, kC1 = 1.0;
inline constexpr double kSymmetry = 4.0;  // the octant holds a quarter of the azimuth
inline constexpr double kFitDepth = 0.2;  // fit over w0 <= 0.2 t

inline double youngs_modulus() { return 6.0 * kC1; }

/// Reissner's k0 = 8 √(BY)/R = (8/3) E t² / R [N/mm].
inline double reissner(double radius) {
  return 8.0 / 3.0 * youngs_modulus() * kThickness * kThickness / radius;
}

/// Vella et al.'s τ = p R² / (4 √(BY)).
inline double tau_of(double pressure, double radius) {
  return 3.0 * pressure * radius * radius / (4.0 * youngs_modulus() * kThickness * kThickness);
}

/// The pressure of τ at radius R [MPa] (tau_of inverted).
inline double pressure_of(double tau, double radius) {
  return tau * 4.0 * youngs_modulus() * kThickness * kThickness / (3.0 * radius * radius);
}

/// Vella et al.'s k = k0 (π/2) √(τ² − 1) / artanh √(1 − τ⁻²) [N/mm]; k0 at τ = 0.
inline double vella(double tau, double radius) {
  if (tau == 0.0) return reissner(radius);
  return reissner(radius) * std::numbers::pi / 2.0 * std::sqrt(tau * tau - 1.0) /
         std::atanh(std::sqrt(1.0 - 1.0 / (tau * tau)));
}

struct Indentation {
  double pressure = 0.0;
  double stiffness = 0.0;  ///< k [N/mm], whole sphere
  int fitted = 0;          ///< steps in the fit
};

/// Runs `validation/<case_file>` shortened to w0 = 0.2 t with `options` and fits k.
inline Indentation indent(const std::string& name, const std::string& options,
                          const std::string& case_file = "pressurised-shell-indentation.yaml") {
  const auto dir = scratch_directory(name);
  // Shorter than the case, as the fit needs: 5 pressure steps, then 25 indenter steps of
  // 0.01 mm to w0 = 0.2 t (the case goes on to 0.3 t).
  const std::string shorter =
      " --set solver.steps=30 --set solver.max_step=0.0333334 --set loads[0].ramp=[0,0.166667]"
      " --set dies[0].move.ramp=[0.166667,1] --set dies[0].move.displacement=[0,-0.25,0]";
  const int status = run_plisse("run " + std::string(PLISSE_SOURCE_DIR) + "/validation/" +
                                    case_file + " -o " + dir.string() + shorter + options,
                                dir.string() + ".log");
  EXPECT_EQ(status, 0) << "see " << dir.string() << ".log";
  Indentation result;
  if (status != 0) return result;
  const HistoryTable h = read_history(dir / "history.csv");
  const std::size_t contact = history_column(h, "contact_nodes:indenter"),
                    uy = history_column(h, "uy:mid"), force = history_column(h, "force_y:indenter"),
                    pressure = history_column(h, "pressure:gas");
  result.pressure = h.rows.back()[pressure];
  double rest = 0.0;
  bool touched = false;
  // Normal equations of F = k w + c w^2.
  double s2 = 0.0, s3 = 0.0, s4 = 0.0, b1 = 0.0, b2 = 0.0;
  for (const auto& row : h.rows) {
    if (row[contact] == 0.0) {
      EXPECT_FALSE(touched) << "the indenter lost contact";
      rest = row[uy];
      continue;
    }
    touched = true;
    const double w = rest - row[uy], f = kSymmetry * row[force];
    if (w <= 0.0 || w > kFitDepth * kThickness) continue;
    s2 += w * w, s3 += w * w * w, s4 += w * w * w * w, b1 += w * f, b2 += w * w * f;
    ++result.fitted;
  }
  result.stiffness = (b1 * s4 - b2 * s3) / (s2 * s4 - s3 * s3);
  return result;
}

}  // namespace plisse::test
