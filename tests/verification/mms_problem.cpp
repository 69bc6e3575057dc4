#include "verification/mms_problem.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <variant>

#include "mesh/generate.hpp"
#include "solver/mixed_model.hpp"
#include "solver/newton_solver.hpp"
#include "verification/simplex_quadrature.hpp"

namespace plisse::test {
namespace {

constexpr int kPerNode = DofMap::kPerNode;

/// Faces with the exact displacement prescribed, and faces with the dead traction P N, each with
/// its outward unit normal (the cube [0, 1]^3).
const char* const kDirichletFaces[] = {"left", "front", "bottom"};
struct TractionFace {
  const char* tag;
  Vec3d normal;
};
const TractionFace kTractionFaces[] = {
    {"right", Vec3d::UnitX()}, {"back", Vec3d::UnitY()}, {"top", Vec3d::UnitZ()}};

Mat3d cofactor(const Mat3d& F) {
  Mat3d cof;
  cof.col(0) = F.col(1).cross(F.col(2));
  cof.col(1) = F.col(2).cross(F.col(0));
  cof.col(2) = F.col(0).cross(F.col(1));
  return cof;
}

PointResponse evaluate(const AnyMaterial& material, const Mat3d& F) {
  return std::visit([&](const auto& m) { return m.evaluate(F); }, material);
}

}  // namespace

Mat3d total_stress(const MmsProblem& problem, const Vec3d& X) {
  const Mat3d F = problem.solution.F(X);
  return evaluate(problem.material, F).P - problem.solution.p(X) * cofactor(F);
}

Vec3d divergence_of_stress(const MmsProblem& problem, const Vec3d& X, double step) {
  const ManufacturedSolution& s = problem.solution;
  const Mat3d F = s.F(X);
  const PointResponse m = evaluate(problem.material, F);
  const Mat3d cof = cofactor(F);
  const Vec3d grad_p = s.grad_p(X);
  Vec3d div = -cof * grad_p;
  for (int J = 0; J < 3; ++J) {
    const Vec3d dX = step * Vec3d::Unit(J);
    const Mat3d dF = (s.F(X + dX) - s.F(X - dX)) / (2.0 * step);  // ∂F/∂X_J, error O(step²)
    // A acts on vec F column-major: row i + 3 J' is P(i, J'); take J' = J.
    const Vec9d dP = m.A * Eigen::Map<const Vec9d>(dF.data());
    div += dP.segment<3>(3 * J);
  }
  return div;
}

std::vector<double> manufactured_loads(const Mesh& mesh, const MmsProblem& problem) {
  const ManufacturedSolution& s = problem.solution;
  std::vector<double> load(static_cast<std::size_t>(kPerNode) * mesh.n_nodes(), 0.0);
  // Body force and pressure source (M8, M10), Duffy rule exact for degree 3 (27 points).
  const SimplexRule<3> rule = collapsed_tet_rule(3);
  for (const auto& tet : mesh.tets) {
    std::array<Vec3d, 4> Xa;
    for (int a = 0; a < 4; ++a) Xa[a] = mesh.nodes[tet[a]];
    const double V = (Xa[1] - Xa[0]).cross(Xa[2] - Xa[0]).dot(Xa[3] - Xa[0]) / 6.0;
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const auto& L = rule.points[q];
      const Vec3d X = L[0] * Xa[0] + L[1] * Xa[1] + L[2] * Xa[2] + L[3] * Xa[3];
      const Vec3d f0 = -divergence_of_stress(problem, X);
      const double source = (s.F(X).determinant() - 1.0) + problem.inverse_bulk_modulus * s.p(X);
      const double w = rule.weights[q] * V;
      for (int a = 0; a < 4; ++a) {
        for (int k = 0; k < 3; ++k) load[kPerNode * tet[a] + k] += w * L[a] * f0(k);
        load[kPerNode * tet[a] + 3] -= w * L[a] * source;
      }
    }
  }
  // Dead traction t0 = P N on the traction faces (M9), Duffy rule exact for degree 6.
  const SimplexRule<2> face_rule = collapsed_triangle_rule(4);
  for (const TractionFace& face : kTractionFaces) {
    for (int t : mesh.surface_tags.at(face.tag)) {
      const auto& tri = mesh.triangles[t];
      const std::array<Vec3d, 3> Xa = {mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]};
      const double area = 0.5 * (Xa[1] - Xa[0]).cross(Xa[2] - Xa[0]).norm();
      for (std::size_t q = 0; q < face_rule.points.size(); ++q) {
        const auto& L = face_rule.points[q];
        const Vec3d X = L[0] * Xa[0] + L[1] * Xa[1] + L[2] * Xa[2];
        const Vec3d t0 = total_stress(problem, X) * face.normal;
        const double w = face_rule.weights[q] * area;
        for (int a = 0; a < 3; ++a)
          for (int k = 0; k < 3; ++k) load[kPerNode * tri[a] + k] += w * L[a] * t0(k);
      }
    }
  }
  return load;
}

std::vector<ConstrainedComponent> manufactured_constraints(const Mesh& mesh,
                                                           const ManufacturedSolution& solution) {
  std::set<int> nodes;
  for (const char* tag : kDirichletFaces)
    for (int t : mesh.surface_tags.at(tag))
      for (int v : mesh.triangles[t]) nodes.insert(v);
  std::vector<ConstrainedComponent> constraints;
  for (int v : nodes) {
    const Vec3d u = solution.u(mesh.nodes[v]);
    for (int k = 0; k < 3; ++k) constraints.push_back({v, k, u(k), Ramp{0.0, 1.0}});
  }
  return constraints;
}

