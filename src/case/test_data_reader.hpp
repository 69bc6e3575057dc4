#pragma once
/// Reads material test data for `plisse fit` (docs/fit.md, "Data file"): a CSV file with the
/// header `mode,stretch,stress` (in any order) and one measured point per line,
///   mode     uniaxial | equibiaxial (or biaxial) | planar (or pure-shear)
///   stretch  λ > 0, not 1
///   stress   nominal stress (force / undeformed area) [MPa], non-zero, > 0 for λ > 1 and < 0
///            for λ < 1
/// Blank lines and lines starting with '#' are skipped. Every broken rule is an InputError with
/// the file, line, column name and the rule.
#include <filesystem>
#include <vector>

#include "material/material_fit.hpp"

namespace plisse {

/// Largest data file read [bytes]: far above any test campaign, far below the memory.
inline constexpr std::uintmax_t kMaxTestDataBytes = std::uintmax_t{16} << 20;

std::vector<TestPoint> read_test_data(const std::filesystem::path& path);

}  // namespace plisse
