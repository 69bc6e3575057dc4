#include "solver/unresisted_motion.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "physics/rigid_motion.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// A motion nearer than this to the tangent's null space (|K v| / (|K| |v|)) is free: exact null
/// vectors give round-off, about 1e-15.
constexpr double kUnresisted = 1e-10;

/// Destroys the PETSc objects it holds on every way out.
struct Owned {
  Mat K = nullptr;
  Vec Kv = nullptr;
  std::vector<Vec> v, y;
  ~Owned() {
    MatDestroy(&K);
    VecDestroy(&Kv);
    for (Vec& x : v) VecDestroy(&x);
    for (Vec& x : y) VecDestroy(&x);
  }
};

}  // namespace

std::string unresisted_rigid_motion(MixedModel& model) {
  const Mesh& mesh = model.mesh();
  // Every piece with its six motions: free_rigid_motions with nothing held.
  const std::vector<FreePiece> pieces = free_rigid_motions(mesh, {}, {});
  Owned o;
  o.K = model.create_matrix();
  if (!model.assemble_tangent(o.K).ok) return {};  // an inverted element: not this question
  PetscReal norm_K = 0.0;
  PLISSE_PETSC(MatNorm(o.K, NORM_INFINITY, &norm_K));
  if (!(norm_K > 0.0)) return {};
  std::vector<double> kept = model.state();
  for (const FreePiece& piece : pieces) {
    const int n = static_cast<int>(piece.motions.size());
    for (Vec& x : o.v) VecDestroy(&x);
    for (Vec& x : o.y) VecDestroy(&x);
    o.v.assign(static_cast<std::size_t>(n), nullptr);
    o.y.assign(static_cast<std::size_t>(n), nullptr);
    // v_i: the free part of motion i (the state set to it for get_free, then put back).
    for (int i = 0; i < n; ++i) {
      std::vector<double>& state = model.state();
      std::fill(state.begin(), state.end(), 0.0);
      for (int node : piece.members)
        for (int k = 0; k < 3; ++k)
          state[static_cast<std::size_t>(node_dof(node, k))] =
              piece.motions[static_cast<std::size_t>(i)].at(
                  mesh.nodes[static_cast<std::size_t>(node)])[k];
      o.v[static_cast<std::size_t>(i)] = model.create_vector();
      o.y[static_cast<std::size_t>(i)] = model.create_vector();
      model.get_free(o.v[static_cast<std::size_t>(i)]);
      PLISSE_PETSC(
          MatMult(o.K, o.v[static_cast<std::size_t>(i)], o.y[static_cast<std::size_t>(i)]));
    }
    model.state() = kept;
    // Gram matrices of the v_i and of the K v_i; the smallest |K v| / |v| over their span.
    Eigen::MatrixXd A(n, n), B(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) {
        PetscScalar a = 0.0, b = 0.0;
        PLISSE_PETSC(
            VecDot(o.v[static_cast<std::size_t>(i)], o.v[static_cast<std::size_t>(j)], &a));
        PLISSE_PETSC(
            VecDot(o.y[static_cast<std::size_t>(i)], o.y[static_cast<std::size_t>(j)], &b));
        A(i, j) = A(j, i) = a;
        B(i, j) = B(j, i) = b;
      }
    // Over the part of the span the free unknowns see (a motion held by prescribed components
    // everywhere has no free part).
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> span(A);
    const double largest = span.eigenvalues().maxCoeff();
    if (!(largest > 0.0)) continue;
    std::vector<int> seen;
    for (int i = 0; i < n; ++i)
      if (span.eigenvalues()[i] > 1e-12 * largest) seen.push_back(i);
    Eigen::MatrixXd W(n, static_cast<Eigen::Index>(seen.size()));
    for (std::size_t j = 0; j < seen.size(); ++j)
      W.col(static_cast<Eigen::Index>(j)) =
          span.eigenvectors().col(seen[j]) / std::sqrt(span.eigenvalues()[seen[j]]);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> resisted(W.transpose() * B * W);
    const Eigen::VectorXd c = W * resisted.eigenvectors().col(0);
    // |K v| / |v| of the weakest combination v = sum c_i v_i, from the vectors themselves: the
    // Gram matrix's eigenvalue is a square, whose round-off leaves its root uncertain by about
    // 1e-8 of the largest |K v_i|, too coarse for kUnresisted.
    if (o.Kv == nullptr) o.Kv = model.create_vector();
    PLISSE_PETSC(VecSet(o.Kv, 0.0));
    for (int i = 0; i < n; ++i) PLISSE_PETSC(VecAXPY(o.Kv, c[i], o.y[static_cast<std::size_t>(i)]));
    PetscReal norm_Kv = 0.0;
    PLISSE_PETSC(VecNorm(o.Kv, NORM_2, &norm_Kv));
    const double weakest = norm_Kv / std::sqrt(c.dot(A * c));
    if (!(weakest <= kUnresisted * norm_K)) continue;
    RigidMotion motion{Vec3d::Zero(), Vec3d::Zero(), piece.centre};
    for (int i = 0; i < n; ++i) {
      motion.translation += c[i] * piece.motions[static_cast<std::size_t>(i)].translation;
      motion.rotation += c[i] * piece.motions[static_cast<std::size_t>(i)].rotation;
    }
    // Round-off parts against the largest, so that the name reads "translation along y".
    const double scale = std::max(motion.translation.cwiseAbs().maxCoeff(),
                                  motion.rotation.cwiseAbs().maxCoeff() * piece.size);
    for (int k = 0; k < 3; ++k) {
      if (std::abs(motion.translation[k]) <= 1e-6 * scale) motion.translation[k] = 0.0;
      if (std::abs(motion.rotation[k]) * piece.size <= 1e-6 * scale) motion.rotation[k] = 0.0;
    }
    const int carrier = farthest_moved(motion, mesh, piece.members);
    char stiffness[120];
    std::snprintf(stiffness, sizeof stiffness,
                  ": the tangent's stiffness against it is %.1e of its largest, so the tangent "
                  "is singular",
                  weakest / norm_K);
    const std::string text = piece_text(piece, mesh) + " " +
                             free_motion_text(motion.describe(), mesh, carrier) + stiffness;
    return text;
  }
  return {};
}

}  // namespace plisse
