#include "case/petsc_option_text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string_view>
#include <vector>

namespace plisse {
namespace {

/// The kind of value an option takes.
enum class Value {
  integer,  ///< a whole number, e.g. -ksp_max_it 200
  real,     ///< a finite real number, e.g. -ksp_rtol 1e-8
  word,     ///< one of the rule's words, e.g. -ksp_type gmres
  flag,     ///< nothing, or true/false (yes/no, on/off, 1/0)
  view,     ///< nothing, or a text format to the log (::ascii_info, ::ascii_info_detail)
};

/// Where an option may stand: alone, or after the prefix of one of the linear solvers.
enum class Prefixes {
  none,    ///< the option's name as it is (SNES, EPS)
  solver,  ///< also after fieldsplit_u_, fieldsplit_p_, stability_ or st_ (KSP, PC, MUMPS)
};

/// The linear solvers' prefixes: Newton's (none), the field split's blocks, the stability
/// check's factorisation (solver/stability.cpp) and SLEPc's spectral transformation.
constexpr std::string_view kSolverPrefixes[] = {"fieldsplit_u_", "fieldsplit_p_", "stability_",
                                                "st_"};

/// One accepted option. A `name` ending in '_' followed by `numbered` non-empty is a family:
/// the name followed by one of those numbers (-mat_mumps_icntl_14).
struct Rule {
  std::string_view name;  ///< lower case, without the dash and the prefix
  Value value;
  Prefixes prefixes;
  std::vector<std::string_view> words;  ///< Value::word: the accepted words
  std::string_view meaning;
  std::vector<int> numbered = {};
};

std::vector<int> numbers(int first, int last, std::vector<int> except = {}) {
  std::vector<int> out;
  for (int n = first; n <= last; ++n)
    if (std::find(except.begin(), except.end(), n) == except.end()) out.push_back(n);
  return out;
}

const std::vector<Rule>& rules() {
  using enum Value;
  constexpr Prefixes none = Prefixes::none, any = Prefixes::solver;
  static const std::vector<Rule> table = {
      // Newton: PETSc's SNES.
      {"snes_type",
       word,
       none,
       {"newtonls", "newtontr", "ksponly", "qn", "nrichardson", "ngmres", "anderson", "ncg"},
       "nonlinear solver"},
      {"snes_rtol", real, none, {}, "relative tolerance of Newton"},
      {"snes_atol", real, none, {}, "absolute tolerance of Newton"},
      {"snes_stol", real, none, {}, "tolerance on the step length"},
      {"snes_divergence_tolerance", real, none, {}, "divergence tolerance"},
      {"snes_max_it", integer, none, {}, "most Newton iterations"},
      {"snes_max_funcs", integer, none, {}, "most residual evaluations"},
      {"snes_max_fail", integer, none, {}, "most failed nonlinear solves"},
      {"snes_max_linear_solve_fail", integer, none, {}, "most failed linear solves"},
      {"snes_force_iteration", flag, none, {}, "at least one iteration"},
      {"snes_lag_jacobian", integer, none, {}, "rebuild the tangent every N iterations"},
      {"snes_lag_jacobian_persists", flag, none, {}, "the lag goes on across steps"},
      {"snes_lag_preconditioner", integer, none, {}, "rebuild the preconditioner every N"},
      {"snes_lag_preconditioner_persists", flag, none, {}, "the lag goes on across steps"},
      {"snes_linesearch_type", word, none, {"basic", "bt", "l2", "cp", "nleqerr"}, "line search"},
      {"snes_linesearch_order", integer, none, {}, "order of the backtracking polynomial"},
      {"snes_linesearch_damping", real, none, {}, "line-search damping"},
      {"snes_linesearch_max_it", integer, none, {}, "most line-search iterations"},
      {"snes_linesearch_maxstep", real, none, {}, "longest step"},
      {"snes_linesearch_minlambda", real, none, {}, "smallest step fraction"},
      {"snes_linesearch_alpha", real, none, {}, "sufficient decrease"},
      {"snes_linesearch_rtol", real, none, {}, "line-search relative tolerance"},
      {"snes_linesearch_atol", real, none, {}, "line-search absolute tolerance"},
      {"snes_linesearch_ltol", real, none, {}, "line-search step tolerance"},
      {"snes_linesearch_keeplambda", flag, none, {}, "start from the last step fraction"},
      {"snes_ksp_ew", flag, none, {}, "Eisenstat-Walker linear tolerances"},
      {"snes_ksp_ew_version", integer, none, {}, "Eisenstat-Walker version"},
      {"snes_ksp_ew_rtol0", real, none, {}, "Eisenstat-Walker first tolerance"},
      {"snes_ksp_ew_rtolmax", real, none, {}, "Eisenstat-Walker largest tolerance"},
      {"snes_ksp_ew_gamma", real, none, {}, "Eisenstat-Walker gamma"},
      {"snes_ksp_ew_alpha", real, none, {}, "Eisenstat-Walker alpha"},
      {"snes_ksp_ew_alpha2", real, none, {}, "Eisenstat-Walker alpha2"},
      {"snes_ksp_ew_threshold", real, none, {}, "Eisenstat-Walker threshold"},
      {"snes_test_jacobian", flag, none, {}, "compare the tangent with finite differences"},
      {"snes_monitor", view, none, {}, "print the residual norm of every iteration"},
      {"snes_monitor_short", view, none, {}, "the same, fewer digits"},
      {"snes_converged_reason", view, none, {}, "print why Newton stopped"},
      {"snes_linesearch_monitor", view, none, {}, "print the line search"},
      {"snes_view", view, none, {}, "print the nonlinear solver"},
      // Krylov solvers: PETSc's KSP.
      {"ksp_type",
       word,
       any,
       {"preonly", "gmres", "fgmres", "lgmres", "dgmres", "pgmres", "gcr",        "cg",
        "pipecg",  "fcg",   "minres", "symmlq", "cr",     "bcgs",   "bcgsl",      "fbcgs",
        "ibcgs",   "tfqmr", "tcqmr",  "bicg",   "cgs",    "lsqr",   "richardson", "chebyshev"},
       "Krylov method"},
      {"ksp_rtol", real, any, {}, "relative tolerance"},
      {"ksp_atol", real, any, {}, "absolute tolerance"},
      {"ksp_divtol", real, any, {}, "divergence tolerance"},
      {"ksp_max_it", integer, any, {}, "most iterations"},
      {"ksp_gmres_restart", integer, any, {}, "GMRES restart"},
      {"ksp_gmres_modifiedgramschmidt", flag, any, {}, "modified Gram-Schmidt"},
      {"ksp_gmres_cgs_refinement_type",
       word,
       any,
       {"refine_never", "refine_ifneeded", "refine_always"},
       "GMRES reorthogonalisation"},
      {"ksp_initial_guess_nonzero", flag, any, {}, "start from the last solution"},
      {"ksp_norm_type",
       word,
       any,
       {"none", "preconditioned", "unpreconditioned", "natural"},
       "norm of the convergence test"},
      {"ksp_pc_side", word, any, {"left", "right", "symmetric"}, "side of the preconditioner"},
      {"ksp_richardson_scale", real, any, {}, "Richardson damping"},
      {"ksp_error_if_not_converged", flag, any, {}, "an unconverged solve is an error"},
      {"ksp_reuse_preconditioner", flag, any, {}, "keep the preconditioner"},
      {"ksp_monitor", view, any, {}, "print the residual norm of every iteration"},
      {"ksp_monitor_short", view, any, {}, "the same, fewer digits"},
      {"ksp_monitor_true_residual", view, any, {}, "with the unpreconditioned residual"},
      {"ksp_converged_reason", view, any, {}, "print why the solve stopped"},
      {"ksp_view", view, any, {}, "print the linear solver"},
      // Preconditioners: PETSc's PC.
      {"pc_type",
       word,
       any,
       {"none",     "jacobi", "pbjacobi",   "vpbjacobi", "bjacobi",   "asm",
        "gasm",     "sor",    "eisenstat",  "ilu",       "icc",       "lu",
        "cholesky", "svd",    "fieldsplit", "hypre",     "gamg",      "mg",
        "ml",       "ksp",    "redundant",  "lsc",       "composite", "telescope"},
       "preconditioner"},
      {"pc_factor_mat_solver_type",
       word,
       any,
       {"mumps", "petsc", "superlu", "superlu_dist", "umfpack", "cholmod", "klu", "strumpack",
        "pastix", "mkl_pardiso"},
       "package of a factorisation"},
      {"pc_factor_mat_ordering_type",
       word,
       any,
       {"natural", "nd", "1wd", "rcm", "qmd", "rowlength", "external"},
       "ordering of a factorisation"},
      {"pc_factor_shift_type",
       word,
       any,
       {"none", "nonzero", "positive_definite", "inblocks"},
       "shift of zero pivots"},
      {"pc_factor_shift_amount", real, any, {}, "size of that shift"},
      {"pc_factor_levels", integer, any, {}, "levels of an incomplete factorisation"},
      {"pc_factor_fill", real, any, {}, "expected fill"},
      {"pc_factor_zeropivot", real, any, {}, "pivot taken as zero"},
      {"pc_factor_reuse_ordering", flag, any, {}, "keep the ordering"},
      {"pc_jacobi_type", word, any, {"diagonal", "rowmax", "rowsum"}, "Jacobi's diagonal"},
      {"pc_jacobi_abs", flag, any, {}, "absolute values"},
      {"pc_sor_omega", real, any, {}, "SOR relaxation"},
      {"pc_sor_its", integer, any, {}, "SOR iterations"},
      {"pc_sor_symmetric", flag, any, {}, "symmetric SOR"},
      {"pc_asm_overlap", integer, any, {}, "additive Schwarz overlap"},
      {"pc_asm_type",
       word,
       any,
       {"basic", "restrict", "interpolate", "none"},
       "additive Schwarz variant"},
      {"pc_bjacobi_blocks", integer, any, {}, "block-Jacobi blocks"},
      {"pc_gamg_type", word, any, {"agg", "geo", "classical"}, "algebraic multigrid (GAMG)"},
      {"pc_gamg_threshold", real, any, {}, "GAMG drop tolerance"},
      {"pc_gamg_agg_nsmooths", integer, any, {}, "GAMG smoothing steps"},
      {"pc_gamg_square_graph", integer, any, {}, "GAMG levels with a squared graph"},
      {"pc_gamg_sym_graph", flag, any, {}, "GAMG symmetrised graph"},
      {"pc_gamg_coarse_eq_limit", integer, any, {}, "GAMG coarsest size"},
      {"pc_mg_levels", integer, any, {}, "multigrid levels"},
      {"pc_mg_cycle_type", word, any, {"v", "w"}, "multigrid cycle"},
      {"pc_mg_type",
       word,
       any,
       {"additive", "multiplicative", "full", "kaskade"},
       "multigrid variant"},
      {"pc_hypre_type",
       word,
       any,
       {"boomeramg", "pilut", "parasails", "euclid", "ams", "ads"},
       "hypre preconditioner"},
      {"pc_hypre_boomeramg_strong_threshold", real, any, {}, "BoomerAMG strength threshold"},
      {"pc_hypre_boomeramg_max_levels", integer, any, {}, "BoomerAMG levels"},
      {"pc_hypre_boomeramg_max_iter", integer, any, {}, "BoomerAMG cycles"},
      {"pc_hypre_boomeramg_tol", real, any, {}, "BoomerAMG tolerance"},
      {"pc_hypre_boomeramg_truncfactor", real, any, {}, "BoomerAMG interpolation truncation"},
      {"pc_hypre_boomeramg_p_max", integer, any, {}, "BoomerAMG interpolation entries a row"},
      {"pc_hypre_boomeramg_max_row_sum", real, any, {}, "BoomerAMG row-sum threshold"},
      {"pc_hypre_boomeramg_agg_nl", integer, any, {}, "BoomerAMG aggressive coarsening levels"},
      {"pc_hypre_boomeramg_agg_num_paths", integer, any, {}, "BoomerAMG aggressive paths"},
      {"pc_hypre_boomeramg_grid_sweeps_all", integer, any, {}, "BoomerAMG smoothing sweeps"},
      {"pc_hypre_boomeramg_nodal_coarsen", integer, any, {}, "BoomerAMG nodal coarsening"},
      {"pc_hypre_boomeramg_vec_interp_variant", integer, any, {}, "BoomerAMG vector interpolation"},
      {"pc_hypre_boomeramg_coarsen_type",
       word,
       any,
       {"cljp", "ruge-stueben", "modifiedruge-stueben", "falgout", "pmis", "hmis"},
       "BoomerAMG coarsening"},
      {"pc_hypre_boomeramg_interp_type",
       word,
       any,
       {"classical", "direct", "multipass", "multipass-wts", "ext+i", "ext+i-cc", "standard",
        "standard-wts", "block", "block-wtd", "ff", "ff1", "ext", "ad-wts", "ext-mm", "ext+i-mm",
        "ext+e-mm"},
       "BoomerAMG interpolation"},
      {"pc_hypre_boomeramg_relax_type_all",
       word,
       any,
       {"jacobi", "sequential-gauss-seidel", "seqboundary-gauss-seidel", "sor/jacobi",
        "backward-sor/jacobi", "symmetric-sor/jacobi", "l1scaled-sor/jacobi",
        "gaussian-elimination", "l1-gauss-seidel", "backward-l1-gauss-seidel", "cg", "chebyshev",
        "fcf-jacobi", "l1scaled-jacobi"},
       "BoomerAMG smoother"},
      // The field split of the iterative solver (solver/linear_solver.hpp).
      {"pc_fieldsplit_type",
       word,
       any,
       {"additive", "multiplicative", "symmetric_multiplicative", "special", "schur", "gkb"},
       "how the blocks are combined"},
      {"pc_fieldsplit_schur_fact_type",
       word,
       any,
       {"diag", "lower", "upper", "full"},
       "Schur-complement factorisation"},
      {"pc_fieldsplit_schur_precondition",
       word,
       any,
       {"self", "selfp", "user", "a11", "full"},
       "preconditioner of the Schur complement"},
      {"pc_fieldsplit_schur_scale", real, any, {}, "scale of the diagonal Schur factorisation"},
      {"pc_fieldsplit_diag_use_amat", flag, any, {}, "blocks from the operator"},
      {"pc_fieldsplit_off_diag_use_amat", flag, any, {}, "coupling from the operator"},
      // MUMPS (its control numbers, ICNTL and CNTL, in MUMPS's manual). ICNTL(1) to (3) send its
      // messages to Fortran units, which write files, and ICNTL(22) factorises out of core into
      // files: those are left out.
      {"mat_mumps_icntl_",
       integer,
       any,
       {},
       "MUMPS integer control ICNTL(N), N = 4 to 60 but 22",
       numbers(4, 60, {22})},
      {"mat_mumps_cntl_", real, any, {}, "MUMPS real control CNTL(N), N = 1 to 15", numbers(1, 15)},
      {"mat_mumps_use_omp_threads", integer, any, {}, "MUMPS's OpenMP threads"},
      // Eigenmodes: SLEPc's EPS and its spectral transformation (solver/eigenmodes.hpp).
      {"eps_type",
       word,
       none,
       {"krylovschur", "arnoldi", "lanczos", "gd", "jd", "rqcg", "lobpcg", "power", "subspace",
        "lapack"},
       "eigensolver"},
      {"eps_nev", integer, none, {}, "eigenpairs asked for"},
      {"eps_ncv", integer, none, {}, "size of the subspace"},
      {"eps_mpd", integer, none, {}, "largest projected dimension"},
      {"eps_tol", real, none, {}, "eigensolver tolerance"},
      {"eps_max_it", integer, none, {}, "most eigensolver iterations"},
      {"eps_target", real, none, {}, "target eigenvalue"},
      {"eps_target_magnitude", flag, none, {}, "eigenvalues nearest the target"},
      {"eps_target_real", flag, none, {}, "eigenvalues nearest the target in real part"},
      {"eps_smallest_magnitude", flag, none, {}, "smallest eigenvalues in magnitude"},
      {"eps_smallest_real", flag, none, {}, "smallest eigenvalues"},
      {"eps_largest_magnitude", flag, none, {}, "largest eigenvalues in magnitude"},
      {"eps_largest_real", flag, none, {}, "largest eigenvalues"},
      {"eps_true_residual", flag, none, {}, "converge on the true residual"},
      {"eps_krylovschur_restart", real, none, {}, "Krylov-Schur restart fraction"},
      {"eps_monitor", view, none, {}, "print the eigensolver's iterations"},
      {"eps_converged_reason", view, none, {}, "print why the eigensolver stopped"},
      {"eps_view", view, none, {}, "print the eigensolver"},
      {"st_type", word, none, {"shift", "sinvert", "cayley", "precond"}, "spectral transformation"},
      {"st_shift", real, none, {}, "its shift"},
  };
  return table;
}

/// The formats a view or monitor may ask for: text, to the log.
constexpr std::string_view kTextFormats[] = {"::ascii_info", "::ascii_info_detail"};
constexpr std::string_view kFlagWords[] = {"true", "false", "yes", "no", "on", "off", "1", "0"};

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

/// The rule of the option `name` (lower case, without its dash), or null.
const Rule* find_rule(std::string_view name) {
  std::vector<std::string_view> bases = {name};
  for (const std::string_view prefix : kSolverPrefixes)
    if (name.starts_with(prefix)) bases.push_back(name.substr(prefix.size()));
  for (const Rule& rule : rules())
    for (std::size_t i = 0; i < bases.size(); ++i) {
      const std::string_view base = bases[i];
      if (i > 0 && rule.prefixes != Prefixes::solver) continue;
      if (rule.numbered.empty()) {
        if (base == rule.name) return &rule;
        continue;
      }
      if (!base.starts_with(rule.name)) continue;
      const std::string_view digits = base.substr(rule.name.size());
      if (digits.empty() || digits.size() > 2 ||
          !std::all_of(digits.begin(), digits.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }) ||
          digits[0] == '0')
        continue;
      const int n = std::stoi(std::string(digits));
      if (std::find(rule.numbered.begin(), rule.numbered.end(), n) != rule.numbered.end())
        return &rule;
    }
  return nullptr;
}

bool is_integer(const std::string& text) {
  std::size_t i = text[0] == '-' || text[0] == '+' ? 1 : 0;
  return i < text.size() && text.size() - i <= 18 &&
         std::all_of(text.begin() + static_cast<std::ptrdiff_t>(i), text.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

bool is_real(const std::string& text) {
  if (!std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
               c == '+' || c == '-';
      }))
    return false;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

template <class Words>
std::string listed(const Words& words) {
  std::string out;
  for (const std::string_view w : words) out += (out.empty() ? "" : ", ") + std::string(w);
  return out;
}

/// What `rule`'s value must be, in words.
std::string expected(const Rule& rule) {
  switch (rule.value) {
    case Value::integer:
      return "an integer";
    case Value::real:
      return "a real number";
    case Value::word:
      return "one of " + listed(rule.words);
    case Value::flag:
      return "nothing or true/false";
    case Value::view:
      return "nothing or " + listed(kTextFormats) +
             " (views and monitors print text to the log, never to a file)";
  }
  return {};
}

/// Whether `value` (lower case) fits `rule`.
bool fits(const Rule& rule, const std::string& value) {
  switch (rule.value) {
    case Value::integer:
      return is_integer(value);
    case Value::real:
      return is_real(value);
    case Value::word:
      return std::find(rule.words.begin(), rule.words.end(), value) != rule.words.end();
    case Value::flag:
      return std::find(std::begin(kFlagWords), std::end(kFlagWords), value) != std::end(kFlagWords);
    case Value::view:
      return std::find(std::begin(kTextFormats), std::end(kTextFormats), value) !=
             std::end(kTextFormats);
  }
  return false;
}

/// Whether PETSc reads `word` as an option name (PetscOptionsValidKey: a dash, or two, then a
/// letter); anything else after an option is its value.
bool is_option(const std::string& word) {
  const std::size_t dashes = word.starts_with("--") ? 2 : word.starts_with("-") ? 1 : 0;
  return dashes > 0 && word.size() > dashes &&
         std::isalpha(static_cast<unsigned char>(word[dashes])) &&
         !(dashes == 1 && is_real(word));  // -inf, -1e3: values
}

constexpr std::string_view kWhere =
    " is not among the solver options plisse accepts (docs/case-file.md, \"PETSc options\"); "
    "every option that names a file, writes a view or monitor other than text to the log, reads "
    "options (-options_file, -prefix_push) or starts another program is refused";

}  // namespace

std::string petsc_option_problem(const std::string& options) {
  for (const char c : options) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\'')
      return "the quote in '" + options +
             "' is refused: PETSc would read the words between quotes as one value";
    if (u != ' ' && (u < 0x21 || u > 0x7e) && !std::isspace(u))
      return "'" + options + "' holds a character other than printable ASCII";
  }
  std::istringstream stream(options);
  std::vector<std::string> words;
  for (std::string word; stream >> word;) words.push_back(word);
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (!is_option(word))
      return "'" + word +
             "' is neither a PETSc option (options start with '-') nor the value of the option "
             "before it";
    const bool has_value = i + 1 < words.size() && !is_option(words[i + 1]);
    const std::string given = word + (has_value ? " " + words[i + 1] : std::string());
    const Rule* rule = find_rule(lower(word.substr(word[1] == '-' ? 2 : 1)));
    if (!rule) return "'" + given + "' is refused: " + word + std::string(kWhere);
    const bool optional = rule->value == Value::flag || rule->value == Value::view;
    if (!has_value && !optional)
      return "'" + word + "' is refused: its value must be " + expected(*rule);
    if (has_value && !fits(*rule, lower(words[i + 1])))
      return "'" + given + "' is refused: the value of " + word + " must be " + expected(*rule);
    if (has_value) ++i;
  }
  return {};
}

