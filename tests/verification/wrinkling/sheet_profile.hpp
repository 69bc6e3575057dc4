#pragma once
/// The wrinkles across the middle of a stretched sheet (validation/sheet-tension-wrinkling.yaml),
/// measured as scripts/sheet_wrinkles.py measures them for the study
/// (docs/studies/sheet-tension.md): the top-surface profile w(y) = u_z along the mirror line x =
/// L/2 of the quarter model (of a shell's mesh, all of whose nodes lie in one plane, the
/// mid-surface's), mirrored about y = 0 to the full width; its amplitude max |w|; its crests
/// (alternating extrema of at least 10 % of the amplitude; none on a profile no higher than
/// `flat`); and the wavelength, twice the mean spacing of the zero crossings between consecutive
/// crests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "output/pvd_writer.hpp"
#include "output/run_directory.hpp"
#include "output/vtu_reader.hpp"

namespace plisse::test {

struct SheetProfile {
  double strain = 0.0;      ///< nominal strain, -u_x(clamp) / (L/2)
  double amplitude = 0.0;   ///< max |w| [mm]
  int crests = 0;           ///< counted crests across the full width
  double wavelength = 0.0;  ///< [mm]; 0 with fewer than two crests
};

/// The profile of one state: `reference` and `displacement` per node of the quarter model; a
/// profile whose amplitude is at most `flat` [mm] has no crests (the script's 1e-4 t: a shell
/// that has flattened again is flat to round-off, whose undulations are not crests).
inline SheetProfile measure_sheet(const std::vector<Vec3d>& reference,
                                  const std::vector<Vec3d>& displacement, double flat = 0.0) {
  double half_length = 0.0, z_min = 1e300, z_max = -1e300;
  for (const Vec3d& x : reference) {
    half_length = std::max(half_length, x.x());
    z_min = std::min(z_min, x.z());
    z_max = std::max(z_max, x.z());
  }
  SheetProfile p;
  double clamp_sum = 0.0;
  int clamp_nodes = 0;
  const bool mid_surface = z_max == z_min;      // a shell's nodes: all of them are measured
  std::vector<std::pair<double, double>> line;  // (y, w)
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const Vec3d& x = reference[i];
    if (x.x() < 1e-9 * half_length) {
      clamp_sum += displacement[i].x();
      ++clamp_nodes;
    }
    if ((mid_surface || x.z() > 0.5 * (z_min + z_max)) &&
        std::abs(x.x() - half_length) < 1e-6 * half_length)
      line.emplace_back(x.y(), displacement[i].z());
  }
  p.strain = -clamp_sum / clamp_nodes / half_length;
  std::sort(line.begin(), line.end());
  std::vector<double> y, w;
  for (auto it = line.rbegin(); it != line.rend(); ++it)
    if (it->first > 1e-9) y.push_back(-it->first), w.push_back(it->second);
  for (const auto& [yi, wi] : line) y.push_back(yi), w.push_back(wi);
  for (double wi : w) p.amplitude = std::max(p.amplitude, std::abs(wi));
  if (p.amplitude <= flat) return p;

  // Alternating extrema of at least 10 % of the amplitude (of two of one sign, the larger).
  std::vector<std::size_t> crest;
  const std::size_t n = w.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double left = k > 0 ? w[k - 1] : -w[k], right = k + 1 < n ? w[k + 1] : -w[k];
    const bool extremum =
        (w[k] > 0 && w[k] >= left && w[k] >= right) || (w[k] < 0 && w[k] <= left && w[k] <= right);
    if (!extremum || std::abs(w[k]) < 0.1 * p.amplitude) continue;
    if (!crest.empty() && (w[crest.back()] > 0) == (w[k] > 0)) {
      if (std::abs(w[k]) > std::abs(w[crest.back()])) crest.back() = k;
      continue;
    }
    crest.push_back(k);
  }
  p.crests = static_cast<int>(crest.size());
  std::vector<double> zeros;
  for (std::size_t c = 0; c + 1 < crest.size(); ++c)
    for (std::size_t k = crest[c]; k < crest[c + 1]; ++k)
      if ((w[k] > 0) != (w[k + 1] > 0) && w[k + 1] != 0.0) {
        zeros.push_back(y[k] - w[k] * (y[k + 1] - y[k]) / (w[k + 1] - w[k]));
        break;
      }
  if (zeros.size() >= 2)
    p.wavelength = 2.0 * (zeros.back() - zeros.front()) / static_cast<double>(zeros.size() - 1);
  return p;
}

