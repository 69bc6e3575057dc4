// The tables of the case file's `solver:` section (with `newton`, `newton.linear` and
// `stability`): key, type, unit, range, default and meaning of each key, and the rules between
// keys (case_schema.hpp explains the rows). case.cpp puts the section in the case's table.
#include "case/solver_section.hpp"

#include <sstream>
#include <string>

#include "case/petsc_option_text.hpp"
#include "schema/field.hpp"

namespace plisse::case_detail {
namespace {

using schema::Choices;
using schema::Field;
using schema::FieldMap;
using schema::format_number;
using schema::KeyDoc;
using schema::ReadContext;
using schema::resolve_path;

const Range kFraction{0.0, 1.0, true, false};  // (0, 1]
const Range kOpenUnit{0.0, 1.0, true, true};   // (0, 1)

const Choices<Scheme> kSchemes{{"total-lagrangian", Scheme::total_lagrangian},
                               {"incremental", Scheme::incremental}};
const Choices<LineSearch> kLineSearches{{"bt", LineSearch::bt},
                                        {"basic", LineSearch::basic},
                                        {"l2", LineSearch::l2},
                                        {"cp", LineSearch::cp}};
const Choices<StepControl> kStepControls{{"load", StepControl::load},
                                         {"arc-length", StepControl::arc_length}};
const Choices<LinearSolverType> kLinearSolverTypes{{"direct", LinearSolverType::direct},
                                                   {"iterative", LinearSolverType::iterative}};
const Choices<std::string> kImperfectionKinds{{"random", "random"}, {"mode", "mode"}};
const Choices<std::string> kBranchStarts{{"koiter", "koiter"}, {"perturbation", "perturbation"}};

/// `solver.newton.linear`: the iterative solver's keys do not apply to the direct one.
Schema<LinearSolverSettings> linear_solver_schema() {
  Schema<LinearSolverSettings> s;
  s.place(&LinearSolverSettings::place, true);
  s.variant<LinearSolverType>("type", &LinearSolverSettings::type, kLinearSolverTypes,
                              "solver of each Newton iteration's linear system: MUMPS "
                              "factorisation, or GMRES with a field-split preconditioner (below)");
  s.real("rtol", &LinearSolverSettings::rtol, kOpenUnit, "–",
         "GMRES stops when the true residual ‖K dx + R‖ ≤ rtol ‖R‖")
      .applies({"iterative"});
  s.integer("max_iterations", &LinearSolverSettings::max_iterations, Range::at_least(1),
            "GMRES iterations per Newton iteration; more counts as a failed linear solve (the "
            "step is cut back)")
      .applies({"iterative"});
  s.integer("restart", &LinearSolverSettings::restart, Range::at_least(1),
            "Krylov vectors kept before GMRES restarts (memory: about 2 × restart vectors of the "
            "unknowns)")
      .applies({"iterative"});
  return s;
}

/// `solver.newton`.
Schema<NewtonSettings> newton_schema() {
  Schema<NewtonSettings> s;
  s.real("rtol", &NewtonSettings::rtol, kOpenUnit, "–", "relative residual tolerance");
  s.real("atol", &NewtonSettings::atol, Range::non_negative(), "N",
         "absolute residual tolerance (the pressure equations count as forces: their volume "
         "change times mu/h, docs/theory/mixed_up.md, X1)");
  s.integer("max_iterations", &NewtonSettings::max_iterations, Range::at_least(1),
            "Newton iterations per step before the step counts as failed");
  s.integer("stall_iterations", &NewtonSettings::stall_iterations, Range::at_least(0),
            "a step counts as failed after this many Newton iterations in a row that each cut "
            "the residual by less than 1 − stall_ratio, before max_iterations: a stalled "
            "solve is cut back at once instead of spending a factorisation per iteration left "
            "(docs/case-file.md, \"Stalled steps\"); 0: only max_iterations ends a step");
  s.real("stall_ratio", &NewtonSettings::stall_ratio, kOpenUnit, "–",
         "an iteration stalls when it leaves ‖R‖ above stall_ratio times the one before");
  s.choice<LineSearch>("line_search", &NewtonSettings::line_search, kLineSearches,
                       "PETSc SNES line search: bt backtracks on the residual norm, basic "
                       "takes full steps, l2 and cp minimise along the step (cp suits "
                       "slender bodies in bending, whose full step first raises the residual)");
  s.boolean("reuse_factor", &NewtonSettings::reuse_factor,
            "direct solver: before factorising, iterate with the last factorisation (the last "
            "Newton tangent or the stability check's) while each iteration cuts the residual "
            "tenfold, and within Newton keep a factorisation for the next iteration after one "
            "that cut it tenfold; the convergence test is unchanged (docs/performance.md)");
  s.integer("reuse_krylov_iterations", &NewtonSettings::reuse_krylov_iterations, Range::at_least(0),
            "with reuse_factor: when an iteration with the kept factorisation cuts the residual "
            "less than tenfold, Newton steps go on without factorising, their linear system "
            "solved by GMRES preconditioned with that factorisation in at most this many "
            "iterations (GMRES keeps as many vectors of the unknowns); 0 factorises instead "
            "(docs/performance.md)");
  s.nested<LinearSolverSettings>("linear", &NewtonSettings::linear, linear_solver_schema())
      .null_is_absent();
  return s;
}

/// `solver.stability`.
Schema<StabilitySettings> stability_schema() {
  Schema<StabilitySettings> s;
  s.place(&StabilitySettings::place, true);
  s.boolean("check", &StabilitySettings::check, "inertia of the tangent at every converged step");
  s.boolean("branch_switch", &StabilitySettings::branch_switch,
            "perturb along the critical mode when stability is lost");
  s.integer("modes", &StabilitySettings::modes, Range::at_least(1),
            "eigenmodes computed at an instability (the lowest; more are searched when the "
            "nearest zero miss the negative ones)");
  s.real("imperfection", &StabilitySettings::imperfection, Range::non_negative(), "–",
         "imperfection amplitude / wall thickness");
  s.choice<std::string>("imperfection_kind", &StabilitySettings::imperfection_kind,
                        kImperfectionKinds,
                        "random: a random perturbation of the nodes; mode: an eigenmode of an "
                        "earlier run (`imperfection_from`)");
  s.integer("seed", &StabilitySettings::seed, Range::at_least(0),
            "seed of the random imperfection");
  s.add({"imperfection_from",
         "path",
         "–",
         "",
         "none",
         {},
         "run directory (or one of its `.vtu` files) whose eigenmode shapes the imperfection; "
         "relative to the case file"},
        [](const Field& f, StabilitySettings& st, ReadContext& context) {
          const std::string text = f.text();
          if (text.empty()) f.fail("must name a run directory or a .vtu file");
          st.imperfection_from = resolve_path(text, context.directory);
        });
  s.integer("imperfection_mode", &StabilitySettings::imperfection_mode, Range::at_least(1),
            "which mode (`mode_N` field) of that run");
  s.real("branch_amplitude", &StabilitySettings::branch_amplitude, Range::positive(), "–",
         "size of the perturbation along the critical mode at a branch switch / wall thickness; "
         "also the difference step of Koiter's estimate and the least distance from the "
         "unstable state that counts as a switch (half of it)");
  s.choice<std::string>("branch_start", &StabilitySettings::branch_start, kBranchStarts,
                        "where a branch switch starts Newton: koiter: Koiter's estimate of the "
                        "buckled state from the critical mode and the second-order field "
                        "(symmetric tangents), then the perturbations if it does not switch; "
                        "perturbation: the state perturbed along the mode by 1, 4, 16 and 64 "
                        "`branch_amplitude` (docs/theory/stability.md, S10)");
  s.boolean("stop_when_unstable", &StabilitySettings::stop_when_unstable,
            "end the run, completed, at the first step the check finds unstable and a branch "
            "switch (when on) does not leave: that step and the one before bracket the buckling "
            "or collapse load (summary.json `ended`: `instability`)");
  s.rule("`imperfection_from` needs `imperfection_kind: mode`",
         [](const FieldMap& m, const StabilitySettings& st, const ReadContext&) {
           if (const auto from = m.find("imperfection_from");
               from && st.imperfection_kind != "mode")
             from->fail_at_key("imperfection_from needs 'imperfection_kind: mode'");
         });
  s.rule(
      "`imperfection_kind: mode` with `imperfection` > 0 needs `imperfection_from`",
      [](const FieldMap&, const StabilitySettings& st, const ReadContext&) {
        if (st.imperfection_kind == "mode" && st.imperfection > 0.0 && st.imperfection_from.empty())
          throw InputError(st.place,
                           "'imperfection_kind: mode' needs 'imperfection_from: DIR', the run "
                           "whose eigenmode shapes the imperfection");
      });
  s.rule("`stop_when_unstable` needs `check: true`",
         [](const FieldMap& m, const StabilitySettings& st, const ReadContext&) {
           if (st.stop_when_unstable && !st.check)
             m.find("stop_when_unstable")
                 ->fail(
                     "stop_when_unstable needs 'check: true' (the instability it stops at is "
                     "found by the stability check)");
         });
  s.rule("`branch_switch` needs `check: true`",
         [](const FieldMap& m, const StabilitySettings& st, const ReadContext&) {
           if (st.branch_switch && !st.check)
             m.find("branch_switch")
                 ->fail(
                     "branch_switch needs 'check: true' (the instability it switches at is found "
                     "by the stability check)");
         });
  return s;
}

}  // namespace

/// `solver:`. The stepping keys may be members of a base struct of SolverSettings: the member
/// pointers convert to pointers to members of SolverSettings.
Schema<SolverSettings> solver_schema() {
  using S = SolverSettings;
  Schema<S> s;
  s.choice<Scheme>("scheme", &S::scheme, kSchemes,
                   "total-Lagrangian Newton (step-size independent), or the paper's incremental "
                   "velocity scheme");
  s.real("end_time", &S::end_time, Range::positive(), "s", "end of the (pseudo-)time");
  s.real("stop_load_factor", &S::stop_load_factor, Range{0.0, 1.0, false, true}, "–",
         "with `control: arc-length`: the run ends, completed, once its load factor falls below "
         "this on a falling branch (past a limit load: a collapse whose load never comes back to "
         "end_time); 0: only end_time ends it");
  s.choice<StepControl>(
      "control", &S::control, kStepControls,
      "load: each step raises the time (the load factor) and Newton finds the state; "
      "arc-length: from the second step on, each step has a length along the path of equilibria "
      "and the load factor is an unknown (Crisfield's cylindrical arc length), so the run follows "
      "the load past its maximum and through a snap-back, ending at end_time; the step-size keys "
      "then set the arc (docs/theory/arc_length.md)");
  s.integer("steps", &S::steps, Range::at_least(1),
            "initial number of steps (first step = end_time / steps)");
  s.integer("max_steps", &S::max_steps, Range::at_least(1), "largest number of steps");
  s.real("min_step", &S::min_step, kFraction, "–",
         "smallest step, fraction of end_time: a step that fails below it stops the run, which "
         "names the load factor it could not raise (a limit load under load control; "
         "summary.json `limit`)");
  s.real("max_step", &S::max_step, kFraction, "–", "largest step, fraction of end_time");
  s.real("growth", &S::growth, Range::at_least(1.0), "–", "step growth after easy steps");
  s.real("cutback", &S::cutback, kOpenUnit, "–", "step reduction after a failed step");
  s.integer("easy_iterations", &S::easy_iterations, Range::at_least(1),
            "a step is easy when Newton needs at most this many iterations");
  s.real("viscosity", &S::viscosity, Range::non_negative(), "MPa s",
         "viscous stabilisation through snap-throughs: nodal forces η V_i v_i / ℓ² against the "
         "step velocity (ℓ the wall thickness, else the mean edge length; "
         "docs/theory/viscous.md); history column `dissipated_energy` [mJ] — keep it small "
         "against the strain energy");
  s.integer("max_augmentations", &S::max_augmentations, Range::at_least(0),
            "multiplier updates per step for augmented-Lagrangian contact before the step counts "
            "as failed");
  s.nested<NewtonSettings>("newton", &S::newton, newton_schema());
  s.nested<StabilitySettings>("stability", &S::stability, stability_schema());
  s.add({"petsc_options",
         "text",
         "–",
         "",
         "empty",
         {},
         "extra PETSc options, e.g. `-ksp_type preonly -pc_type lu`: the solver options of the "
         "table \"PETSc options\" below, each with a value of its type; views and monitors "
         "print text to the log (`-ksp_view ::ascii_info`); every other option (one that names "
         "a file, writes a binary view, reads options, opens a window) is refused"},
        [](const Field& f, S& solver, ReadContext&) {
          solver.petsc_options = f.text();
          solver.petsc_options_place = f.place();
          // PETSc reads "-name [value] -name [value] ...": a word before the first option, or two
          // words in a row, is not read as anything and PETSc ignores it without a word (a
          // forgotten dash in "ksp_type preonly" silently kept the default solver).
          std::istringstream words(solver.petsc_options);
          bool after_value = true;  // nothing may come before the first "-option"
          for (std::string word; words >> word;) {
            const bool option = word.size() > 1 && word[0] == '-';
            if (!option && after_value)
              f.fail("'" + word +
                     "' is neither a PETSc option (options start with '-') nor the value of the "
                     "option before it; expected e.g. '-ksp_type preonly -pc_type lu'");
            after_value = !option;
          }
          if (const std::string problem = petsc_option_problem(solver.petsc_options);
              !problem.empty())
            f.fail(problem);
        })
      .null_is_absent();
  s.rule("`min_step` <= `max_step`", [](const FieldMap& m, const S& solver, const ReadContext&) {
    if (solver.min_step > solver.max_step)
      (m.has("min_step") ? *m.find("min_step") : *m.find("max_step"))
          .fail("min_step must be <= max_step (got min_step " + format_number(solver.min_step) +
                ", max_step " + format_number(solver.max_step) + ")");
  });
  s.rule(
      "`control: arc-length` refuses `viscosity`, `stability.branch_switch` and the "
      "iterative linear solver",
      [](const FieldMap& m, const S& solver, const ReadContext&) {
        if (solver.control != StepControl::arc_length) return;
        const std::string head = "with 'control: arc-length', ";
        if (solver.viscosity > 0.0)
          m.find("viscosity")
              ->fail(head +
                     "viscous stabilisation is not available: its forces follow the time "
                     "step, which the arc length makes run backwards past a limit load; the "
                     "arc length follows the snap itself");
        if (solver.stability.branch_switch)
          throw InputError(solver.stability.place,
                           head +
                               "'branch_switch' is not available: the arc length follows "
                               "the path it is on; switch branches under load control");
        if (solver.newton.linear.type == LinearSolverType::iterative)
          throw InputError(solver.newton.linear.place,
                           head +
                               "the linear systems are solved by MUMPS; remove "
                               "'type: iterative'");
      });
  s.rule("`stop_load_factor` needs `control: arc-length`",
         [](const FieldMap& m, const S& solver, const ReadContext&) {
           if (solver.stop_load_factor > 0.0 && solver.control != StepControl::arc_length)
             m.find("stop_load_factor")
                 ->fail(
                     "stop_load_factor needs 'control: arc-length' (under load control the "
                     "load factor never falls)");
         });
  s.rule("`steps` <= `max_steps`", [](const FieldMap& m, const S& solver, const ReadContext&) {
    if (solver.steps > solver.max_steps)
      (m.has("steps") ? *m.find("steps") : *m.find("max_steps"))
          .fail("steps must be <= max_steps (got steps " + std::to_string(solver.steps) +
                ", max_steps " + std::to_string(solver.max_steps) + ")");
  });
  return s;
}

}  // namespace plisse::case_detail
