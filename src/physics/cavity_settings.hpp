#pragma once
/// What defines a fluid-filled cavity (physics/cavity.hpp solves it).
#include <string>

#include "core/error.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/ramp.hpp"

namespace plisse {

enum class CavityControl { volume, gas };

/// A closed (or closed by symmetry planes) surface enclosing a fluid region
/// (docs/theory/cavities.md).
struct Cavity {
  std::string name;  ///< history columns `volume:<name>`, `pressure:<name>`
  SurfaceRef surface;
  CavityControl control = CavityControl::volume;
  double volume_ratio = 1.0;      ///< volume: V(end of ramp) / V0, > 0
  double initial_pressure = 0.0;  ///< gas: gauge pressure at t = 0 [MPa], >= 0
  double mass_ratio = 1.0;        ///< gas: gas mass at end of ramp / initial mass, > 0
  double ambient_pressure = 0.1;  ///< gas: absolute ambient pressure [MPa], > 0
  Ramp ramp;
  InputPlace place;
};

}  // namespace plisse