/// The profile of every written step of the run in `dir` (its solution.pvd) but step 0, the sheet
/// before the first step; `mesh` is the run's own (generated again by the caller), `flat` as for
/// measure_sheet. A step file whose displacement does not fit the mesh fails the test and ends the
/// list there.
inline std::vector<SheetProfile> measure_sheet_run(const std::filesystem::path& dir,
                                                   const Mesh& mesh, double flat = 0.0) {
  std::vector<SheetProfile> steps;
  for (const PvdEntry& entry : read_pvd(dir / "solution.pvd")) {
    if (entry.file == RunDirectory::step_file_name(0)) continue;
    const VtuField u = read_vtu_point_field(dir / entry.file, "displacement");
    EXPECT_EQ(u.values.size(), 3u * static_cast<std::size_t>(mesh.n_nodes())) << entry.file;
    if (u.values.size() != 3u * static_cast<std::size_t>(mesh.n_nodes())) break;
    std::vector<Vec3d> displacement(static_cast<std::size_t>(mesh.n_nodes()));
    for (std::size_t i = 0; i < displacement.size(); ++i)
      displacement[i] = Vec3d(u.values[3 * i], u.values[3 * i + 1], u.values[3 * i + 2]);
    steps.push_back(measure_sheet(mesh.nodes, displacement, flat));
  }
  return steps;
}

/// The time of the first step the run's log reports a new instability at ("step 7: t =
/// 0.0167562: new instability, ..."), 0 when there is none.
inline double first_instability_time(const std::string& log_path) {
  std::ifstream log(log_path);
  for (std::string line; std::getline(log, line);) {
    const auto t = line.find(": t = ");
    if (line.find("new instability") != std::string::npos && t != std::string::npos)
      return std::stod(line.substr(t + 6));
  }
  return 0.0;
}

/// Cerda & Mahadevan's wavelength (2003, Phys. Rev. Lett. 90, 074302) of a sheet of length
/// `length` and thickness `thickness` [mm] at the nominal strain `strain`, for nu = 1/2:
/// lambda = (2 pi L t)^(1/2) / (3 (1 - nu^2) eps)^(1/4) [mm].
inline double cerda_mahadevan(double strain, double length, double thickness) {
  const double nu = 0.5;
  return std::sqrt(2.0 * std::numbers::pi * length * thickness) /
         std::pow(3.0 * (1.0 - nu * nu) * strain, 0.25);
}

/// Prints each step of `steps` to `out`: strain, amplitude over t, crests, wavelength and its
/// ratio to Cerda & Mahadevan's for the sheet of `length` and `thickness` [mm].
inline void print_sheet_steps(std::ostream& out, const std::vector<SheetProfile>& steps,
                              double length, double thickness) {
  for (const auto& s : steps)
    out << "  strain " << s.strain << " amplitude/t " << s.amplitude / thickness << " crests "
        << s.crests << " wavelength " << s.wavelength << " / CM "
        << (s.wavelength > 0 ? s.wavelength / cerda_mahadevan(s.strain, length, thickness) : 0.0)
        << "\n";
}

/// The least-squares line through the points (log x, log y): the exponent of a power law y ~ x^a
/// and the means of the logarithms. Precondition: at least two distinct x.
struct PowerLaw {
  double exponent = 0.0;
  double mean_log_x = 0.0, mean_log_y = 0.0;
};

inline PowerLaw fit_power_law(const std::vector<std::pair<double, double>>& points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [x, y] : points) {
    const double lx = std::log(x), ly = std::log(y);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  const double n = static_cast<double>(points.size());
  return {(n * sxy - sx * sy) / (n * sxx - sx * sx), sx / n, sy / n};
}

}  // namespace plisse::test
