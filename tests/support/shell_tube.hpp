#pragma once
/// What the shell air-beam tests (tests/verification/wrinkling/air_beam_*shell*,
/// air_beam_full_size) share: the reference centroids of a shell mesh's triangles, and the row of
/// the closed tube's axial membrane force after the pressure.
#include <string>
#include <vector>

#include "mesh/generate.hpp"
#include "mesh/mesh.hpp"
#include "support/run_plisse.hpp"
#include "support/validation_claim.hpp"

namespace plisse::test {

/// The mid-surface of the half tube (z >= 0) along x that `mesh: {generate: tube, symmetry:
/// half}` gives a shell case (the VTU files hold no connectivity to read) [mm].
inline Mesh half_tube_shell(double radius, double length, double thickness, double size) {
  MeshGenerationSpec spec;
  spec.kind = "tube";
  spec.radius = radius;
  spec.length = length;
  spec.thickness = thickness;
  spec.element_size = size;
  spec.symmetry = Symmetry::half;
  return generate_shell_surface(spec);
}

/// The centroid of each triangle of `mesh` in the reference configuration [mm].
inline std::vector<Vec3d> triangle_centroids(const Mesh& mesh) {
  std::vector<Vec3d> centroids;
  centroids.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    Vec3d c = Vec3d::Zero();
    for (int n : t) c += mesh.nodes[static_cast<std::size_t>(n)] / 3.0;
    centroids.push_back(c);
  }
  return centroids;
}

/// How the rows name a shell mesh of in-surface element size `size` [mm].
inline std::string shell_mesh_text(double size) {
  return "h = " + six_digits(size) + " mm, shell triangles";
}

/// The row `row` of a closed tube with a shell wall: N_x after the pressure, at the section
/// `where` ("mid-length", "mid-span"), over p r / 2 (`ratio`), against the end plates'
/// equilibrium within 0.25 %: the flat triangles are chords of the circle, 1 - cos(pi / 2n) below
/// it at n divisions of the half circle.
inline void expect_closed_tube_axial_force(const std::string& row, const std::string& subject,
                                           const std::string& where, const std::string& mesh,
                                           double ratio) {
  expect_claim({.row = row,
                .subject = subject,
                .quantity = "membrane force N_x at " + where + " after the pressure, over p r/2",
                .mesh = mesh,
                .measured = ratio,
                .reference = 1.0,
                .source = "closed tube's equilibrium, N_x = p r/2",
                .low = -0.0025,
                .high = 0.0025,
                .why = "the flat triangles are chords of the circle"});
}

}  // namespace plisse::test
