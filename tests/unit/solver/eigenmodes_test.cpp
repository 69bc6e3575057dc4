// lowest_eigenmodes (SLEPc, shift-invert with MUMPS) against a dense reference computed here with
// Eigen from the same assembled tangent: the pressure is condensed,
//   S = K_uu - K_up K_pp^-1 K_pu,                                     (eigenmodes.md, E3)
// restricted to the global volume constraint when K_pp is singular (exact incompressibility, E4),
// and S φ_u = λ M_u φ_u is solved by GeneralizedSelfAdjointEigenSolver with M_u the lumped nodal
// volume, recomputed here from the mesh. The two agree when SLEPc's operator, its treatment of
// the singular M (purification) and the scaling of the returned vectors are right.
//
// Model: a 4x4x4-cell cube (Kuhn tetrahedra), bottom fixed, top moved down and sideways, so the
// state is prestressed (compression and shear) and the tangent has a geometric part; 225 free
// displacement and 125 free pressure dofs. Tolerances: SLEPc is asked for a relative residual of
// 1e-12; for a symmetric pencil the eigenvalue error is of the order of the residual squared
// (Rayleigh quotient), so 1e-8 relative on λ leaves a wide margin for the dense solver's round-off
// (~1e-13 relative for these condition numbers).
#include "solver/eigenmodes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <string>

#include "mesh/box_mesh.hpp"
#include "mesh/shell_surface.hpp"
#include "physics/pressure_load.hpp"
#include "solver/newton_solver.hpp"
#include "solver/petsc_session.hpp"
#include "support/shell_mesh.hpp"

namespace plisse {
namespace {

/// The bottom face fixed and the top face moved by `top` [mm] (ramped over t in [0, 1]).
std::vector<ConstrainedComponent> clamp_bottom_move_top(const Mesh& mesh, const Vec3d& top) {
  std::vector<ConstrainedComponent> constraints;
  auto constrain = [&](const std::string& tag, const Vec3d& value) {
    std::set<int> nodes;
    for (int t : mesh.surface_tags.at(tag))
      for (int v : mesh.triangles[t]) nodes.insert(v);
    for (int v : nodes)
      for (int k = 0; k < 3; ++k) constraints.push_back({v, k, value(k), Ramp{0.0, 1.0}});
  };
  constrain("bottom", Vec3d::Zero());
  constrain("top", top);
  return constraints;
}

/// The assembled tangent over the free dofs as a dense matrix.
Eigen::MatrixXd dense_tangent(MixedModel& model) {
  Mat K = model.create_matrix();
  EXPECT_TRUE(model.assemble_tangent(K).ok);
  const int n = model.n_free();
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (PetscInt i = 0; i < n; ++i) {
    PetscInt n_cols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* values = nullptr;
    MatGetRow(K, i, &n_cols, &cols, &values);
    for (PetscInt j = 0; j < n_cols; ++j) dense(i, cols[j]) = values[j];
    MatRestoreRow(K, i, &n_cols, &cols, &values);
  }
  MatDestroy(&K);
  return dense;
}

/// Free-dof vector of a full state, in the free system's units (pressures over
/// MixedModel::pressure_weight, as the assembled tangent expects them).
Eigen::VectorXd free_part(const MixedModel& model, const std::vector<double>& state) {
  Eigen::VectorXd x(model.n_free());
  for (int d = 0; d < model.dofs().n_dofs(); ++d)
    if (const int eq = model.dofs().equation(d); eq >= 0)
      x[eq] = model.dofs().is_pressure(d) ? state[d] / model.pressure_weight() : state[d];
  return x;
}

/// Lumped nodal volume per free dof (V_e / 4 from each tetrahedron of the node), 0 on pressures.
Eigen::VectorXd lumped_volume(const MixedModel& model) {
  const Mesh& mesh = model.mesh();
  Eigen::VectorXd m = Eigen::VectorXd::Zero(model.n_free());
  for (const auto& tet : mesh.tets) {
    const Vec3d a = mesh.nodes[tet[1]] - mesh.nodes[tet[0]];
    const Vec3d b = mesh.nodes[tet[2]] - mesh.nodes[tet[0]];
    const Vec3d c = mesh.nodes[tet[3]] - mesh.nodes[tet[0]];
    const double volume = a.dot(b.cross(c)) / 6.0;
    for (int v : tet)
      for (int k = 0; k < 3; ++k)
        if (const int eq = model.dofs().equation(DofMap::dof(v, k)); eq >= 0) m[eq] += volume / 4.0;
  }
  return m;
}

/// Checks lowest_eigenmodes at the model's current state against the condensed dense problem.
void expect_matches_dense_reference(MixedModel& model, const EigenSettings& options,
                                    int expected_kernel) {
  const Eigen::MatrixXd K = dense_tangent(model);
  ASSERT_LT((K - K.transpose()).norm(), 1e-12 * K.norm()) << "the test assumes a symmetric tangent";
  const Eigen::VectorXd m = lumped_volume(model);
  std::vector<int> u, p;
  for (int d = 0; d < model.dofs().n_dofs(); ++d)
    if (const int eq = model.dofs().equation(d); eq >= 0)
      (d % DofMap::kPerNode == 3 ? p : u).push_back(eq);
  const auto block = [&](const std::vector<int>& rows, const std::vector<int>& cols) {
    Eigen::MatrixXd b(rows.size(), cols.size());
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < cols.size(); ++j) b(i, j) = K(rows[i], cols[j]);
    return b;
  };
  const Eigen::MatrixXd Kuu = block(u, u), Kup = block(u, p), Kpp = block(p, p);