std::string petsc_options_markdown() {
  std::ostringstream out;
  out << "| option | value | meaning |\n|---|---|---|\n";
  for (const Rule& rule : rules()) {
    std::string name = "-" + std::string(rule.name);
    if (!rule.numbered.empty()) name += "N";
    std::string value;
    switch (rule.value) {
      case Value::integer:
        value = "integer";
        break;
      case Value::real:
        value = "real";
        break;
      case Value::word:
        for (const std::string_view w : rule.words)
          value += (value.empty() ? "`" : " \\| `") + std::string(w) + "`";
        break;
      case Value::flag:
        value = "none, or `true` \\| `false`";
        break;
      case Value::view:
        value = "none, or `::ascii_info` \\| `::ascii_info_detail`";
        break;
    }
    out << "| `" << name << "`" << (rule.prefixes == Prefixes::solver ? " ¹" : "") << " | " << value
        << " | " << rule.meaning << " |\n";
  }
  out << "\n¹ also after a linear solver's prefix: `-fieldsplit_u_`, `-fieldsplit_p_` (the blocks "
         "of the iterative solver's field split), `-stability_` (the stability check's "
         "factorisation), `-st_` (the eigensolver's spectral transformation), e.g. "
         "`-fieldsplit_u_pc_hypre_boomeramg_strong_threshold 0.7`, "
         "`-stability_mat_mumps_cntl_3 1e-10`.\n";
  return out.str();
}

}  // namespace plisse
