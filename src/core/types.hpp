#pragma once
/// Small fixed-size math types shared by every folder (Eigen, column-major).
#include <Eigen/Dense>

namespace plisse {

template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
using Mat3d = Mat3<double>;
using Vec3d = Vec3<double>;
/// Fourth-order tensor acting on vec(F) (9 components, column-major vec).
using Mat9d = Eigen::Matrix<double, 9, 9>;
using Vec9d = Eigen::Matrix<double, 9, 1>;

/// [v]x, the matrix of the cross product: [v]x w = v x w.
inline Mat3d cross_matrix(const Vec3d& v) {
  Mat3d s;
  s << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return s;
}

}  // namespace plisse