FieldErrors compute_errors(const Mesh& mesh, const std::vector<double>& state,
                           const ManufacturedSolution& solution, int points_per_direction) {
  const SimplexRule<3> rule = collapsed_tet_rule(points_per_direction);
  FieldErrors e;
  for (const auto& tet : mesh.tets) {
    std::array<Vec3d, 4> Xa, ua;
    Eigen::Vector4d pa;
    Mat3d jacobian;
    for (int a = 0; a < 4; ++a) {
      Xa[a] = mesh.nodes[tet[a]];
      ua[a] = Eigen::Map<const Vec3d>(&state[kPerNode * tet[a]]);
      pa(a) = state[kPerNode * tet[a] + 3];
    }
    for (int a = 1; a < 4; ++a) jacobian.col(a - 1) = Xa[a] - Xa[0];
    const double V = jacobian.determinant() / 6.0;
    const Mat3d inverse = jacobian.inverse();  // row a-1 = Grad N_a
    Mat3d grad_u_h = Mat3d::Zero();
    for (int a = 1; a < 4; ++a) grad_u_h += (ua[a] - ua[0]) * inverse.row(a - 1);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const auto& L = rule.points[q];
      const Vec3d X = L[0] * Xa[0] + L[1] * Xa[1] + L[2] * Xa[2] + L[3] * Xa[3];
      const Vec3d u_h = L[0] * ua[0] + L[1] * ua[1] + L[2] * ua[2] + L[3] * ua[3];
      const double p_h = L[0] * pa(0) + L[1] * pa(1) + L[2] * pa(2) + L[3] * pa(3);
      const double w = rule.weights[q] * V;
      const Vec3d u = solution.u(X);
      const Mat3d G = solution.grad_u(X);
      const double p = solution.p(X);
      e.u_L2 += w * (u - u_h).squaredNorm();
      e.u_H1 += w * (G - grad_u_h).squaredNorm();
      e.p_L2 += w * (p - p_h) * (p - p_h);
      e.u_L2_exact += w * u.squaredNorm();
      e.u_H1_exact += w * G.squaredNorm();
      e.p_L2_exact += w * p * p;
    }
  }
  for (double* v : {&e.u_L2, &e.u_H1, &e.p_L2, &e.u_L2_exact, &e.u_H1_exact, &e.p_L2_exact})
    *v = std::sqrt(*v);
  return e;
}

MmsLevel solve_manufactured(const MmsProblem& problem, int divisions) {
  const auto t0 = std::chrono::steady_clock::now();
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 1.0;
  spec.divisions = divisions;
  const Mesh mesh = generate_mesh(spec);
  const ManufacturedSolution& s = problem.solution;
  MixedModel model(mesh, problem.material, problem.inverse_bulk_modulus,
                   manufactured_constraints(mesh, s));
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d u = s.u(mesh.nodes[v]);
    for (int k = 0; k < 3; ++k) model.state()[kPerNode * v + k] = u(k);
    model.state()[kPerNode * v + 3] = s.p(mesh.nodes[v]);
  }
  model.set_external_force(manufactured_loads(mesh, problem), Ramp{0.0, 1.0});
  model.set_time(1.0);
  NewtonSettings settings;
  // Relative to the interpolant's residual: the algebraic error left is then ~1e-6 of the distance
  // between interpolant and discrete solution, itself of the size of the discretisation error.
  settings.rtol = 1e-6;
  settings.atol = 1e-14;
  settings.max_iterations = 20;
  NewtonSolver newton(model, settings);
  const NewtonResult result = newton.solve();
  MmsLevel level;
  level.divisions = divisions;
  level.h = 1.0 / divisions;
  level.n_free = model.n_free();
  level.newton_iterations = result.iterations;
  level.final_residual = result.residual_norm;
  level.residual_history = result.residual_history;
  level.converged = result.converged;
  level.errors = compute_errors(mesh, model.state(), s);
  level.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return level;
}

double observed_rate(const std::vector<MmsLevel>& levels, std::size_t i,
                     double FieldErrors::*error) {
  return std::log(levels[i - 1].errors.*error / (levels[i].errors.*error)) /
         std::log(levels[i - 1].h / levels[i].h);
}

std::string convergence_table(const std::string& title, const std::vector<MmsLevel>& levels) {
  std::ostringstream out;
  char line[256];
  out << title << "\n";
  std::snprintf(line, sizeof line, "%6s %9s %7s %4s %11s %5s %11s %5s %11s %5s %7s\n", "n", "h",
                "free", "it", "|u-uh|L2", "rate", "|u-uh|H1", "rate", "|p-ph|L2", "rate", "time/s");
  out << line;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const MmsLevel& l = levels[i];
    auto rate = [&](double FieldErrors::*e) { return i == 0 ? 0.0 : observed_rate(levels, i, e); };
    std::snprintf(line, sizeof line,
                  "%6d %9.5f %7d %4d %11.4e %5.2f %11.4e %5.2f %11.4e %5.2f %7.2f\n", l.divisions,
                  l.h, l.n_free, l.newton_iterations, l.errors.u_L2, rate(&FieldErrors::u_L2),
                  l.errors.u_H1, rate(&FieldErrors::u_H1), l.errors.p_L2, rate(&FieldErrors::p_L2),
                  l.seconds);
    out << line;
  }
  if (!levels.empty()) {
    const FieldErrors& e = levels.front().errors;
    std::snprintf(line, sizeof line, "exact norms: |u|L2 = %.4e, |Grad u|L2 = %.4e, |p|L2 = %.4e\n",
                  e.u_L2_exact, e.u_H1_exact, e.p_L2_exact);
    out << line;
  }
  return out.str();
}

}  // namespace plisse::test
