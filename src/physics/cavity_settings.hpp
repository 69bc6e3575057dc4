#pragma once
/// What defines a fluid-filled cavity (physics/cavity.hpp solves it).
#include <string>

#include "core/error.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/ramp.hpp"

namespace plisse {

enum class CavityControl { volume, gas };

/// What a volume-controlled cavity's volume reaches at the end of its ramp (cavities.md, C8).
enum class VolumeTarget {
  ratio,     ///< V0 x volume_ratio (needs V0 > 0)
  absolute,  ///< `volume` [mm^3]
  change     ///< V0 + `volume_change` [mm^3] (a cavity that starts flat has V0 = 0)
};

/// A closed (or closed by symmetry planes) surface enclosing a fluid region
/// (docs/theory/cavities.md).
struct Cavity {
  std::string name;  ///< history columns `volume:<name>`, `pressure:<name>`
  SurfaceRef surface;
  CavityControl control = CavityControl::volume;
  VolumeTarget target = VolumeTarget::ratio;  ///< volume: which of the three below is given
  double volume_ratio = 1.0;                  ///< volume: V(end of ramp) / V0, > 0
  double volume = 0.0;                        ///< volume: V(end of ramp) [mm^3], > 0
  double volume_change = 0.0;                 ///< volume: V(end of ramp) − V0 [mm^3], != 0
  InputPlace target_place;                    ///< where the given one is written
  double initial_pressure = 0.0;              ///< gas: gauge pressure at t = 0 [MPa], >= 0
  double mass_ratio = 1.0;                    ///< gas: gas mass at end of ramp / initial mass, > 0
  double ambient_pressure = 0.1;              ///< gas: absolute ambient pressure [MPa], > 0
  /// gas: polytropic exponent, (p + p_amb) (V_gas / m)^gamma constant: 1 isothermal, 1.4 adiabatic
  /// air (cavities.md, C9)
  double gamma = 1.0;
  /// gas: the volume of a rigid reservoir the gas also fills [mm^3], of the whole body (the
  /// modelled part of a symmetric model holds its share)
  double reservoir_volume = 0.0;
  Ramp ramp;
  InputPlace place;
};

}  // namespace plisse
