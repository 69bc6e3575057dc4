// Where the time of one Newton iteration goes, on a real case (bench/README in
// docs/performance.md).
//
//   plisse-newton-profile CASE.yaml [--time T] [--steps N] [--repeat R] [--set key=value ...]
//
// Brings the case to time T in N load steps with plisse's Newton solver, then moves it to the
// next step time (T + T/N: the state of a first Newton iteration, where every element's bubble
// needs a few local iterations) and times, R times each, the pieces of one iteration:
//   element kernel     assemble_mini over all elements, no scatter (residual only / tangent)
//   residual           MixedModel::assemble_residual (kernel + scatter + terms)
//   tangent            MixedModel::assemble_tangent (kernel + scatter + terms + zeroing)
//   terms              the model terms' assemble alone (residual only / with a no-op sink)
//   sparsity           MixedModel::create_matrix
//   factorisation      MUMPS symbolic (first PCSetUp) and numeric (PCSetUp after new values)
//   solve              one KSPSolve (forward/backward substitution)
// and finally one more load step through SNES, reporting assembly and linear-solve time per
// Newton iteration and PETSc's counts of symbolic and numeric factorisations.
// Export OPENBLAS_NUM_THREADS=1 on a shared machine; OMP_NUM_THREADS sets assembly threads.
#include <petscksp.h>
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "app/model_builder.hpp"
#include "case/case.hpp"
#include "material/registry.hpp"
#include "physics/dirichlet.hpp"
#include "solver/mixed_model.hpp"
#include "solver/newton_solver.hpp"
#include "solver/petsc_call.hpp"
#include "solver/petsc_session.hpp"

namespace plisse {
namespace {

using Clock = std::chrono::steady_clock;

/// CPU time of the whole process (all threads) [s]: on a shared machine far steadier than the
/// wall time of a single-threaded piece.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Best and mean wall time, and best CPU time [s], of `repeat` calls of f.
struct Timing {
  double best = 1e300, mean = 0.0, cpu = 1e300;
};
Timing time_calls(int repeat, const std::function<void()>& f) {
  Timing t;
  for (int k = 0; k < repeat; ++k) {
    const double c0 = cpu_seconds();
    const auto t0 = Clock::now();
    f();
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    t.cpu = std::min(t.cpu, cpu_seconds() - c0);
    t.best = std::min(t.best, s);
    t.mean += s / repeat;
  }
  return t;
}

void print(const char* what, const Timing& t) {
  std::printf("  %-38s wall best %8.4f s  mean %8.4f s   cpu best %8.4f s\n", what, t.best, t.mean,
              t.cpu);
}

/// Counts tangent entries and drops them (the terms' own cost without any scatter).
class NullSink : public TangentSink {
 public:
  void add(std::span<const int> rows, std::span<const int> cols, std::span<const double>) override {
    entries += static_cast<long>(rows.size() * cols.size());
  }
  long entries = 0;
};

int event_count(const char* name) {
  PetscLogEvent event = 0;
  PetscEventPerfInfo info{};
  if (PetscLogEventGetId(name, &event) != 0 || PetscLogEventGetPerfInfo(0, event, &info) != 0)
    return 0;
  return info.count;
}

int run(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: %s CASE.yaml [--time T] [--steps N] [--repeat R] [--set key=value ...]\n",
                 argv[0]);
    return 2;
  }
  std::string case_file = argv[1];
  double target_time = 0.06;
  int steps = 3, repeat = 3;
  std::vector<std::string> overrides;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--time")
      target_time = std::stod(value);
    else if (key == "--steps")
      steps = std::stoi(value);
    else if (key == "--repeat")
      repeat = std::stoi(value);
    else if (key == "--set")
      overrides.push_back(value);
    else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  const Case c = parse_case_file(case_file, overrides);
  const Mesh mesh = load_case_mesh(c);
  check_case_against_mesh(c, mesh);
  app::ModelParts parts = app::build_model_parts(c, mesh);
  const AnyMaterial material =
      parts.materials.materials.front();  // the bare kernel loop below evaluates it
  PetscSession petsc({"-no_signal_handler", c.solver.petsc_options});
  PLISSE_PETSC(PetscLogDefaultBegin());
  const std::unique_ptr<MixedModel> model_owner = app::make_model(mesh, std::move(parts));
  MixedModel& model = *model_owner;
  std::printf("%s: %d nodes, %d tetrahedra, %d unknowns; %d assembly threads\n", case_file.c_str(),
              mesh.n_nodes(), mesh.n_tets(), model.n_free(), model.assembly_threads());

