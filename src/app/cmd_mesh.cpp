/// `plisse mesh KIND [options] [--element FAMILY] -o FILE.msh`: writes a generated mesh
/// (docs/architecture.md, "Interface contract"), or with `--element shell` the mid-surface of a
/// shell (docs/meshes.md, "Shell meshes"). One subcommand per kind of `mesh_kinds()`; its options
/// are that kind's declared options with dashes (inner_radius -> --inner-radius), so names, units,
/// ranges and defaults come from the one registry in mesh/generate.cpp.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "element/element_family.hpp"
#include "mesh/generate.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/quality.hpp"
#include "output/atomic_file.hpp"

namespace plisse::app {
namespace {

std::string dashed(std::string key) {
  for (char& c : key)
    if (c == '_') c = '-';
  return key;
}

/// Command-line values of one `plisse mesh KIND` invocation.
struct MeshCommand {
  MeshGenerationSpec spec;
  std::string symmetry = "full";
  std::string output;
  int format = 4;
  bool binary = false;
  std::string element;                  ///< --element; empty when not given
  CLI::Option* order_option = nullptr;  ///< --order of the subcommand (borrowed): given or not
};

InputError option_error(const std::string& option, const std::string& rule) {
  return InputError(InputPlace{"command line", 0, 0, option}, rule);
}

/// The family --element names: mini and taylor-hood choose the order of a solid mesh (an --order
/// given with them must agree), shell the mid-surface; nullopt when --element is not given.
std::optional<ElementFamily> element_option(const MeshCommand& cmd) {
  if (cmd.element.empty()) return std::nullopt;
  if (cmd.element == "shell") return ElementFamily::shell;
  const auto family = parse_element_family(cmd.element);
  if (!family)
    throw option_error("--element",
                       "must be one of mini, taylor-hood, shell (got '" + cmd.element + "')");
  return family;
}

/// The summary line of a written mesh.
std::string summary(const MeshCommand& cmd, double version, const Mesh& mesh) {
  std::ostringstream line;
  line << "wrote " << cmd.output << " (Gmsh " << version << (cmd.binary ? " binary" : " ASCII")
       << "): " << mesh.n_nodes() << " nodes, ";
  if (mesh.is_shell())
    line << mesh.triangles.size() << " triangles (shell mid-surface)";
  else
    line << mesh.n_tets() << " tetrahedra" << (mesh.order() == 2 ? " (second order)" : "");
  line << "; tags:";
  bool first = true;
  for (const auto& [name, triangles] : mesh.surface_tags) {
    line << (first ? " " : ", ") << name << " (" << triangles.size() << " triangles)";
    first = false;
  }
  if (!mesh.edge_tags.empty()) {
    line << "; edge tags:";
    first = true;
    for (const auto& [name, edges] : mesh.edge_tags) {
      line << (first ? " " : ", ") << name << " (" << edges.size() << " edges)";
      first = false;
    }
  }
  return line.str();
}

void run(const MeshKind& kind, MeshCommand& cmd) {
  const std::optional<ElementFamily> family = element_option(cmd);
  const bool shell = family == ElementFamily::shell;
  // Declared ranges, reported with the option's name (a shell ignores `layers`).
  for (const auto& option : kind.options) {
    if (shell && option.integer == &MeshGenerationSpec::layers) continue;
    std::optional<std::string> violation;
    if (option.real) violation = option.range.violation(cmd.spec.*option.real);
    if (option.integer)
      violation = option.range.violation(static_cast<double>(cmd.spec.*option.integer));
    if (option.symmetry) {
      const auto symmetry = parse_symmetry(cmd.symmetry);
      if (!symmetry)
        throw option_error(
            "--" + dashed(option.key),
            "must be one of full, half, quarter, octant (got '" + cmd.symmetry + "')");
      cmd.spec.*option.symmetry = *symmetry;
    }
    if (violation) throw option_error("--" + dashed(option.key), *violation);
  }
  if (family) {
    const int order = mesh_order_of(*family);
    const bool order_given = cmd.order_option != nullptr && cmd.order_option->count() > 0;
    // A shell refuses --order 2 itself (generate_shell_surface), naming the rule.
    if (order_given && !shell && cmd.spec.order != order)
      throw option_error("--order", "--element " + cmd.element + " needs order " +
                                        std::to_string(order) + " (got " +
                                        std::to_string(cmd.spec.order) + ")");
    if (!order_given) cmd.spec.order = order;
  }
  if (cmd.format != 2 && cmd.format != 4)
    throw option_error("--format", "must be 2 (Gmsh v2.2) or 4 (Gmsh v4.1) (got " +
                                       std::to_string(cmd.format) + ")");

  Mesh mesh;
  try {
    mesh = shell ? generate_shell_surface(cmd.spec) : generate_mesh(cmd.spec);
  } catch (const InputError& e) {
    // Cross-option rules name the case-file key "mesh.<key>"; here the option is "--<key>". The
    // kind ("mesh.generate") is the subcommand, so a kind that has no shell is --element's fault.
    const std::string& key = e.place().key;
    if (key == "mesh.generate") throw option_error("--element", e.rule());
    if (key.rfind("mesh.", 0) == 0) throw option_error("--" + dashed(key.substr(5)), e.rule());
    throw;
  }
  if (!shell) {
    // check_mesh is the tetrahedral mesh's; make_shell_surface has checked a shell.
    const MeshReport report = check_mesh(mesh);
    for (const auto& warning : report.warnings)
      std::cerr << "plisse mesh: warning: " << warning << '\n';
    PLISSE_CHECK(report.ok(),
                 "internal error: the generated mesh fails check_mesh: " << report.errors.front());
  }

  const double version = cmd.format == 2 ? 2.2 : 4.1;
  // Written beside the target and renamed over it: an interrupted write leaves the earlier file
  // whole, and the next write of the same name removes what a killed one left.
  if (cmd.output.size() < 4 || cmd.output.compare(cmd.output.size() - 4, 4, ".msh") != 0)
    throw option_error("-o",
                       "the mesh file name must end in .msh (Gmsh picks the format from "
                       "the extension; got '" +
                           cmd.output + "')");
  const std::filesystem::path target(cmd.output);
  const std::filesystem::path folder =
      target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  remove_stale_temporaries(folder, target.filename().string());
  AtomicPath file(target);
  try {
    write_gmsh(mesh, file.temporary().string(), version, cmd.binary);
  } catch (const InputError& e) {
    std::error_code ec;
    throw InputError({cmd.output, 0, 0, "-o"},
                     e.rule() + (std::filesystem::exists(target, ec)
                                     ? "; the earlier " + target.filename().string() + " is kept"
                                     : std::string()));
  }
  file.commit();

  std::cout << summary(cmd, version, mesh) << '\n';
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto* mesh = app.add_subcommand("mesh",
                                  "Write a generated mesh: plisse mesh KIND [options] -o FILE.msh "
                                  "(lengths in mm; see docs/meshes.md)");
  mesh->require_subcommand(1);
  for (const MeshKind& kind : mesh_kinds()) {
    auto* sub = mesh->add_subcommand(kind.name, kind.help);
    auto cmd = std::make_shared<MeshCommand>();
    cmd->spec.kind = kind.name;
    cmd->spec.order = mesh_order_of(kDefaultElement);  // meshes for a case's default element
    for (const MeshOption& option : kind.options) {
      const std::string flag = "--" + dashed(option.key);
      const std::string unit = option.unit == "-" ? "" : " [" + option.unit + "]";
      if (option.real)
        sub->add_option(flag, cmd->spec.*option.real,
                        option.help + unit + ", " + option.range.describe())
            ->capture_default_str();
      else if (option.integer) {
        auto* added = sub->add_option(flag, cmd->spec.*option.integer,
                                      option.help + ", integer " + option.range.describe());
        added->capture_default_str();
        if (option.integer == &MeshGenerationSpec::order) cmd->order_option = added;
      } else
        sub->add_option(flag, cmd->symmetry, option.help)->capture_default_str();
    }
    sub->add_option("--element", cmd->element,
                    "element family the mesh is for: mini (--order 1), taylor-hood (--order 2) "
                    "or shell (the mid-surface: 3-node triangles and no tetrahedra; layers is "
                    "ignored); not given: --order decides");
    sub->add_option("-o,--output", cmd->output, "output file, must end in .msh")->required();
    sub->add_option("--format", cmd->format, "Gmsh file format: 2 (v2.2) or 4 (v4.1)")
        ->capture_default_str();
    sub->add_flag("--binary", cmd->binary, "write a binary file (default ASCII)");
    sub->callback([&kind, cmd] { run(kind, *cmd); });
  }
}

}  // namespace plisse::app
