#pragma once
/// The shell's cross-section: its thickness and the Gauss-Legendre points through it
/// (docs/theory/shell.md, KL13). Plain data, made once per shell region.
#include <array>

namespace plisse::shell {

inline constexpr int kMinThicknessPoints = 2;
inline constexpr int kMaxThicknessPoints = 9;
/// Five points: exact to degree 9 in ζ; enough for surface strains of ±25 % (KL13).
inline constexpr int kDefaultThicknessPoints = 5;

struct ShellSection {
  double thickness = 0.0;                          ///< reference thickness t [mm], > 0
  int n_points = 0;                                ///< Gauss-Legendre points through the thickness
  std::array<double, kMaxThicknessPoints> zeta{};  ///< ζ_g in [-t/2, t/2] [mm]
  std::array<double, kMaxThicknessPoints> weight{};  ///< w_g t, summing to t [mm]
};

/// The section of thickness t [mm] with n_points Gauss-Legendre points (KL13). Throws
/// plisse::Error unless t > 0 and kMinThicknessPoints <= n_points <= kMaxThicknessPoints.
ShellSection make_shell_section(double thickness, int n_points = kDefaultThicknessPoints);

}  // namespace plisse::shell