  // K_pp is the condensed bubble, -Σ_e G_e^T K_bb^-1 G_e (minus M_p/κ when κ is finite). With
  // exact incompressibility it is singular, and exactly so: a constant pressure does no work on a
  // bubble (∫ cof F : Grad b dV = 0 by the Piola identity, b = 0 on the element boundary), so
  // its kernel is the constant pressure, whose multiplier enforces the global volume constraint
  // g^T u = 0 with g = K_up 1 (eigenmodes.md, E4). Otherwise K_pp is invertible.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> pp(Kpp);
  const Eigen::VectorXd& pp_values = pp.eigenvalues();
  const double pp_scale = pp_values.cwiseAbs().maxCoeff();
  std::vector<int> kernel, range;
  for (int i = 0; i < pp_values.size(); ++i)
    (std::abs(pp_values[i]) < 1e-10 * pp_scale ? kernel : range).push_back(i);
  std::cout << "K_pp: " << kernel.size() << " zero eigenvalue(s); the others in ["
            << pp_values(range.front()) << ", " << pp_values(range.back()) << "]\n";
  ASSERT_EQ(static_cast<int>(kernel.size()), expected_kernel);
  // Apart from the kernel, K_pp is negative definite and well conditioned.
  EXPECT_LT(pp_values.maxCoeff(), 1e-10 * pp_scale);
  EXPECT_LT(pp_scale / std::abs(pp_values(range.back())), 1e6);
  if (expected_kernel == 1) {
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(p.size());
    EXPECT_LT((Kpp * ones).norm(), 1e-12 * pp_scale * ones.norm()) << "kernel is not p = const";
  }
  Eigen::MatrixXd Kpp_pinv = Eigen::MatrixXd::Zero(p.size(), p.size());
  for (int i : range)
    Kpp_pinv += pp.eigenvectors().col(i) * pp.eigenvectors().col(i).transpose() / pp_values[i];
  // Z: orthonormal basis of {u : (K_up c)^T u = 0 for every kernel vector c}.
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(u.size(), u.size());
  if (!kernel.empty()) {
    Eigen::MatrixXd G(u.size(), kernel.size());
    for (size_t j = 0; j < kernel.size(); ++j) G.col(j) = Kup * pp.eigenvectors().col(kernel[j]);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(G);
    const Eigen::MatrixXd Q = qr.householderQ();
    Z = Q.rightCols(u.size() - kernel.size());
  }
  const Eigen::MatrixXd S = Z.transpose() * (Kuu - Kup * Kpp_pinv * Kup.transpose()) * Z;
  Eigen::VectorXd mu(u.size());
  for (size_t i = 0; i < u.size(); ++i) mu[i] = m[u[i]];
  const Eigen::MatrixXd Mz = Z.transpose() * mu.asDiagonal() * Z;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(
      0.5 * (S + S.transpose()), 0.5 * (Mz + Mz.transpose()));
  ASSERT_EQ(dense.info(), Eigen::Success);
  std::vector<double> reference(dense.eigenvalues().data(),
                                dense.eigenvalues().data() + dense.eigenvalues().size());
  std::sort(reference.begin(), reference.end(), [&](double a, double b) {
    return std::abs(a - options.target) < std::abs(b - options.target);
  });
  reference.resize(options.count);
  std::sort(reference.begin(), reference.end());

