#include "solver/branch_start.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "solver/petsc_call.hpp"

namespace plisse {
namespace {

/// Free-dof vectors of one model, destroyed on every way out.
class FreeVectors {
 public:
  explicit FreeVectors(const MixedModel& model) : model_(model) {}
  ~FreeVectors() {
    for (Vec& x : vectors_) VecDestroy(&x);
  }
  FreeVectors(const FreeVectors&) = delete;
  FreeVectors& operator=(const FreeVectors&) = delete;
  Vec make() {
    vectors_.push_back(model_.create_vector());
    return vectors_.back();
  }

 private:
  const MixedModel& model_;
  std::vector<Vec> vectors_;
};

/// The residual at x0 + s phi + s² v (v may be null) into `f`; returns phi · f. `x` is scratch.
double path_residual(MixedModel& model, Vec x0, Vec phi, Vec v, double s, Vec x, Vec f) {
  PLISSE_PETSC(VecCopy(x0, x));
  PLISSE_PETSC(VecAXPY(x, s, phi));
  if (v) PLISSE_PETSC(VecAXPY(x, s * s, v));
  model.set_free(x);
  const AssemblyStatus status = model.assemble_residual(f);
  PLISSE_CHECK(status.ok, "the branch switch's estimate met an inverted element ("
                              << status.worst_element << ") at the mode's amplitude " << s
                              << " mm");
  PetscScalar g = 0.0;
  PLISSE_PETSC(VecDot(phi, f, &g));
  return g;
}

/// The two sides' buckled states are taken as equally near when their amplitudes differ by less
/// than this fraction (S10a): a symmetric bifurcation, whose q is round-off.
constexpr double kSameDistance = 0.01;

/// The root of k + q s + c s² = 0 nearest 0 (the positive one when both are equally near), or 0
/// when k >= 0 or there is no real root.
double nearest_root(double k, double q, double c) {
  if (!(k < 0.0)) return 0.0;
  const double discriminant = q * q - 4.0 * k * c;
  if (discriminant < 0.0) return 0.0;
  if (c == 0.0) return q != 0.0 ? -k / q : 0.0;
  // The two roots without cancellation: s1 = (-q - sign(q) sqrt(D)) / (2c), s2 = k / (c s1).
  const double t = -0.5 * (q + std::copysign(std::sqrt(discriminant), q));
  const double s1 = t / c, s2 = t != 0.0 ? k / t : s1;
  const double low = std::min(s1, s2), high = std::max(s1, s2);
  if (high <= 0.0) return high;  // both on the negative side: the larger is nearer
  if (low >= 0.0) return low;
  return -low < (1.0 - kSameDistance) * high ? low : high;
}

}  // namespace

BranchStart asymptotic_branch_start(MixedModel& model, Mat factor, const std::vector<double>& mode,
                                    double h) {
  PLISSE_CHECK(factor != nullptr, "the branch switch's estimate needs the tangent's factor");
  PLISSE_CHECK(mode.size() == model.state().size(),
               "the mode has " << mode.size() << " entries, the state " << model.state().size());
  PLISSE_CHECK(h > 0.0, "the branch switch's difference step must be positive, not " << h);
  FreeVectors vectors(model);
  const Vec x0 = vectors.make(), phi = vectors.make(), x = vectors.make(), f = vectors.make();
  const Vec r = vectors.make(), v = vectors.make();
  BranchStart start;
  // Restores the converged state on every way out.
  struct Restore {
    MixedModel& model;
    ~Restore() { model.restore_converged(); }
  } restore{model};

  // Φ: the mode's free vector (the pressures weighted as get_free weighs them).
  model.get_free(x0);
  const std::vector<double> u = model.state();
  for (std::size_t i = 0; i < u.size(); ++i) model.state()[i] = u[i] + mode[i];
  model.get_free(phi);
  PLISSE_PETSC(VecAXPY(phi, -1.0, x0));
  model.state() = u;

  // r = -½ R″[Φ, Φ] = -(R(u + hΦ) + R(u - hΦ) - 2 R(u)) / (2 h²), without its part along Φ.
  const double g0 = path_residual(model, x0, phi, nullptr, 0.0, x, r);
  PLISSE_PETSC(VecScale(r, 2.0));
  path_residual(model, x0, phi, nullptr, h, x, f);
  PLISSE_PETSC(VecAXPY(r, -1.0, f));
  path_residual(model, x0, phi, nullptr, -h, x, f);
  PLISSE_PETSC(VecAXPY(r, -1.0, f));
  PLISSE_PETSC(VecScale(r, 0.5 / (h * h)));
  PetscScalar along = 0.0, phi_phi = 0.0;
  PLISSE_PETSC(VecDot(phi, r, &along));
  PLISSE_PETSC(VecDot(phi, phi, &phi_phi));
  PLISSE_PETSC(VecAXPY(r, -along / phi_phi, phi));
  // V = K⁻¹ r: the second-order field, with no component along the critical mode (S10a).
  PLISSE_PETSC(MatSolve(factor, r, v));

  // g along the path u + sΦ + s²V at ±h, ±2h: odd parts k s + c s³, even parts g0 + q s².
  double g[4];
  const double s[4] = {h, -h, 2.0 * h, -2.0 * h};
  for (int i = 0; i < 4; ++i) g[i] = path_residual(model, x0, phi, v, s[i], x, f);
  const double odd1 = 0.5 * (g[0] - g[1]), odd2 = 0.5 * (g[2] - g[3]);
  start.c = (odd2 - 2.0 * odd1) / (6.0 * h * h * h);
  start.k = (8.0 * odd1 - odd2) / (6.0 * h);
  start.q = (0.5 * (g[0] + g[1]) - g0) / (h * h);
  start.amplitude = nearest_root(start.k, start.q, start.c);
  if (start.amplitude != 0.0) {
    const double a = start.amplitude;
    PLISSE_PETSC(VecCopy(x0, x));
    PLISSE_PETSC(VecAXPY(x, a, phi));
    PLISSE_PETSC(VecAXPY(x, a * a, v));
    model.set_free(x);
    start.state = model.state();
  }
  return start;
}

}  // namespace plisse
