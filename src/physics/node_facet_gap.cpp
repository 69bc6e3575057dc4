#include "physics/node_facet_gap.hpp"

#include <cmath>

#include "core/error.hpp"

namespace plisse {

namespace {

using Vec9d_ = Eigen::Matrix<double, 9, 1>;
using Mat9d_ = Eigen::Matrix<double, 9, 9>;
using Mat9x12d = Eigen::Matrix<double, 9, 12>;

/// T, the constant map x = (xs, xa, xb, xc) -> y = (e1, e2, w) = (xb - xa, xc - xa, xs - xa).
Mat9x12d coordinate_map() {
  const Mat3d I = Mat3d::Identity();
  Mat9x12d T = Mat9x12d::Zero();
  T.block<3, 3>(0, 3) = -I;  // e1 = xb - xa
  T.block<3, 3>(0, 6) = I;
  T.block<3, 3>(3, 3) = -I;  // e2 = xc - xa
  T.block<3, 3>(3, 9) = I;
  T.block<3, 3>(6, 0) = I;  // w = xs - xa
  T.block<3, 3>(6, 3) = -I;
  return T;
}

}  // namespace

NodeFacetGap node_facet_gap(const Vec3d& xs, const Vec3d& xa, const Vec3d& xb, const Vec3d& xc,
                            bool with_hessian) {
  const Vec3d e1 = xb - xa, e2 = xc - xa, w = xs - xa;
  const Vec3d a = e1.cross(e2);
  const double m = a.norm();
  PLISSE_CHECK(std::isfinite(m) && m > 1e-300,
               "degenerate contact facet: |(xb - xa) x (xc - xa)| = " << m);
  const Vec3d n = a / m;
  const double q = a.dot(w);

  NodeFacetGap out;
  out.n = n;
  out.g = q / m;  // (N9)

  // Barycentric coordinates of p = xs - g n (N10): the normal equations of e1, e2 for p - xa,
  // solved by Cramer's rule. Their determinant |e1|^2 |e2|^2 - (e1 . e2)^2 and numerators are
  // written with Lagrange's identity (u x v) . (r x s) = (u . r)(v . s) - (u . s)(v . r), which
  // avoids the cancellation of the Gram determinant on slender facets; e1 . p = e1 . w since the
  // normal part of w is orthogonal to e1 and e2.
  const double Nb = a.dot(w.cross(e2)) / (m * m);
  const double Nc = a.dot(e1.cross(w)) / (m * m);
  out.xi = Vec3d(1.0 - Nb - Nc, Nb, Nc);

  // First derivatives in y = (e1, e2, w): q (N11), m (N12), g = q/m (N13).
  Vec9d_ gq, gm;
  gq << e2.cross(w), w.cross(e1), a;
  gm << e2.cross(n), n.cross(e1), Vec3d::Zero();
  const Vec9d_ gy = (gq - out.g * gm) / m;

  const Mat9x12d T = coordinate_map();
  out.gradient = T.transpose() * gy;
  if (!with_hessian) return out;

  // Hessian of the triple product q (N11): zero diagonal blocks, skew off-diagonal blocks.
  Mat9d_ Hq = Mat9d_::Zero();
  Hq.block<3, 3>(0, 3) = -cross_matrix(w);
  Hq.block<3, 3>(0, 6) = cross_matrix(e2);
  Hq.block<3, 3>(3, 6) = -cross_matrix(e1);
  Hq.block<3, 3>(3, 0) = Hq.block<3, 3>(0, 3).transpose();
  Hq.block<3, 3>(6, 0) = Hq.block<3, 3>(0, 6).transpose();
  Hq.block<3, 3>(6, 3) = Hq.block<3, 3>(3, 6).transpose();

  // Hessian of m = |e1 x e2| (N12); m does not depend on w.
  Eigen::Matrix<double, 3, 6> J;
  J << -cross_matrix(e2), cross_matrix(e1);
  const Mat3d P = Mat3d::Identity() - n * n.transpose();
  Mat9d_ Hm = Mat9d_::Zero();
  Hm.topLeftCorner<6, 6>() = J.transpose() * P * J / m;
  Hm.block<3, 3>(0, 3) -= cross_matrix(n);
  Hm.block<3, 3>(3, 0) += cross_matrix(n);

  // Quotient rule (N13), with q/m = g.
  const Mat9d_ Hy = (Hq - (gq * gm.transpose() + gm * gq.transpose()) / m +
                     2.0 * out.g / m * gm * gm.transpose() - out.g * Hm) /
                    m;
  out.hessian = T.transpose() * Hy * T;
  // Every term is symmetric in exact arithmetic; the products above are so only to round-off.
  out.hessian = 0.5 * (out.hessian + out.hessian.transpose()).eval();
  return out;
}

}  // namespace plisse
