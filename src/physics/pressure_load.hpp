#pragma once
/// Follower pressure on a tagged surface: the traction -p n acts on the deformed surface, with its
/// consistent load stiffness (docs/theory/loads.md).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/cap_closure.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "physics/ramp.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// A `loads:` entry of type pressure, as the case file gives it (terms/pressure_load.cpp).
struct PressureLoadSettings {
  std::string name;    ///< history columns `pressure:<name>`, `volume:<name>` ...
  SurfaceRef surface;  ///< the loaded surface
  double value = 0.0;  ///< [MPa] at the end of the ramp, positive against the outward normal
  /// The caps that close the surface's rims (cavities.md, C14): the pressure pushes on them too.
  std::vector<std::string> caps;
  InputPlace caps_place;
  Ramp ramp;
  InputPlace place;
};

class PressureLoad : public ModelTerm {
 public:
  /// `value` [MPa] at the end of `ramp`; positive pushes against the body's outward normal (on a
  /// balloon's `inner` surface it inflates). Borrows `mesh`. `constraints` decide whether the load
  /// stiffness is symmetric (see pressure_stiffness_is_symmetric).
  /// `mirror_planes`: the model's (dirichlet.hpp), which scale `full_volume:<name>`. The rims
  /// that one of `caps` ties are closed by it (cavities.md, C14-C16): the cap carries the
  /// pressure on the area the rim encloses. Throws InputError at `caps_place` for a cap that ties
  /// no rim of the surface.
  PressureLoad(const Mesh& mesh, std::string name, const std::string& surface, double value,
               Ramp ramp, const std::vector<ConstrainedComponent>& constraints, int mirror_planes,
               const std::vector<CapNodes>& caps = {}, const InputPlace& caps_place = {});

  bool symmetric() const override { return symmetric_; }
  /// The closing caps' rim nodes with one another (add_cap_closure_couplings).
  void add_couplings(std::vector<std::pair<int, int>>& pairs) const override;
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  /// `pressure:<name>`; when the surface is closed, by itself or by the planes x, y, z = 0
  /// (closing_planes), also `volume:<name>`, the volume it encloses, and when mirror planes are
  /// among those planes `full_volume:<name>`, the whole body's.
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;
  double pressure(double t) const { return value_ * ramp_.factor(t); }

 private:
  const Mesh& mesh_;
  std::string name_;
  std::vector<SurfaceFace> faces_;    ///< outward oriented, 3 or 6 nodes
  std::vector<CapClosure> closures_;  ///< the caps that close the surface's rims
  double value_;
  Ramp ramp_;
  bool symmetric_;
  std::optional<int> closing_planes_;  ///< the planes that close the rest, when all is closed
  int full_body_factor_ = 1;           ///< of the closing planes that are mirror planes
};

/// The load stiffness of a follower pressure is symmetric when the loaded surface is closed, or
/// when each edge of its boundary lies in a symmetry plane whose normal displacement is
/// constrained at its nodes (the two ends, and the edge node of a 6-node face), or all those
/// nodes are fixed: the boundary term p (du x dv) . dx then vanishes (docs/theory/loads.md, L5).
/// The rims of `closures` are closed (by their caps' cones, cavities.md C16).
bool pressure_stiffness_is_symmetric(const Mesh& mesh, const std::vector<SurfaceFace>& faces,
                                     const std::vector<ConstrainedComponent>& constraints,
                                     const std::vector<CapClosure>& closures = {});

}  // namespace plisse