  const auto start = std::chrono::steady_clock::now();
  const std::vector<Eigenmode> modes = lowest_eigenmodes(model, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "lowest_eigenmodes: " << model.n_free() << " free dofs, " << seconds << " s\n";
  ASSERT_EQ(static_cast<int>(modes.size()), options.count);

  for (int i = 0; i < options.count; ++i) {
    const Eigenmode& mode = modes[i];
    std::cout << "  lambda_" << i << " = " << mode.eigenvalue << ", relative difference to dense "
              << (mode.eigenvalue - reference[i]) / reference[i] << "\n";
    EXPECT_NEAR(mode.eigenvalue, reference[i], 1e-8 * std::abs(reference[i])) << "mode " << i;
    if (i > 0) {
      EXPECT_LE(modes[i - 1].eigenvalue, mode.eigenvalue) << "not ascending";
    }

    ASSERT_EQ(mode.state.size(), model.state().size());
    for (int d = 0; d < model.dofs().n_dofs(); ++d) {
      if (model.dofs().equation(d) < 0) {
        EXPECT_EQ(mode.state[d], 0.0) << "constrained dof " << d;
      }
    }
    // Normalisation: the largest nodal |u| is 1, its largest component positive.
    double largest = 0.0;
    int node = -1;
    for (int v = 0; v < model.mesh().n_nodes(); ++v) {
      const Vec3d uv(mode.state[DofMap::dof(v, 0)], mode.state[DofMap::dof(v, 1)],
                     mode.state[DofMap::dof(v, 2)]);
      if (uv.norm() > largest) {
        largest = uv.norm();
        node = v;
      }
    }
    EXPECT_NEAR(largest, 1.0, 1e-12) << "mode " << i;
    const Vec3d uv(mode.state[DofMap::dof(node, 0)], mode.state[DofMap::dof(node, 1)],
                   mode.state[DofMap::dof(node, 2)]);
    const int component = [&] {
      int c = 0;
      for (int k = 1; k < 3; ++k)
        if (std::abs(uv[k]) > std::abs(uv[c])) c = k;
      return c;
    }();
    EXPECT_GT(uv[component], 0.0) << "mode " << i;

    // Residual of the full (unreduced) pencil, pressure rows included: K φ - λ M φ = 0. Relative
    // to |K| |φ|, with SLEPc's tolerance 1e-12 on the operator (K - σM)^-1 M and the condition of
    // K (~1e4 here) between the two measures.
    const Eigen::VectorXd x = free_part(model, mode.state);
    const Eigen::VectorXd r = K * x - mode.eigenvalue * m.cwiseProduct(x);
    EXPECT_LT(r.norm(), 1e-8 * K.norm() * x.norm()) << "mode " << i;
  }
}

TEST(Eigenmodes, PrestressedCubeMatchesCondensedDenseProblem) {
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {4, 4, 4});
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0,
                   clamp_bottom_move_top(mesh, Vec3d(0.05, 0.0, -0.15)));
  model.set_time(1.0);
  NewtonSettings settings;
  settings.rtol = 1e-10;
  NewtonSolver newton(model, settings);
  ASSERT_TRUE(newton.solve().converged);
  model.save_converged();
  expect_matches_dense_reference(model, EigenSettings{4, 0.0, 1e-12}, /*expected_kernel=*/1);
}

