#pragma once
/// The outer surface as a source of material rings: the intersection of the reference surface
/// with a cone of constant latitude, sampled on triangle edges (docs/theory/wrinkles.md, sec. 2).
#include <array>
#include <vector>

#include "analysis/cylindrical_frame.hpp"
#include "core/types.hpp"

namespace plisse {

/// One point of a material ring: reference and deformed positions and unit normals.
struct RingPoint {
  Vec3d X;                 ///< reference position [mm] (on the cone phi = phi0)
  Vec3d x;                 ///< deformed position X + u [mm]
  Vec3d normal;            ///< deformed unit normal (interpolated vertex normals), outward
  Vec3d reference_normal;  ///< reference unit normal, same interpolation
};

/// Surface nodes, unique edges and area-weighted vertex normals of a triangulated surface, in
/// the reference and the deformed configuration. Owns copies of what it needs (the surface's
/// nodes only), so the caller's arrays may go away.
class RingSurface {
 public:
  /// `nodes`: reference coordinates of all mesh nodes [mm]; `triangles`: the surface triangles
  /// (node indices, outward normal by the right-hand rule, e.g. Mesh::surface_tags["outer"]);
  /// `displacement`: one vector per mesh node [mm], or empty for the reference configuration.
  /// Throws Error if an index is out of range or the sizes disagree.
  RingSurface(const std::vector<Vec3d>& nodes, const std::vector<std::array<int, 3>>& triangles,
              const std::vector<Vec3d>& displacement);

  /// Points of the ring at latitude `phi0` [rad] about `frame` (wrinkles.md, W4-W5): one per
  /// edge whose end nodes lie strictly on opposite sides of the cone (the crossing parameter is
  /// found on the cone to round-off by bisection, positions and normals are then interpolated
  /// linearly along the edge), plus every node lying on the cone (|f| <= 1e-12 r). Unordered.
  std::vector<RingPoint> sample(const CylindricalFrame& frame, double phi0) const;

  int n_nodes() const { return static_cast<int>(X_.size()); }
  int n_edges() const { return static_cast<int>(edges_.size()); }

 private:
  std::vector<Vec3d> X_, x_;   ///< reference and deformed positions of the surface nodes
  std::vector<Vec3d> n_, n0_;  ///< deformed and reference unit vertex normals
  std::vector<std::array<int, 2>> edges_;  ///< unique edges, local node indices
};

}  // namespace plisse
