#include "solver/load_stepper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <new>

#include "solver/branch_start.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_call.hpp"
#include "solver/unresisted_motion.hpp"

namespace plisse {
namespace {
/// Logs the PETSc events of its lifetime (e.g. the eigensolver's factorisations) in the stage
/// `name` instead of the main stage, whose factorisations NewtonSolver::times() reports.
class LogStage {
 public:
  explicit LogStage(const char* name) {
    PetscLogStage stage = -1;
    PLISSE_PETSC(PetscLogStageGetId(name, &stage));
    if (stage < 0) PLISSE_PETSC(PetscLogStageRegister(name, &stage));
    PLISSE_PETSC(PetscLogStagePush(stage));
  }
  ~LogStage() { PetscLogStagePop(); }
  LogStage(const LogStage&) = delete;
  LogStage& operator=(const LogStage&) = delete;
};

/// Branch switching re-solves from u + a φ1 with a, 4a, 16a, 64a while Newton falls back onto
/// the unperturbed (unstable) equilibrium (stability.md, S10).
constexpr int kAmplitudeTries = 4;
constexpr double kAmplitudeGrowth = 4.0;
/// The most eigenpairs an instability's search asks for when the nearest ones miss the negative
/// eigenvalues the inertia counts (stability.md, S7).
constexpr int kMostModes = 64;
}  // namespace

std::string LoadStepper::describe_failure(const NewtonResult& newton) const {
  if (newton.out_of_memory)
    return newton.reason +
           "; a smaller load step needs as much memory, so the run stops here: run on a machine "
           "or node with more memory, over more ranks (-n), on a coarser mesh, or with "
           "solver.newton.linear: {type: iterative}";
  const AssemblyStatus& status = newton.status;
  // Only MINI has bubbles to solve for; a Taylor-Hood element can only invert. A shell triangle
  // has no det F that falls to zero (J = 1 when exactly incompressible): its state is refused
  // when the triangle collapses or the metric of a point of its section is not positive, the wall
  // folded tighter than half its thickness (element/shell_plane_stress.cpp).
  const ElementFamily family = model_.element_family();
  const bool shell = family == ElementFamily::shell;
  std::string why = status.ok ? "Newton did not converge (" + newton.reason + ")"
                    : family == ElementFamily::mini
                        ? "an element inverted or its bubble did not converge"
                    : shell ? "a shell triangle collapsed, or its wall folded tighter than half "
                              "its thickness"
                            : "an element inverted";
  if (status.worst_element >= 0) {
    // A tetrahedron, or the triangle of a shell (a mesh without tetrahedra).
    const Mesh& mesh = model_.mesh();
    Vec3d centroid = Vec3d::Zero();
    if (mesh.tets.empty()) {
      for (int v : mesh.triangles[status.worst_element]) centroid += mesh.nodes[v] / 3.0;
    } else {
      for (int v : mesh.tets[status.worst_element]) centroid += 0.25 * mesh.nodes[v];
    }
    char where[160];
    std::snprintf(where, sizeof where, "; worst element %d (reference centroid %.4g, %.4g, %.4g)",
                  status.worst_element, centroid[0], centroid[1], centroid[2]);
    why += where;
    if (!shell) {  // a shell's J says nothing of why it failed
      std::snprintf(where, sizeof where, ", min J %.3g", status.min_J);
      why += where;
    }
  }
  return why;
}

LoadStepper::LoadStepper(MixedModel& model, const SteppingSettings& settings)
    : model_(model), settings_(settings), newton_(model, settings.newton) {
  if (settings.control == StepControl::arc_length)
    arc_ = std::make_unique<ArcLengthSolver>(model, settings.newton, settings.end_time);
}

LoadStepper::~LoadStepper() = default;

void LoadStepper::set_stability(const StabilityCheckSettings& options) {
  PLISSE_CHECK(
      !options.branch_switch || options.check,
      "branch switching needs the stability check (it switches where the check finds a new "
      "instability)");
  PLISSE_CHECK(options.modes >= 1, "stability: modes = " << options.modes << ", must be >= 1");
  PLISSE_CHECK(!options.branch_switch || options.perturbation_mm > 0.0,
               "branch switching needs a positive perturbation amplitude, got "
                   << options.perturbation_mm << " mm");
  stability_ = options;
}

PhaseTimes LoadStepper::times() const {
  PhaseTimes t = newton_.times();
  if (arc_) {
    t.assembly += arc_->assembly_seconds();
    t.linear_solve += arc_->solve_seconds();
  }
  return t;
}

double LoadStepper::stability_seconds() const { return inertia_ ? inertia_->seconds() : 0.0; }
double LoadStepper::stability_assembly_seconds() const {
  return inertia_ ? inertia_->assembly_seconds() : 0.0;
}
int LoadStepper::stability_checks() const { return inertia_ ? inertia_->calls() : 0; }

std::string LoadStepper::solve_step(NewtonResult& newton, SteppingResult& result) {
  int augmentations = 0;
  attempt_reused_ = 0;
  attempt_newton_ = 0;
  // Inexact multiplier updates: when the last step needed multiplier updates, this one will
  // too, and solving to rtol only to move the multipliers again is wasted; its passes go to
  // sqrt(rtol), and the pass that needs no update more is refined to rtol (docs/theory/contact.md,
  // "Inexact passes").
  const double loose_rtol = last_step_updated_ ? std::sqrt(settings_.newton.rtol) : 0.0;
  const auto count = [&](const NewtonResult& n) {
    result.newton_iterations += n.iterations;
    attempt_newton_ += n.iterations;
    result.reused_solves += n.reused_solves;
    result.krylov_steps += n.krylov_steps;
    attempt_reused_ += n.reused_solves;
  };
  try {
    // Newton, then (augmented Lagrangian terms) multiplier updates and re-solves until every
    // constraint meets its tolerance.
    while (true) {
      newton = newton_.solve(loose_rtol);
      count(newton);
      if (!newton.converged) return describe_failure(newton);
      bool again = model_.update_multipliers();
      if (!again && loose_rtol > 0.0) {
        newton = newton_.refine();
        count(newton);
        if (!newton.converged) return describe_failure(newton);
        again = model_.update_multipliers();
      }
      if (!again) {
        last_step_updated_ = augmentations > 0;
        return {};
      }
      if (interrupt_ && interrupt_()) return "interrupted";  // run() asks again and stops
      if (++augmentations > settings_.max_augmentations)
        return "constraints not met after " + std::to_string(settings_.max_augmentations) +
               " multiplier updates";
    }
  } catch (const Error& e) {
    return e.what();
  } catch (const std::bad_alloc&) {
    // One rank (a distributed run ends at the failed allocation: run_case's new-handler).
    newton.out_of_memory = true;
    newton.reason = "out of memory: an allocation failed while solving the step";
    return describe_failure(newton);
  }
}

bool LoadStepper::compute_inertia(Inertia& out, int step, const Log& log) {
  try {
    out = inertia_->compute();
    return true;
  } catch (const Error& e) {
    log("  step " + std::to_string(step) + ": the stability check failed (" + e.what() +
        "); the step is reported unchecked");
    return false;
  }
}

std::string LoadStepper::report_instability(StepInfo& info, const Inertia& inertia, int expected,
                                            int baseline, const Log& log) {
  info.new_instability = true;
  info.unstable_negative_pivots = inertia.negative;
  std::string lowest = "not computed";
  char line[320];
  const auto t0 = std::chrono::steady_clock::now();
  try {
    EigenSettings eigen;
    eigen.count = stability_.modes;
    const LogStage stage("Stability eigenmodes");
    info.modes = lowest_eigenmodes(model_, eigen);
    // The pairs nearest 0 can all be positive while the inertia counts negative eigenvalues
    // farther out (a thin wall has many soft modes): more pairs until the unstable ones are among
    // them, then the lowest stability_.modes kept (stability.md, S7).
    const int unstable = inertia.negative - expected;
    const int most = std::min(model_.n_free(), kMostModes);
    const auto negative = [&] {
      return static_cast<int>(std::count_if(info.modes.begin(), info.modes.end(),
                                            [](const Eigenmode& m) { return m.eigenvalue < 0.0; }));
    };
    while (negative() < unstable && eigen.count < most) {
      eigen.count = std::min(2 * eigen.count, most);
      info.modes = lowest_eigenmodes(model_, eigen);
    }
    if (info.modes.size() > static_cast<std::size_t>(stability_.modes))
      info.modes.resize(static_cast<std::size_t>(stability_.modes));
    if (!info.modes.empty()) {
      std::snprintf(line, sizeof line, "%.6g", info.modes.front().eigenvalue);
      lowest = line;
    }
  } catch (const Error& e) {
    log("  step " + std::to_string(info.step) +
        ": the eigenmodes could not be computed: " + e.what());
  }
  eigenmode_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::snprintf(line, sizeof line,
                "step %d: t = %.6g: new instability, %d negative pivots (stable: %d, previous "
                "step: %d), %d zero; lowest eigenvalue %s",
                info.step, info.time, inertia.negative, expected, baseline, inertia.zero,
                lowest.c_str());
  log("  " + std::string(line));
  return lowest;
}

bool LoadStepper::switch_branch(StepInfo& info, SteppingResult& result, const Log& log,
                                const std::string& lowest, int expected, Inertia& inertia,
                                bool& switched) {
  // (stability.md, S10): Newton from a state near the buckled one, the same time solved again;
  // the model's converged state is the unperturbed one. The starts: Koiter's estimate (S10a) when
  // the tangent's factor is at hand, then u + a φ1 on the displacement dofs (φ1 is zero on
  // constrained ones) with growing amplitudes.
  const std::vector<double>& phi = info.modes.front().state;
  const std::vector<double> unperturbed = model_.converged_state();
  const int n_nodes = model_.mesh().n_nodes();
  char line[320];
  newton_.allow_reuse(false);  // an unstable state (newton_solver.hpp, allow_reuse)
  struct Start {
    double amplitude;
    std::vector<double> state;  ///< Koiter's estimate; empty: u + amplitude φ1
  };
  std::vector<Start> starts;
  if (const Mat factor = stability_.koiter_start ? inertia_->factor() : nullptr) {
    try {
      BranchStart estimate =
          asymptotic_branch_start(model_, factor, phi, stability_.perturbation_mm);
      char what[64] = "no buckled state near";
      if (estimate.amplitude != 0.0)
        std::snprintf(what, sizeof what, "amplitude %.4g mm", estimate.amplitude);
      std::snprintf(line, sizeof line,
                    "step %d: Koiter's estimate along mode 1: %s (k = %.4g N/mm, q = %.4g N/mm^2, "
                    "c = %.4g N/mm^3)",
                    info.step, what, estimate.k, estimate.q, estimate.c);
      log("  " + std::string(line));
      if (estimate.amplitude != 0.0)
        starts.push_back({std::abs(estimate.amplitude), std::move(estimate.state)});
    } catch (const Error& e) {
      log("  step " + std::to_string(info.step) + ": Koiter's estimate failed (" + e.what() +
          "); perturbing along the mode instead");
    }
  }
  for (int i = 0; i < kAmplitudeTries; ++i)
    starts.push_back({stability_.perturbation_mm * std::pow(kAmplitudeGrowth, i), {}});

  const int n_starts = static_cast<int>(starts.size());
  for (int attempt = 0; attempt < n_starts; ++attempt) {
    const Start& start = starts[static_cast<std::size_t>(attempt)];
    const double a = start.amplitude;
    const bool estimated = !start.state.empty();
    const char* next = attempt + 1 >= n_starts ? "; keeping the unperturbed state"
                       : estimated             ? "; perturbing along the mode instead"
                                               : "; trying a larger amplitude";
    auto& x = model_.state();
    if (estimated) {
      x = start.state;
    } else {
      for (int v = 0; v < n_nodes; ++v)
        for (int k = 0; k < 3; ++k) x[DofMap::dof(v, k)] += a * phi[DofMap::dof(v, k)];
    }
    NewtonResult newton;
    const std::string failure = solve_step(newton, result);
    if (!failure.empty()) {
      // Near the inflection of the residual along the mode (S10) Newton's first step is huge
      // and it can wander off; from farther out it converges.
      model_.restore_converged();
      const bool again = attempt + 1 < n_starts && !newton.out_of_memory && !newton.interrupted &&
                         !(interrupt_ && interrupt_());
      std::snprintf(line, sizeof line, "step %d: branch switching %s %.4g mm failed (%s)%s",
                    info.step, estimated ? "from Koiter's estimate, amplitude" : "with amplitude",
                    a, failure.c_str(), again ? next : "; keeping the unperturbed state");
      log("  " + std::string(line));
      if (!again) return true;
      continue;
    }
    // Fallen back: within half the first amplitude of the unperturbed state. Not half of `a`:
    // from a larger amplitude Newton may land on a buckled state nearer than a/2 (S10).
    const double moved = max_nodal_distance(model_.state(), unperturbed, n_nodes);
    if (moved < 0.5 * stability_.perturbation_mm) {
      model_.restore_converged();
      std::snprintf(line, sizeof line,
                    "step %d: the re-solve from %s %.4g mm fell back onto the "
                    "unperturbed state (max |du| %.3g mm)%s",
                    info.step, estimated ? "Koiter's estimate, amplitude" : "amplitude", a, moved,
                    next);
      log("  " + std::string(line));
      continue;
    }
    model_.save_converged();
    const bool checked = compute_inertia(inertia, info.step, log);
    if (checked) newton_.offer_factor(inertia_->factor());
    switched = true;
    info.branch_switched = true;
    info.perturbation_mm = a;
    info.newton_iterations += attempt_newton_;
    info.reused_solves += attempt_reused_;
    info.residual_norm = newton.residual_norm;
    info.reference_norm = newton.reference_norm;
    info.residual_history = newton.residual_history;
    std::snprintf(line, sizeof line,
                  "step %d: switched branch along mode 1 (eigenvalue %s): %samplitude %.4g mm, "
                  "%d extra negative pivot(s) before, max |du| %.4g mm, %d Newton "
                  "iterations; now %d negative pivots",
                  info.step, lowest.c_str(), estimated ? "Koiter's estimate, " : "", a,
                  info.unstable_negative_pivots - expected, moved, newton.iterations,
                  checked ? inertia.negative : -1);
    log("  " + std::string(line));
    return checked;
  }
  return true;
}

bool LoadStepper::ends_unstable(const StepInfo& info, SteppingResult& result) const {
  if (!stability_.stop_when_unstable || info.negative_pivots < 0 || info.stable) return false;
  result.completed = true;
  result.stopped_unstable = true;
  return true;
}

void LoadStepper::check_stability(StepInfo& info, SteppingResult& result, const Log& log,
                                  bool& switched) {
  switched = false;
  if (!stability_.check) return;
  if (!inertia_) inertia_ = std::make_unique<InertiaCheck>(model_);
  if (inertia_->uses_symmetric_part() && !told_symmetric_part_) {
    log("  stability check: the tangent is unsymmetric (follower pressure on an open surface); "
        "the inertia is that of its symmetric part 0.5 (K + K^T)");
    told_symmetric_part_ = true;
  }
  const int expected = expected_negative_pivots(model_);
  info.expected_negative_pivots = expected;
  // The check is a diagnostic of an accepted step: when it fails, the step is reported unchecked
  // (negative_pivots = -1) and the run goes on.
  Inertia inertia;
  if (!compute_inertia(inertia, info.step, log)) return;
  // The tangent of the converged state, just factorised: the next solve starts from it.
  newton_.offer_factor(inertia_->factor());
  // A rise above the previous step is a new instability; before the first check the baseline is
  // the stable count (the reference state is stable).
  const int baseline = current_.negative_pivots >= 0 ? current_.negative_pivots : expected;
  if (inertia.negative > baseline) {
    const std::string lowest = report_instability(info, inertia, expected, baseline, log);
    if (stability_.branch_switch && !info.modes.empty() &&
        !switch_branch(info, result, log, lowest, expected, inertia, switched)) {
      newton_.allow_reuse(false);  // stability unknown
      current_.negative_pivots = -1;
      return;
    }
  }
  info.negative_pivots = inertia.negative;
  info.zero_pivots = inertia.zero;
  info.stable = inertia.negative == expected && inertia.zero == 0;
  newton_.allow_reuse(info.stable);
  current_.negative_pivots = inertia.negative;
}

void LoadStepper::set_interrupt(std::function<bool()> stop) {
  interrupt_ = stop;
  if (arc_) arc_->set_interrupt(stop);
  newton_.set_interrupt(std::move(stop));
}

void LoadStepper::start() {
  StepperState& st = current_;
  if (resume_) {
    // The model already holds the checkpoint's converged state.
    st = *resume_;
    resume_.reset();
    model_.resume_at(st.time);
    // From the second converged step on, an arc-length run's next step size is an arc length.
    arc_length_set_ = arc_ && st.steps >= 2;
    return;
  }
  st = StepperState{};
  arc_length_set_ = false;
  st.dt = std::min(settings_.end_time / settings_.steps, settings_.max_step * settings_.end_time);
  model_.set_time(0.0);
  model_.save_converged();
  st.previous_state = model_.converged_state();
}

void LoadStepper::predict(double step) {
  // Extrapolate the last increment (secant); the caller then imposes the new boundary values.
  if (current_.previous_dt <= 0.0) return;
  const double s = step / current_.previous_dt;
  const auto& now = model_.converged_state();
  const std::vector<double>& previous_state = current_.previous_state;
  auto& x = model_.state();
  for (size_t i = 0; i < x.size(); ++i) x[i] = now[i] + s * (now[i] - previous_state[i]);
}

void LoadStepper::report_workspace_growth(int step, const Log& log) {
  const WorkspaceGrowth g = factor_workspace_growth();
  if (g.count == reported_growths_) return;
  reported_growths_ = g.count;
  char text[200];
  std::snprintf(text, sizeof text,
                "  step %d: the factorisation needed more working memory than MUMPS estimated "
                "(INFOG(1) = %d): its margin ICNTL(14) is now %d %%",
                step, g.status, g.percent);
  log(text);
}

bool LoadStepper::cut_back(const NewtonResult& newton, const std::string& failure, double t_new,
                           double step, SteppingResult& result, const Log& log) {
  if (newton.out_of_memory) {
    result.failure = "step " + std::to_string(result.steps + 1) + ": " + failure;
    return false;
  }
  ++result.cutbacks;
  const double new_dt = step * settings_.cutback;
  const double min_dt = settings_.min_step * settings_.end_time;
  char line[256];
  std::snprintf(line, sizeof line,
                "step %d: t = %.6g failed after %d iterations: ", result.steps + 1, t_new,
                newton.iterations);
  char steps[160];
  std::snprintf(steps, sizeof steps, "; the next step %.6g would be below the minimum %.6g", new_dt,
                min_dt);
  if (new_dt < min_dt) {
    result.failure = std::string(line) + failure + steps;
    result.smallest_step = true;
    return false;
  }
  std::snprintf(steps, sizeof steps, "; cutting the step to %.6g", new_dt);
  log("  " + std::string(line) + failure + steps);
  current_.dt = new_dt;
  return true;
}

StepInfo LoadStepper::accept_step(const NewtonResult& newton, double t_new, double step,
                                  SteppingResult& result) {
  StepperState& st = current_;
  st.previous_state = model_.converged_state();
  model_.save_converged();
  st.previous_dt = step;
  st.time = t_new;
  ++result.steps;
  st.steps = result.steps;
  if (newton.iterations <= settings_.easy_iterations)
    st.dt = std::min(step * settings_.growth, settings_.max_step * settings_.end_time);
  else
    st.dt = step;
  StepInfo info;
  info.step = result.steps;
  info.time = t_new;
  info.dt = step;
  info.load_factor = t_new / settings_.end_time;
  info.newton_iterations = attempt_newton_;
  info.reused_solves = attempt_reused_;
  info.residual_norm = newton.residual_norm;
  info.reference_norm = newton.reference_norm;
  info.residual_history = newton.residual_history;
  return info;
}

LoadStepper::Attempt LoadStepper::arc_length_attempt(SteppingResult& result, const Log& log,
                                                     StepInfo& info) {
  StepperState& st = current_;
  const double end = settings_.end_time;
  if (!arc_length_set_) {
    // The first arc: the length of the first (load-controlled) step's increment, grown or kept
    // as that step's time step was.
    const double first = arc_->distance_from(st.previous_state);
    st.dt = first * (st.previous_dt > 0.0 ? st.dt / st.previous_dt : 1.0);
    arc_length_set_ = true;
    char text[160];
    std::snprintf(text, sizeof text,
                  "  arc-length control from step 2: first arc %.4g mm (step 1 moved %.4g mm)",
                  st.dt, first);
    log(text);
  }
  double arc = st.dt;
  attempt_newton_ = 0;
  attempt_reused_ = 0;
  NewtonResult newton;
  ArcLengthPredictor predictor;
  double t_new = st.time;
  std::string failure;
  try {
    newton = arc_->solve(st.time, arc, st.previous_state, t_new, predictor);
    arc = arc_->used_arc();  // shorter when the predictor passed end_time (A8)
    int augmentations = 0;
    // Contact multipliers: updated at the converged point, then the same arc solved again.
    while (newton.converged && model_.update_multipliers()) {
      attempt_newton_ += newton.iterations;
      if (++augmentations > settings_.max_augmentations) {
        failure = "constraints not met after " + std::to_string(settings_.max_augmentations) +
                  " multiplier updates";
        break;
      }
      newton = arc_->correct(arc, t_new);
    }
  } catch (const Error& e) {
    failure = e.what();
  } catch (const std::bad_alloc&) {
    newton.out_of_memory = true;
    newton.reason = "out of memory: an allocation failed while solving the step";
  }
  attempt_newton_ += newton.iterations;
  result.newton_iterations += newton.iterations;
  if (failure.empty() && !newton.converged && !arc_->left_ramps())
    failure = describe_failure(newton);
  report_workspace_growth(result.steps + 1, log);
  if (failure.empty() && !newton.converged && !newton.interrupted && !newton.out_of_memory &&
      arc_->left_ramps()) {
    // The arc passes end_time (or falls below 0), beyond which the ramps hold: the step is taken
    // again under load control to that bound, from the point where the line from the converged
    // state to the iterate crosses it (A8).
    const double bound = t_new > end ? end : 0.0;
    const std::vector<double> on_arc = model_.state();
    const double f = (bound - st.time) / (t_new - st.time);
    model_.restore_converged();
    const std::vector<double>& from = model_.converged_state();
    std::vector<double>& x = model_.state();
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = from[i] + f * (on_arc[i] - from[i]);
    char passed[160];
    std::snprintf(passed, sizeof passed,
                  "the arc passed t = %.6g (to %.6g) and the step to it under load control "
                  "failed: ",
                  bound, t_new);
    t_new = bound;
    model_.set_time(bound);
    const int arc_iterations = attempt_newton_;  // solve_step counts its own from 0
    failure = solve_step(newton, result);
    attempt_newton_ += arc_iterations;
    if (!failure.empty()) failure = passed + failure;
  }
  if (!failure.empty()) {
    model_.restore_converged();
    model_.set_time(st.time);
    if (newton.interrupted || (interrupt_ && interrupt_())) {
      result.interrupted = true;
      return Attempt::stop;
    }
    if (newton.out_of_memory) {
      result.failure = "step " + std::to_string(result.steps + 1) + ": " + failure;
      return Attempt::stop;
    }
    if (!(predictor.rate > 0.0)) {
      result.failure = "step " + std::to_string(result.steps + 1) + ": " + failure;
      return Attempt::stop;
    }
    ++result.cutbacks;
    // The shortest arc: that of a load increment of solver.min_step at the last converged
    // state's stiffness (A7).
    const double shortest = settings_.min_step * end * predictor.rate;
    const double next = arc * settings_.cutback;
    char line[512];
    std::snprintf(line, sizeof line,
                  "step %d: arc %.4g mm from t = %.6g failed after %d iterations: ",
                  result.steps + 1, arc, st.time, newton.iterations);
    if (next < shortest) {
      char tail[200];
      std::snprintf(tail, sizeof tail,
                    "; the next arc %.4g mm would be below the shortest %.4g mm (solver.min_step "
                    "of the load at the last step's stiffness)",
                    next, shortest);
      result.failure = std::string(line) + failure + tail;
      result.smallest_step = true;
      return Attempt::stop;
    }
    char tail[80];
    std::snprintf(tail, sizeof tail, "; cutting the arc to %.4g mm", next);
    log("  " + std::string(line) + failure + tail);
    st.dt = next;
    return Attempt::retry;
  }
  const double load_step = t_new - st.time;
  info = accept_step(newton, t_new, std::abs(load_step), result);
  info.dt = load_step;
  info.newton_iterations = attempt_newton_;
  // The next arc: grown after an easy step, and short enough that its load increment stays
  // under solver.max_step (at this step's ratio of arc to load).
  double next = newton.iterations <= settings_.easy_iterations ? arc * settings_.growth : arc;
  const double largest = settings_.max_step * end;
  if (std::abs(load_step) > 0.0) next = std::min(next, arc * largest / std::abs(load_step));
  st.dt = next;
  return Attempt::accepted;
}

SteppingResult LoadStepper::run(const std::function<void(const StepInfo&)>& on_step,
                                const Log& log) {
  SteppingResult result;
  const double end = settings_.end_time;
  start();
  StepperState& st = current_;
  result.steps = st.steps;
  int cutbacks_this_step = 0;
  const auto requested = [&] { return interrupt_ && interrupt_(); };
  // A factorisation whose workspace proved too small was done again with a larger one: said once.
  reported_growths_ = factor_workspace_growth().count;
  const auto stop = [&] {
    result.interrupted = true;
    result.failure = "interrupted during step " + std::to_string(result.steps + 1);
    return result;
  };
  while (st.time < end * (1.0 - 1e-12)) {
    if (requested()) return stop();
    if (result.steps >= settings_.max_steps) {
      result.failure = "reached solver.max_steps = " + std::to_string(settings_.max_steps) +
                       " at time " + std::to_string(st.time);
      return result;
    }
    if (arc_ && st.steps >= 1) {
      StepInfo info;
      const Attempt attempt = arc_length_attempt(result, log, info);
      if (attempt == Attempt::stop) return result.interrupted ? stop() : result;
      if (attempt == Attempt::retry) {
        ++cutbacks_this_step;
        continue;
      }
      info.cutbacks = cutbacks_this_step;
      cutbacks_this_step = 0;
      bool switched = false;
      check_stability(info, result, log, switched);
      report_workspace_growth(info.step, log);
      on_step(info);
      if (ends_unstable(info, result)) return result;
      if (info.dt < 0.0 && settings_.stop_load_factor > 0.0 &&
          st.time / end < settings_.stop_load_factor) {
        result.completed = true;
        result.stopped_after_limit = true;
        return result;
      }
      if (st.time <= 0.0) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "step %d: the load factor fell back to %.6g: past its limit load the body "
                      "carries none of the load (the path of solver.control: arc-length ends at "
                      "load factor 0)",
                      info.step, st.time / end);
        result.failure = text;
        return result;
      }
      continue;
    }
    // Land on end_time without a sliver: take the rest when it fits, halve it when it is less
    // than two steps.
    const double remaining = end - st.time;
    if (remaining > st.dt * (1.0 + 1e-9) && remaining < 2.0 * st.dt) st.dt = 0.5 * remaining;
    const double t_new = (remaining <= st.dt * (1.0 + 1e-9)) ? end : st.time + st.dt;
    const double step = t_new - st.time;
    // Predictor, then the new boundary values.
    predict(step);
    model_.set_time(t_new);
    NewtonResult newton;
    const std::string failure = solve_step(newton, result);
    report_workspace_growth(result.steps + 1, log);
    if (!failure.empty()) {
      model_.restore_converged();
      if (newton.interrupted || requested()) return stop();
      // The first try of a run's first step (a resumed run starts past it: its checkpoint holds
      // a step): a tangent that some rigid motion leaves unresisted is singular at every step
      // size, so cutting back would only take time.
      if (result.steps == 0 && cutbacks_this_step == 0)
        if (const std::string free = unresisted_rigid_motion(model_); !free.empty()) {
          char head[64];
          std::snprintf(head, sizeof head, "step 1: t = %.6g failed: ", t_new);
          result.failure = head + free +
                           ". Hold the motion by a boundary condition, a cap or a die that "
                           "touches the body, or add solver.viscosity";
          return result;
        }
      if (!cut_back(newton, failure, t_new, step, result, log)) return result;
      ++cutbacks_this_step;
      continue;
    }
    StepInfo info = accept_step(newton, t_new, step, result);
    info.cutbacks = cutbacks_this_step;
    cutbacks_this_step = 0;
    bool switched = false;
    check_stability(info, result, log, switched);
    report_workspace_growth(info.step, log);
    // After a switch the last increment holds the jump onto the new branch: no extrapolation.
    if (switched) st.previous_dt = 0.0;
    on_step(info);
    if (ends_unstable(info, result)) return result;
  }
  result.completed = true;
  return result;
}

}  // namespace plisse