TEST(Eigenmodes, TargetInsideTheSpectrumNearlyIncompressibleRandomState) {
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {4, 4, 4});
  MixedModel model(mesh, make_material("mooney-rivlin", {{"c1", 0.4}, {"c2", 0.1}}), 1.0 / 50.0,
                   clamp_bottom_move_top(mesh, Vec3d::Zero()));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int d = 0; d < model.dofs().n_dofs(); ++d)
    if (model.dofs().equation(d) >= 0)
      model.state()[d] = (d % 4 == 3 ? 0.1 : 0.02) * uniform(random);
  // A target between eigenvalues (not at the bottom of the spectrum) exercises the selection
  // "nearest the target" and the ascending order of the result.
  expect_matches_dense_reference(model, EigenSettings{5, 20.0, 1e-12}, /*expected_kernel=*/0);
}

TEST(Eigenmodes, UnsymmetricTangentOfAFollowerPressure) {
  // A follower pressure on the open top face (its edges free) has an unsymmetric load stiffness
  // (docs/theory/loads.md, L5): the non-Hermitian path (GNHEP, MUMPS LU). κ is finite, so K_pp is
  // invertible and the reference is the eigenvalues of M_u^-1 S, S = K_uu - K_up K_pp^-1 K_pu.
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {4, 4, 4});
  const auto constraints = clamp_bottom_move_top(mesh, Vec3d::Zero());
  std::vector<ConstrainedComponent> bottom;
  for (const auto& c : constraints)
    if (mesh.nodes[c.node].z() == 0.0) bottom.push_back(c);
  std::vector<std::unique_ptr<ModelTerm>> terms;
  terms.push_back(std::make_unique<PressureLoad>(mesh, "p", "top", 0.3, Ramp{0.0, 1.0}, bottom, 0));
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 1.0 / 50.0, bottom,
                   std::move(terms));
  ASSERT_FALSE(model.symmetric());
  model.set_time(1.0);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int d = 0; d < model.dofs().n_dofs(); ++d)
    if (model.dofs().equation(d) >= 0)
      model.state()[d] = (d % 4 == 3 ? 0.1 : 0.02) * uniform(random);

  const Eigen::MatrixXd K = dense_tangent(model);
  ASSERT_GT((K - K.transpose()).norm(), 1e-6 * K.norm())
      << "the load stiffness should be unsymmetric";
  const Eigen::VectorXd m = lumped_volume(model);
  std::vector<int> u, p;
  for (int d = 0; d < model.dofs().n_dofs(); ++d)
    if (const int eq = model.dofs().equation(d); eq >= 0)
      (d % DofMap::kPerNode == 3 ? p : u).push_back(eq);
  const auto block = [&](const std::vector<int>& rows, const std::vector<int>& cols) {
    Eigen::MatrixXd b(rows.size(), cols.size());
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < cols.size(); ++j) b(i, j) = K(rows[i], cols[j]);
    return b;
  };
  const Eigen::MatrixXd S =
      block(u, u) - block(u, p) * block(p, p).partialPivLu().solve(block(p, u));
  Eigen::VectorXd inverse_mu(u.size());
  for (size_t i = 0; i < u.size(); ++i) inverse_mu[i] = 1.0 / m[u[i]];
  const Eigen::EigenSolver<Eigen::MatrixXd> dense(inverse_mu.asDiagonal() * S, false);
  ASSERT_EQ(dense.info(), Eigen::Success);
  std::vector<std::complex<double>> reference(
      dense.eigenvalues().data(), dense.eigenvalues().data() + dense.eigenvalues().size());
  const EigenSettings options{4, 0.0, 1e-12};
  std::sort(reference.begin(), reference.end(), [&](auto a, auto b) {
    return std::abs(a - options.target) < std::abs(b - options.target);
  });
  reference.resize(options.count);
  for (const auto& value : reference) {
    ASSERT_LT(std::abs(value.imag()), 1e-10 * std::abs(value)) << "the test wants real eigenvalues";
  }
  std::sort(reference.begin(), reference.end(), [](auto a, auto b) { return a.real() < b.real(); });

  const std::vector<Eigenmode> modes = lowest_eigenmodes(model, options);
  ASSERT_EQ(static_cast<int>(modes.size()), options.count);
  for (int i = 0; i < options.count; ++i) {
    const double expected = reference[i].real();
    std::cout << "  lambda_" << i << " = " << modes[i].eigenvalue
              << ", relative difference to dense " << (modes[i].eigenvalue - expected) / expected
              << "\n";
    EXPECT_NEAR(modes[i].eigenvalue, expected, 1e-8 * std::abs(expected)) << "mode " << i;
    const Eigen::VectorXd x = free_part(model, modes[i].state);
    const Eigen::VectorXd r = K * x - modes[i].eigenvalue * m.cwiseProduct(x);
    EXPECT_LT(r.norm(), 1e-8 * K.norm() * x.norm()) << "mode " << i;
  }
}