  NewtonSolver newton(model, c.solver.newton);
  const double dt = target_time / steps;
  std::vector<double> previous = model.state();
  for (int s = 1; s <= steps; ++s) {
    previous = model.state();
    model.set_time(s * dt);
    const NewtonResult r = newton.solve();
    std::printf("  step %d t = %.4g: %d Newton iterations, |R| = %.3e %s\n", s, s * dt,
                r.iterations, r.residual_norm, r.converged ? "" : "(NOT converged)");
    model.save_converged();
  }

  std::printf("after the steps: %d assembly threads\n", model.assembly_threads());
  std::printf(
      "pieces of one Newton iteration at t = %.4g + dt: the state extrapolated from the "
      "last two steps (as a predictor), bubbles from the last converged step; %d calls "
      "each:\n",
      target_time, repeat);
  const MixedModel::Snapshot converged = model.snapshot();
  // From the converged state: bubbles converged there, nodal values moved one step ahead.
  const auto from_converged = [&] {
    model.restore(converged);
    for (size_t d = 0; d < previous.size(); ++d)
      model.state()[d] = 2.0 * converged.state[d] - previous[d];
    model.set_time(target_time + dt);
  };
  from_converged();
  Vec f = nullptr;
  PLISSE_PETSC(VecCreateSeq(PETSC_COMM_SELF, model.n_free(), &f));
  Mat K = nullptr;
  print("sparsity (create_matrix)", time_calls(1, [&] { K = model.create_matrix(); }));

