/// `plisse mesh KIND [options] -o FILE.msh`: writes a generated mesh (docs/architecture.md,
/// "Interface contract"). One subcommand per kind of `mesh_kinds()`; its options are that kind's
/// declared options with dashes (inner_radius -> --inner-radius), so names, units, ranges and
/// defaults come from the one registry in mesh/generate.cpp.
#include <filesystem>
#include <iostream>
#include <memory>
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
};

InputError option_error(const std::string& option, const std::string& rule) {
  return InputError(InputPlace{"command line", 0, 0, option}, rule);
}

void run(const MeshKind& kind, MeshCommand& cmd) {
  // Declared ranges, reported with the option's name.
  for (const auto& option : kind.options) {
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
  if (cmd.format != 2 && cmd.format != 4)
    throw option_error("--format", "must be 2 (Gmsh v2.2) or 4 (Gmsh v4.1) (got " +
                                       std::to_string(cmd.format) + ")");

  Mesh mesh;
  try {
    mesh = generate_mesh(cmd.spec);
  } catch (const InputError& e) {
    // Cross-option rules name the case-file key "mesh.<key>"; here the option is "--<key>".
    const std::string& key = e.place().key;
    if (key.rfind("mesh.", 0) == 0) throw option_error("--" + dashed(key.substr(5)), e.rule());
    throw;
  }
  const MeshReport report = check_mesh(mesh);
  for (const auto& warning : report.warnings)
    std::cerr << "plisse mesh: warning: " << warning << '\n';
  PLISSE_CHECK(report.ok(),
               "internal error: the generated mesh fails check_mesh: " << report.errors.front());

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
    throw InputError({cmd.output, 0, 0, "-o"}, e.rule());
  }
  file.commit();

  std::ostringstream line;
  line << "wrote " << cmd.output << " (Gmsh " << version << (cmd.binary ? " binary" : " ASCII")
       << "): " << mesh.n_nodes() << " nodes, " << mesh.n_tets() << " tetrahedra"
       << (mesh.order() == 2 ? " (second order)" : "") << "; tags:";
  bool first = true;
  for (const auto& [name, triangles] : mesh.surface_tags) {
    line << (first ? " " : ", ") << name << " (" << triangles.size() << " triangles)";
    first = false;
  }
  std::cout << line.str() << '\n';
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
      else if (option.integer)
        sub->add_option(flag, cmd->spec.*option.integer,
                        option.help + ", integer " + option.range.describe())
            ->capture_default_str();
      else
        sub->add_option(flag, cmd->symmetry, option.help)->capture_default_str();
    }
    sub->add_option("-o,--output", cmd->output, "output file, must end in .msh")->required();
    sub->add_option("--format", cmd->format, "Gmsh file format: 2 (v2.2) or 4 (v4.1)")
        ->capture_default_str();
    sub->add_flag("--binary", cmd->binary, "write a binary file (default ASCII)");
    sub->callback([&kind, cmd] { run(kind, *cmd); });
  }
}

}  // namespace plisse::app