TEST(Eigenmodes, NonConvergenceIsASolverError) {
  // A tolerance below round-off cannot be met in two restarts: SLEPc stops short of `count`
  // converged pairs, which must come back as a SolverError (the run keeps its last state).
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {2, 2, 2});
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 1.0 / 50.0,
                   clamp_bottom_move_top(mesh, Vec3d::Zero()));
  PetscSession::insert_options("-eps_max_it 2");
  std::string message;
  try {
    lowest_eigenmodes(model, EigenSettings{4, 0.0, 1e-30});
  } catch (const SolverError& e) {
    message = e.what();
  }
  PetscOptionsClearValue(nullptr, "-eps_max_it");
  std::cout << message << "\n";
  EXPECT_NE(message.find("of 4 eigenpairs"), std::string::npos) << message;
}

TEST(Eigenmodes, ShellLumpedVolumesSumToAreaTimesThickness) {
  // A third of A_e t_e to each corner (eigenmodes.md, E2), t_e the triangle's: the sum is
  // Σ A_e t_e, the shell's volume, A t for a uniform thickness. The octant of a sphere of radius
  // 2 mm with a thickness that varies from triangle to triangle, then 0.1 mm thick.
  Mesh mesh = test::octahedral_sphere(2.0, 0.1, 4, true);
  const auto sum_of = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s;
  };
  double area = 0.0, volume = 0.0;
  for (int k = 0; k < 3; ++k) {
    std::vector<int> every_third;
    for (int t = k; t < static_cast<int>(mesh.triangles.size()); t += 3) every_third.push_back(t);
    set_shell_thickness(mesh, every_third, 0.1 + 0.01 * k);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3d X0 = mesh.nodes[tri[0]];
    const double a = 0.5 * (mesh.nodes[tri[1]] - X0).cross(mesh.nodes[tri[2]] - X0).norm();
    area += a;
    volume += a * (0.1 + 0.01 * static_cast<double>(t % 3));
  }
  std::cout << "relative error of the sum: " << sum_of(lumped_nodal_volumes(mesh)) / volume - 1.0
            << "\n";
  EXPECT_NEAR(sum_of(lumped_nodal_volumes(mesh)), volume, 1e-14 * volume);
  std::vector<int> all(mesh.triangles.size());
  std::iota(all.begin(), all.end(), 0);
  set_shell_thickness(mesh, all, 0.1);
  const std::vector<double> uniform = lumped_nodal_volumes(mesh);
  ASSERT_EQ(uniform.size(), mesh.nodes.size());
  std::cout << "uniform: " << sum_of(uniform) / (area * 0.1) - 1.0 << "\n";
  EXPECT_NEAR(sum_of(uniform), area * 0.1, 1e-14 * area * 0.1);
  EXPECT_GT(*std::min_element(uniform.begin(), uniform.end()), 0.0);
}

