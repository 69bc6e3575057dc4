#pragma once
/// Through-thickness columns of a membrane mesh: each tetrahedron belongs to the outer-surface
/// triangle nearest to its centroid (docs/theory/wrinkles.md, T1).
#include <array>
#include <vector>

#include "core/types.hpp"

namespace plisse {

/// The barycentric weights (wa, wb, wc) of the point of the closed triangle (a, b, c) nearest to p
/// (by Voronoi regions of the vertices, edges and face; Ericson, Real-Time Collision Detection,
/// sec. 5.1.5). A degenerate triangle gives its nearest corner.
Vec3d closest_point_weights(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c);

/// Distance from point p to the closed triangle (a, b, c) [mm]: to its closest_point_weights point.
double point_triangle_distance(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c);

/// For each tetrahedron, the index into `triangles` of the triangle nearest to its centroid, in
/// the configuration `nodes` (normally the reference one). Ties go to the lower index. Uses a
/// uniform grid of buckets (cell ~ the mean triangle edge, at most ~8 cells per triangle) searched
/// in growing shells until no unsearched cell can be nearer: about O(n_tets + n_triangles) for
/// a membrane. Throws Error if `triangles` is empty while `tets` is not, or an index is out of
/// range.
std::vector<int> assign_columns(const std::vector<Vec3d>& nodes,
                                const std::vector<std::array<int, 4>>& tets,
                                const std::vector<std::array<int, 3>>& triangles);

/// For each of `points`, the index into `triangles` (corner indices into `nodes`) of the nearest
/// triangle, by the same bucket search as assign_columns (ties to the lower index). Throws Error
/// if `triangles` is empty while `points` is not, or an index is out of range.
std::vector<int> nearest_triangles(const std::vector<Vec3d>& nodes,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const std::vector<Vec3d>& points);

}  // namespace plisse
