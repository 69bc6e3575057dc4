#include "element/tet_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "element/bubble.hpp"

namespace plisse::mini {

TetGeometry compute_tet_geometry(const std::array<Vec3d, 4>& X) {
  Mat3d jacobian;  // columns X_a - X_0: dX/dL_a for a = 1..3
  for (int a = 1; a < 4; ++a) jacobian.col(a - 1) = X[a] - X[0];
  const double det = jacobian.determinant();
  double size = 0.0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) size = std::max(size, (X[a] - X[b]).norm());
  // Degenerate to working precision counts as zero volume: det below 1e-12 h³ is roundoff of a
  // flat element (a regular tetrahedron has det = h³/√2).
  PLISSE_CHECK(std::isfinite(det) && det > 1e-12 * size * size * size,
               "tetrahedron with corners (" << X[0].transpose() << "), (" << X[1].transpose()
                                            << "), (" << X[2].transpose() << "), ("
                                            << X[3].transpose() << ") has volume " << det / 6.0
                                            << " <= 0 (inverted or degenerate element)");
  TetGeometry g;
  g.volume = det / 6.0;
  const Mat3d inverse = jacobian.inverse();  // row a-1 = Grad L_a
  g.grad_N[0].setZero();
  for (int a = 1; a < 4; ++a) {
    g.grad_N[a] = inverse.row(a - 1).transpose();
    g.grad_N[0] -= g.grad_N[a];
  }
  g.size = size;
  for (int q = 0; q < kQuadPoints; ++q) {
    g.grad_bubble[q] = bubble_gradient(kQuadrature.points[q], g.grad_N);
    g.weight[q] = kQuadrature.weights[q] * g.volume;
  }
  return g;
}

}  // namespace plisse::mini