TEST(Eigenmodes, StretchedShellSheetMatchesDenseProblem) {
  // A flat sheet of 4 × 4 mm, 0.2 mm thick, in 32 shell triangles, its edge nodes held at a
  // biaxial stretch (1.1, 1.05) and its inner nodes at the homogeneous state, which is the
  // equilibrium: the pencil K φ = λ M φ has no pressure block (the shell has no pressure
  // unknowns), M the lumped A_e t / 3 of each triangle's corners, recomputed here. SLEPc's
  // eigenvalues against Eigen's dense generalized solver.
  const Mat3d Q = Eigen::AngleAxisd(0.4, Vec3d(1.0, 0.5, -0.3).normalized()).toRotationMatrix();
  const Mesh mesh = test::flat_square(Q, 4, 0.2);
  const Mat3d stretch = Q * Vec3d(1.1, 1.05, 1.0).asDiagonal() * Q.transpose();
  std::vector<ConstrainedComponent> held;
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d local = Q.transpose() * mesh.nodes[v];
    if (std::abs(std::abs(local.x()) - 2.0) > 1e-12 && std::abs(std::abs(local.y()) - 2.0) > 1e-12)
      continue;
    const Vec3d u = (stretch - Mat3d::Identity()) * mesh.nodes[v];
    for (int k = 0; k < 3; ++k) held.push_back({v, k, u[k], Ramp{0.0, 1.0}});
  }
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, held, {},
                   ElementFamily::shell);
  model.set_time(1.0);
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d u = (stretch - Mat3d::Identity()) * mesh.nodes[v];
    for (int k = 0; k < 3; ++k) model.state()[DofMap::dof(v, k)] = u[k];
  }
  model.save_converged();
  const Eigen::MatrixXd K = dense_tangent(model);
  ASSERT_EQ(model.dofs().n_free_pressure(), 0);
  Eigen::VectorXd m = Eigen::VectorXd::Zero(model.n_free());
  for (const auto& tri : mesh.triangles) {
    const Vec3d X0 = mesh.nodes[tri[0]];
    const double third =
        0.5 * (mesh.nodes[tri[1]] - X0).cross(mesh.nodes[tri[2]] - X0).norm() * 0.2 / 3.0;
    for (int v : tri)
      for (int k = 0; k < 3; ++k)
        if (const int eq = model.dofs().equation(DofMap::dof(v, k)); eq >= 0) m[eq] += third;
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(
      0.5 * (K + K.transpose()), Eigen::MatrixXd(m.asDiagonal()));
  ASSERT_EQ(dense.info(), Eigen::Success);
  const std::vector<Eigenmode> modes = lowest_eigenmodes(model, EigenSettings{4, 0.0, 1e-12});
  ASSERT_EQ(modes.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const double reference = dense.eigenvalues()[i];
    std::cout << "  lambda_" << i << " = " << modes[i].eigenvalue << ", relative difference to "
              << "dense " << (modes[i].eigenvalue - reference) / reference << "\n";
    EXPECT_GT(reference, 0.0);
    EXPECT_NEAR(modes[i].eigenvalue, reference, 1e-8 * std::abs(reference)) << "mode " << i;
  }
}

TEST(Eigenmodes, RefusesMoreModesThanDofs) {
  const Mesh mesh = make_box_mesh(Vec3d(1.0, 1.0, 1.0), {1, 1, 1});
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, {});
  EXPECT_THROW(lowest_eigenmodes(model, EigenSettings{model.n_free() + 1, 0.0, 1e-8}), Error);
}

}  // namespace
}  // namespace plisse
