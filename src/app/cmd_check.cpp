// `plisse check CASE.yaml [--set key.path=value ...]`: validates a case and its mesh without
// solving (docs/architecture.md, "Interface contract") and prints a short summary. Problems are
// thrown as InputError, which main() reports with file, line, column and key and exit status 2.
#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/model_builder.hpp"
#include "app/pre_step_checks.hpp"
#include "app/run_plan.hpp"
#include "app/run_session.hpp"
#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "material/registry.hpp"
#include "mesh/quality.hpp"
#include "output/run_directory.hpp"
#include "solver/petsc_session.hpp"
#include "solver/pressure_twins.hpp"

namespace plisse::app {
namespace {

struct CheckOptions {
  std::string case_file;
  std::vector<std::string> overrides;
  std::string output_directory;  ///< -o DIR; empty: runs/<case file stem>, as `plisse run`
};

std::string number(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

/// "1 die", "3 dies".
std::string count(std::size_t n, const std::string& one, const std::string& many = {}) {
  return std::to_string(n) + " " + (n == 1 ? one : (many.empty() ? one + "s" : many));
}

std::string material_line(const MaterialSection& m) {
  std::string out = m.model + ":";
  const MaterialModelInfo* info = find_material_model(m.model);
  bool first = true;
  for (const auto& [key, value] : m.params) {
    std::string unit;
    if (info)
      for (const ParamSpec& p : info->params)
        if (p.name == key && p.unit != "-") unit = " " + p.unit;
    out += (first ? " " : ", ") + key + " = " + number(value) + unit;
    first = false;
  }
  out += m.exact_incompressibility
             ? "; exactly incompressible"
             : "; nearly incompressible, bulk modulus " + number(m.bulk_modulus) + " MPa";
  if (m.density > 0.0) out += "; density " + number(m.density) + " tonne/mm^3";
  if (m.shell_fibre_frame)
    out += "; fibre directions in each element's (meridian, hoop, normal) frame";
  const Viscoelasticity& v = m.viscoelastic;
  if (v.n_terms() > 0) {
    out += "; viscoelastic, " + count(static_cast<std::size_t>(v.n_terms()), "Maxwell element") +
           " (beta, tau):";
    for (int i = 0; i < v.n_terms(); ++i)
      out += std::string(i ? "," : "") + " (" + number(v.beta(i)) + ", " + number(v.tau(i)) + " s)";
  }
  if (m.mullins.present())
    out += "; Mullins softening r = " + number(m.mullins.r) + ", m = " + number(m.mullins.m) +
           " MPa, beta = " + number(m.mullins.beta);
  return out;
}

void check_case(const CheckOptions& options) {
  const Case c = parse_case_file(options.case_file, options.overrides);
  // The run directory `plisse run` would write (nothing is created here).
  const std::filesystem::path directory =
      options.output_directory.empty()
          ? std::filesystem::path("runs") / std::filesystem::path(options.case_file).stem()
          : std::filesystem::path(options.output_directory);
  if (const std::string problem = output_path_problem(directory); !problem.empty())
    throw InputError({directory.string(), 0, 0, "-o"}, problem);
  const Mesh mesh = load_perturbed_mesh(c);  // with the imperfection, as `plisse run` builds it
  // The same rules `plisse run` applies before solving, from the same table (app/pre_step_checks):
  // the element and the mesh's order, curved elements, symmetry planes, conflicting conditions,
  // pieces held by nothing. Material, conditions and terms: loads, cavities and dies validate
  // their surfaces here.
  run_pre_step_checks(PreStepStage::mesh, c, mesh);
  const ModelParts parts = build_model_parts(c, mesh);
  run_pre_step_checks(PreStepStage::parts, c, mesh, &parts);
  check_petsc_environment();
  {
    PetscSession petsc({"-no_signal_handler", c.solver.petsc_options});
    check_solver_options(c, {});
  }
  const MeshReport report = check_mesh(mesh);

  std::ostream& out = std::cout;
  out << "plisse check: " << c.path << ": valid\n";
  if (!c.title.empty()) out << "  title     " << c.title << '\n';
  out << "  units     the case's own consistent set: plisse assumes none (mm, N, MPa and s below "
         "are the docs' names for its length, force, stress and time units)\n";
  out << "  material  " << material_line(c.material) << '\n';
  for (const Region& r : c.regions) {
    const std::size_t n = region_elements(r, mesh).size();
    out << "  region    " << r.label() << " ("
        << (mesh.is_shell() ? count(n, "triangle", "triangles")
                            : count(n, "tetrahedron", "tetrahedra"))
        << "): ";
    if (r.material) out << material_line(*r.material);
    if (r.thickness) out << ", thickness " << number(*r.thickness) << " mm";
    if (r.rigid && r.displacement.isZero()) out << "rigid, held";
    if (r.rigid && !r.displacement.isZero())
      out << "rigid, translated by (" << number(r.displacement[0]) << ", "
          << number(r.displacement[1]) << ", " << number(r.displacement[2]) << ") mm";
    out << '\n';
  }
  const char* family = c.element == ElementFamily::mini ? " (P1+/P1, linear tetrahedra)"
                       : c.element == ElementFamily::taylor_hood
                           ? " (P2/P1, 10-node tetrahedra)"
                           : " (rotation-free Kirchhoff-Love triangles on the mid-surface)";
  out << "  element   " << to_string(c.element) << family << '\n';
  if (!mesh.is_shell() && !c.regions.empty()) {
    const int twins =
        make_pressure_twins(mesh.n_nodes(), mesh.tets, parts.materials.pressure_region).n_twins();
    out << "  pressure  "
        << (c.region_pressure == RegionPressure::continuous
                ? "one continuous field across the regions (region_pressure: continuous)"
                : "a region's own where regions meet: " +
                      count(static_cast<std::size_t>(twins), "pressure unknown") +
                      " more at the corner nodes they share")
        << '\n';
  }
  const auto tag_line = [&out](const char* what,
                               const std::map<std::string, std::vector<int>>& tags,
                               const char* items) {
    out << "            " << what << " tags:";
    bool first = true;
    for (const auto& [name, members] : tags) {
      out << (first ? " " : ", ") << name << " (" << members.size() << " " << items << ")";
      first = false;
    }
    out << (tags.empty() ? " none\n" : "\n");
  };
  out << "  mesh      "
      << (c.mesh.file ? "file " + *c.mesh.file : "generated " + c.mesh.generate->kind) << ": "
      << mesh.n_nodes() << " nodes, ";
  if (mesh.is_shell()) {
    const auto [thinnest, thickest] =
        std::minmax_element(mesh.triangle_thickness.begin(), mesh.triangle_thickness.end());
    out << mesh.triangles.size() << " triangles, thickness " << number(*thinnest)
        << (*thickest > *thinnest ? " to " + number(*thickest) : std::string()) << " mm\n";
    tag_line("edge", mesh.edge_tags, "edges");
    tag_line("surface", mesh.surface_tags, "triangles");
    out << "            quality: smallest angle " << number(report.min_angle_deg)
        << " degrees, largest turn between neighbours " << number(report.max_turn_deg)
        << " degrees, " << count(report.warnings.size(), "warning") << '\n';
  } else {
    out << mesh.n_tets() << " tetrahedra" << (mesh.order() == 2 ? " (second order)" : "") << '\n';
    tag_line("surface", mesh.surface_tags, "triangles");
    out << "            quality: smallest volume " << number(report.min_volume)
        << " mm^3, largest aspect ratio " << number(report.max_aspect_ratio) << ", "
        << count(report.warnings.size(), "warning") << '\n';
  }
  for (std::size_t i = 0; i < report.warnings.size() && i < 5; ++i)
    out << "            warning: " << report.warnings[i] << '\n';
  for (const InputError& e : setup_warnings(c, &mesh))
    std::cerr << "plisse check: warning: " << e.what() << '\n';
  out << "  case      " << count(c.terms_in("boundary").size(), "boundary condition") << ", "
      << count(c.terms_in("loads").size(), "load") << ", "
      << count(c.terms_in("cavities").size(), "cavity", "cavities") << ", "
      << count(c.terms_in("dies").size(), "die") << ", " << count(c.terms_in("caps").size(), "cap")
      << ", " << count(c.terms_in("contacts").size(), "contact") << ", "
      << count(c.probes.size(), "probe") << '\n';
  out << "  solver    "
      << (c.solver.scheme == Scheme::total_lagrangian ? "total-lagrangian" : "incremental")
      << ", end_time " << number(c.solver.end_time) << " s, " << c.solver.steps
      << " initial steps (at most " << c.solver.max_steps << "), Newton rtol "
      << number(c.solver.newton.rtol) << ", at most " << c.solver.newton.max_iterations
      << " iterations" << (c.solver.stability.check ? ", stability check on" : "")
      << (c.solver.control == StepControl::arc_length ? ", arc-length control from step 2" : "")
      << '\n';
  if (const WrinkleSettings& w = c.output.wrinkles; w.enabled()) {
    out << "  wrinkles  ";
    if (w.has_rings()) out << count(w.rings_deg.size(), "ring") << " about " << w.axis << ", ";
    for (const WrinkleLine& line : w.lines)
      out << "line " << line.name << " (" << number((line.to - line.from).norm()) << " mm, "
          << line.points << " points"
          << (line.mirror == LineMirror::none
                  ? std::string()
                  : std::string(", mirrored at its ") +
                        (line.mirror == LineMirror::from ? "start" : "end"))
          << "), ";
    out << "tension field of '" << w.surface << "'; wrinkled above "
        << number(w.threshold * *c.mesh.wall_thickness()) << " mm\n";
  }
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "check", "Validate a case file and its mesh without solving (exit 0 when valid, 2 if not)");
  auto options = std::make_shared<CheckOptions>();
  cmd->add_option("case", options->case_file, "Case file (YAML)")->required();
  cmd->add_option("--set", options->overrides,
                  "Override a case value before validation, e.g. --set mesh.layers=4, "
                  "--set loads[0].value=1e-3 (repeatable)")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_option("-o,--output", options->output_directory,
                  "The run directory to judge as `plisse run -o DIR` would write it (default "
                  "runs/<case name>): a file on its path or a directory under a run file's name "
                  "is refused");
  cmd->callback([options] { check_case(*options); });
}

}  // namespace plisse::app