  // The element kernel alone, from the converged bubbles, as assemble_* sees it.
  std::vector<mini::TetGeometry> geometry;
  for (const auto& tet : mesh.tets)
    geometry.push_back(mini::compute_tet_geometry(
        {mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]], mesh.nodes[tet[3]]}));
  long bubble_iterations = 0;
  const auto kernel = [&](bool tangent) {
    std::visit(
        [&](const auto& mat) {
          mini::ElemVec x, r;
          mini::ElemMat k;
          bubble_iterations = 0;
          for (int e = 0; e < mesh.n_tets(); ++e) {
            for (int a = 0; a < 4; ++a) {
              for (int i = 0; i < 3; ++i)
                x[3 * a + i] = model.state()[DofMap::dof(mesh.tets[e][a], i)];
              x[12 + a] = model.state()[DofMap::dof(mesh.tets[e][a], 3)];
            }
            mini::BubbleVec b(converged.bubbles.data() + 3 * e);
            const auto st =
                mini::assemble_mini(geometry[e], x, mat, 0.0, b, r, tangent ? &k : nullptr);
            bubble_iterations += st.bubble_iterations;
          }
        },
        material);
  };
  if (c.element == ElementFamily::mini) {
    print("element kernel, residual only", time_calls(repeat, [&] { kernel(false); }));
    print("element kernel, with tangent", time_calls(repeat, [&] { kernel(true); }));
    std::printf("  (%.2f bubble evaluations per element)\n",
                static_cast<double>(bubble_iterations) / mesh.n_tets());
  } else {
    // The bare loop is the MINI kernel's (it reads the bubbles); the other families' kernels are
    // timed inside assemble_residual and assemble_tangent below.
    std::printf("element kernel: timed for MINI cases only (this case's element is %s)\n",
                to_string(c.element).c_str());
  }
  print("assemble_residual", time_calls(repeat, [&] {
          from_converged();
          model.assemble_residual(f);
        }));
  print("assemble_tangent", time_calls(repeat, [&] {
          from_converged();
          model.assemble_tangent(K);
        }));
  print("  of which MatZeroEntries", time_calls(repeat, [&] { PLISSE_PETSC(MatZeroEntries(K)); }));
  print("restore + predictor (included above)", time_calls(repeat, from_converged));
  std::vector<double> scratch(model.state().size());
  NullSink sink;
  print("terms, residual only", time_calls(repeat, [&] {
          for (auto& term : model.terms())
            term->assemble(model.time(), model.state(), scratch, nullptr);
        }));
  print("terms, with tangent (no-op sink)", time_calls(repeat, [&] {
          for (auto& term : model.terms())
            term->assemble(model.time(), model.state(), scratch, &sink);
        }));
  from_converged();
  model.assemble_tangent(K);

  MatInfo info;
  PLISSE_PETSC(MatGetInfo(K, MAT_LOCAL, &info));
  std::printf("  matrix: %.0f nonzeros (%.1f per row)\n", info.nz_used,
              info.nz_used / model.n_free());
  KSP ksp = nullptr;
  PC pc = nullptr;
  PLISSE_PETSC(KSPCreate(PETSC_COMM_SELF, &ksp));
  PLISSE_PETSC(KSPSetOperators(ksp, K, K));
  PLISSE_PETSC(KSPSetType(ksp, KSPPREONLY));
  PLISSE_PETSC(KSPGetPC(ksp, &pc));
  PLISSE_PETSC(PCSetType(pc, model.symmetric() ? PCCHOLESKY : PCLU));
  PLISSE_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PLISSE_PETSC(KSPSetFromOptions(ksp));
  print("factorisation, symbolic + numeric", time_calls(1, [&] { PLISSE_PETSC(KSPSetUp(ksp)); }));
  Mat F = nullptr;
  PLISSE_PETSC(PCFactorGetMatrix(pc, &F));
  PetscInt factor_entries = 0;
  PLISSE_PETSC(MatMumpsGetInfog(F, 29, &factor_entries));
  std::printf("  MUMPS factor entries INFOG(29) = %lld (fill %.1f x the matrix)\n",
              static_cast<long long>(factor_entries), factor_entries / info.nz_used);
  Timing numeric;
  for (int k = 0; k < repeat; ++k) {
    model.assemble_tangent(K);  // same pattern, new matrix state: PETSc refactors numerically
    PLISSE_PETSC(KSPSetOperators(ksp, K, K));
    const Timing t = time_calls(1, [&] { PLISSE_PETSC(KSPSetUp(ksp)); });
    numeric.best = std::min(numeric.best, t.best);
    numeric.cpu = std::min(numeric.cpu, t.cpu);
    numeric.mean += t.mean / repeat;
  }
  print("factorisation, numeric only", numeric);
  Vec du = nullptr;
  PLISSE_PETSC(VecDuplicate(f, &du));
  model.assemble_residual(f);
  print("solve (forward/backward)",
        time_calls(repeat, [&] { PLISSE_PETSC(KSPSolve(ksp, f, du)); }));
  KSPDestroy(&ksp);
  VecDestroy(&du);
  MatDestroy(&K);
  VecDestroy(&f);

  // One more step through SNES, as a run does it.
  from_converged();
  const PhaseTimes before = newton.times();
  const int sym_before = event_count("MatCholFctrSym") + event_count("MatLUFactorSym");
  const int num_before = event_count("MatCholFctrNum") + event_count("MatLUFactorNum");
  const int residuals_before = event_count("SNESFunctionEval");
  const int tangents_before = event_count("SNESJacobianEval");
  const double c0 = cpu_seconds();
  const auto t0 = Clock::now();
  const NewtonResult r = newton.solve();
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const double cpu = cpu_seconds() - c0;
  const PhaseTimes after = newton.times();
  const int its = std::max(r.iterations, 1);
  std::printf(
      "one load step through SNES: %d iterations, %.3f s (%.4f s per iteration), "
      "cpu %.3f s\n",
      r.iterations, wall, wall / its, cpu);
  std::printf("  %d residual and %d tangent assemblies\n",
              event_count("SNESFunctionEval") - residuals_before,
              event_count("SNESJacobianEval") - tangents_before);
  std::printf("  assembly      %.4f s per iteration (%.0f %%)\n",
              (after.assembly - before.assembly) / its,
              100 * (after.assembly - before.assembly) / wall);
  std::printf("  factorisation %.4f s per iteration\n",
              (after.factorisation - before.factorisation) / its);
  std::printf("  triangular    %.4f s per iteration\n",
              (after.triangular_solve - before.triangular_solve) / its);
  std::printf("  symbolic factorisations %d, numeric %d in this step (whole run: %d / %d)\n",
              event_count("MatCholFctrSym") + event_count("MatLUFactorSym") - sym_before,
              event_count("MatCholFctrNum") + event_count("MatLUFactorNum") - num_before,
              event_count("MatCholFctrSym") + event_count("MatLUFactorSym"),
              event_count("MatCholFctrNum") + event_count("MatLUFactorNum"));
  return 0;
}

}  // namespace
}  // namespace plisse

int main(int argc, char** argv) {
  try {
    return plisse::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
