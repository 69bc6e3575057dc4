// The checks of a case that need its mesh: loading or generating the mesh with errors placed at
// the case's `mesh:` keys, surface tags named by the case, planar symmetry surfaces, mesh quality.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include "analysis/point_location.hpp"
#include "analysis/wall_thickness.hpp"
#include "analysis/wrinkle_lines.hpp"
#include "case/case.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/quality.hpp"
#include "mesh/shell_surface.hpp"
#include "mesh/topology.hpp"
#include "schema/field.hpp"

namespace plisse {
namespace {

using schema::format_number;

std::string mesh_name(const Case& c) {
  if (c.mesh.file) return "mesh file '" + *c.mesh.file + "'";
  return "the generated " + (c.mesh.generate ? c.mesh.generate->kind : std::string()) + " mesh";
}

/// The surface or the volume tags of a mesh, as the messages name them.
struct TagKind {
  const std::map<std::string, std::vector<int>> Mesh::*tags;
  const char* kind;   ///< "surface"
  const char* items;  ///< "triangles"
  int dimension;      ///< of the Gmsh physical groups
};
constexpr TagKind kSurfaceTags{&Mesh::surface_tags, "surface", "triangles", 2};
constexpr TagKind kVolumeTags{&Mesh::volume_tags, "volume", "tetrahedra", 3};
constexpr TagKind kEdgeTags{&Mesh::edge_tags, "edge", "edges", 1};

/// "available surface tags: a (12 triangles), ...".
std::string tag_list(const Mesh& mesh, const TagKind& kind) {
  const auto& tags = mesh.*kind.tags;
  if (tags.empty())
    return std::string("the mesh has no ") + kind.kind +
           " tags (Gmsh physical groups of dimension " + std::to_string(kind.dimension) + ")";
  std::string out = std::string("available ") + kind.kind + " tags: ";
  bool first = true;
  for (const auto& [name, members] : tags) {
    out +=
        (first ? "" : ", ") + name + " (" + std::to_string(members.size()) + " " + kind.items + ")";
    first = false;
  }
  return out;
}

/// The tag `name` of `kind` exists in the mesh and is not empty; else an InputError at `place`
/// that lists the tags there are (and the nearest name to a typo).
void check_tag(const Case& c, const Mesh& mesh, const TagKind& kind, const std::string& name,
               const InputPlace& place) {
  const auto& tags = mesh.*kind.tags;
  const auto tag = tags.find(name);
  if (tag == tags.end()) {
    std::vector<std::string> names;
    for (const auto& [known, members] : tags) names.push_back(known);
    std::string rule = std::string("no ") + kind.kind + " tag '" + name + "' in " + mesh_name(c);
    if (const auto guess = schema::closest_match(name, names))
      rule += " (did you mean '" + *guess + "'?)";
    throw InputError(place, rule + "; " + tag_list(mesh, kind));
  }
  if (tag->second.empty())
    throw InputError(place, std::string(kind.kind) + " tag '" + name + "' of " + mesh_name(c) +
                                " has no " + kind.items + "; " + tag_list(mesh, kind));
}

/// A surface tag; on a shell, an edge tag given instead is named as such (the key wants a face).
void check_surface(const Case& c, const Mesh& mesh, const SurfaceRef& ref) {
  if (mesh.is_shell() && !mesh.surface_tags.count(ref.name) && mesh.edge_tags.count(ref.name))
    throw InputError(ref.place, "'" + ref.name + "' is an edge tag of " + mesh_name(c) +
                                    ": this key names a face of the shell (a surface tag); " +
                                    tag_list(mesh, kSurfaceTags));
  check_tag(c, mesh, kSurfaceTags, ref.name, ref.place);
}

/// A condition's tag: a surface tag, or on a shell an edge tag or a surface tag (the message
/// lists both kinds).
void check_condition(const Case& c, const Mesh& mesh, const SurfaceRef& ref) {
  if (!mesh.is_shell()) return check_surface(c, mesh, ref);
  if (mesh.edge_tags.count(ref.name)) return check_tag(c, mesh, kEdgeTags, ref.name, ref.place);
  if (mesh.surface_tags.count(ref.name))
    return check_tag(c, mesh, kSurfaceTags, ref.name, ref.place);
  std::vector<std::string> names;
  for (const auto& [known, members] : mesh.edge_tags) names.push_back(known);
  for (const auto& [known, members] : mesh.surface_tags) names.push_back(known);
  std::string rule = "no edge or surface tag '" + ref.name + "' in " + mesh_name(c);
  if (const auto guess = schema::closest_match(ref.name, names))
    rule += " (did you mean '" + *guess + "'?)";
  throw InputError(ref.place,
                   rule + "; " + tag_list(mesh, kEdgeTags) + "; " + tag_list(mesh, kSurfaceTags));
}

/// What `element: shell` does not run yet, and the kinds of the other family: each refused at
/// its own key, naming it (docs/case-file.md, "Shells").
void check_element_family(const Case& c, const Mesh& mesh) {
  const bool shell = mesh.is_shell();
  for (const TermEntry& entry : c.terms) {
    const TermKind& kind = *entry.kind;
    const std::string what =
        kind.word.empty() ? "`" + kind.section + "` item" : "`type: " + kind.word + "`";
    if (shell && !kind.shell)
      throw InputError(entry.place, what + " is not built for `element: shell` yet");
    if (!shell && !kind.solid)
      throw InputError(entry.place,
                       what + " acts on the edge of a shell: it needs `element: shell`");
  }
  if (!shell) return;
  const auto refuse = [](const InputPlace& place, const std::string& what) {
    throw InputError(place, what + " is not built for `element: shell` yet");
  };
  const auto refuse_material = [&](const MaterialSection& m) {
    if (!m.inelastic().elastic())
      refuse(m.place, "a viscoelastic or Mullins material (history at the thickness points)");
    if (m.shell_fibre_frame) refuse(m.fibre_frame_place, "`fibre_frame: shell`");
  };
  refuse_material(c.material);
  for (const Region& r : c.regions)
    if (r.material) refuse_material(*r.material);
}

/// Every region names its elements the way its mesh holds them (a solid's by a volume tag or a
/// box of tetrahedra, a shell's by a surface tag or a box of triangles), holds some, shares none
/// with another region, and gives a thickness only on a shell; something is left to deform. A
/// shell takes no `region_pressure`.
void check_regions(const Case& c, const Mesh& mesh) {
  const bool shell = mesh.is_shell();
  if (shell && !c.region_pressure_place.key.empty())
    throw InputError(c.region_pressure_place,
                     "a shell has no pressure unknowns (plane stress): `region_pressure` is for "
                     "the mixed solid elements, mini and taylor-hood");
  if (c.regions.empty()) return;
  const std::string element = shell ? "triangle" : "tetrahedron";
  std::vector<int> region_of(shell ? mesh.triangles.size() : mesh.tets.size(), -1);
  for (std::size_t k = 0; k < c.regions.size(); ++k) {
    const Region& r = c.regions[k];
    if (shell && !r.volume.empty())
      throw InputError(r.volume_place,
                       "a shell has no volumes: name the region's triangles by a `surface` tag "
                       "(a Gmsh physical surface) or a `box`");
    if (!shell && !r.surface.empty())
      throw InputError(r.surface_place,
                       "`surface` names a shell's triangles; a region of a solid is a `volume` "
                       "tag (a Gmsh physical volume) or a `box`");
    if (!shell && r.thickness)
      throw InputError(r.thickness_place,
                       "`thickness` is a shell region's wall thickness; a solid's is its mesh's");
    if (!r.box) {
      if (shell)
        check_tag(c, mesh, kSurfaceTags, r.surface, r.surface_place);
      else
        check_tag(c, mesh, kVolumeTags, r.volume, r.volume_place);
    }
    const std::vector<int> elements = region_elements(r, mesh);
    if (elements.empty())
      throw InputError(r.box_place,
                       "no " + element + " of " + mesh_name(c) + " has its centroid in the box");
    const InputPlace& where = r.box ? r.box_place : shell ? r.surface_place : r.volume_place;
    for (int t : elements) {
      int& owner = region_of[static_cast<std::size_t>(t)];
      if (owner >= 0)
        throw InputError(where, "region '" + r.label() + "' shares " + element + " " +
                                    std::to_string(t + 1) + " (numbered from 1) with region '" +
                                    c.regions[static_cast<std::size_t>(owner)].label() + "': a " +
                                    element + " may be in one region only");
      owner = static_cast<int>(k);
    }
  }
  const bool deforms = std::any_of(region_of.begin(), region_of.end(), [&](int k) {
    return k < 0 || !c.regions[static_cast<std::size_t>(k)].rigid;
  });
  if (!deforms)
    throw InputError(c.regions.back().place,
                     "every " + element + " is in a rigid region: nothing is left to deform");
}

/// A probe reports at a material point of the body: one farther from the mesh than the longest
/// edge of the element nearest to it lies off the body (a wrong coordinate or unit). A probe of
/// the thickness needs a wall (a shell has one); a shell has no pressure field to probe.
void check_probe(const Case& c, const Mesh& mesh, const Probe& probe) {
  const std::string what = "probe '" + probe.name + "'";
  // Beyond the meshes' coordinate range the location's arithmetic overflows (a point such as
  // [1e200, 1e200, 1e200] came out "0 mm from its point").
  if (!(probe.point.cwiseAbs().maxCoeff() <= kMaxCoordinate))
    throw InputError(probe.point_place, what + ": the point " + schema::format_vector(probe.point) +
                                            " lies beyond ±" + format_number(kMaxCoordinate) +
                                            " mm, far off the body: give a point on the body");
  const MeshPoint at = locate_point(mesh, probe.point);
  std::vector<int> corners;
  if (mesh.is_shell()) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(at.element)];
    corners.assign(tri.begin(), tri.end());
  } else {
    const auto& t = mesh.tets[static_cast<std::size_t>(at.element)];
    corners.assign(t.begin(), t.end());
  }
  double longest = 0.0;
  for (std::size_t a = 0; a < corners.size(); ++a)
    for (std::size_t b = a + 1; b < corners.size(); ++b)
      longest = std::max(longest, (mesh.nodes[static_cast<std::size_t>(corners[a])] -
                                   mesh.nodes[static_cast<std::size_t>(corners[b])])
                                      .norm());
  if (!(at.distance <= longest))
    throw InputError(probe.point_place,
                     what + ": the point " + schema::format_vector(probe.point) + " is " +
                         format_number(at.distance) + " mm from the body (its nearest point " +
                         schema::format_vector(at.position) +
                         "), farther than the longest edge of the " + "element there (" +
                         format_number(longest) + " mm): give a point on the body");
  const auto asks = [&](ProbeField f) {
    return std::find(probe.fields.begin(), probe.fields.end(), f) != probe.fields.end();
  };
  if (mesh.is_shell()) {
    if (asks(ProbeField::pressure))
      throw InputError(probe.fields_place.line > 0 ? probe.fields_place : probe.place,
                       what +
                           ": a shell has no pressure unknown (plane stress eliminates it, "
                           "docs/theory/shell.md KL9): probe `cauchy` instead, or read the "
                           "step files' cell field `pressure`");
    return;  // the thickness of a shell is its own (its triangles' current thickness)
  }
  if (asks(ProbeField::thickness) && !(c.mesh.wall_thickness() && wall_faces(mesh)))
    throw InputError(
        probe.fields_place.line > 0 ? probe.fields_place : probe.place,
        what + ": the thickness is measured across a wall: " +
            (c.mesh.wall_thickness()
                 ? std::string("the mesh needs surface tags 'inner' and 'outer' (or 'bottom' "
                               "and 'top')")
                 : std::string(c.mesh.file ? "give the wall thickness as 'mesh.thickness' [mm]"
                                           : "the generated cube has no wall")));
}

/// Imperfections, branch switching and the wrinkle threshold are relative to the wall thickness: a
/// case that uses them needs a shell mesh or a file mesh with `thickness:`.
void check_wall_thickness(const Case& c) {
  if (c.mesh.wall_thickness()) return;
  const std::string why = c.mesh.file ? "give the wall thickness as 'mesh.thickness' [mm]"
                                      : "the generated cube has no wall";
  const StabilitySettings& st = c.solver.stability;
  if (st.imperfection > 0.0)
    throw InputError(st.place,
                     "the imperfection amplitude is relative to the wall thickness: " + why);
  if (st.branch_switch)
    throw InputError(st.place,
                     "the branch-switching perturbation is relative to the wall thickness: " + why);
  if (c.output.wrinkles.enabled())
    throw InputError(c.output.wrinkles.place,
                     "the wrinkle threshold is relative to the wall thickness: " + why);
}

/// A measurement line lies in the body: each of its samples within half the wall thickness of the
/// mesh (a line on a curved wall misses its flat facets by their sag; of a shell, it lies on the
/// mid-surface).
void check_wrinkle_line(const Case& c, const Mesh& mesh, const WrinkleLine& line) {
  const std::string what = "output.wrinkles.lines '" + line.name + "'";
  for (const auto& [end, place] : {std::pair{line.from, line.from_place}, {line.to, line.to_place}})
    if (!(end.cwiseAbs().maxCoeff() <= kMaxCoordinate))
      throw InputError(place, what + ": the point " + schema::format_vector(end) +
                                  " lies beyond ±" + format_number(kMaxCoordinate) +
                                  " mm, far off the body: give a line in the body");
  const LineGauge gauge(mesh, line.from, line.to, line.points);
  const double allowed = 0.5 * *c.mesh.wall_thickness();
  const LineGauge::Outside& out = gauge.outside();
  if (out.distance > allowed)
    throw InputError(line.place, what + ": its point " + std::to_string(out.index + 1) + " of " +
                                     std::to_string(line.points) + ", " +
                                     schema::format_vector(out.point) + ", is " +
                                     format_number(out.distance) +
                                     " mm from the body, more than half the wall thickness (" +
                                     format_number(allowed) + " mm): give a line " +
                                     (mesh.is_shell() ? "on the mid-surface" : "inside the body") +
                                     " of the undeformed body");
}

}  // namespace

std::vector<int> region_elements(const Region& region, const Mesh& mesh) {
  const bool shell = mesh.is_shell();
  if (!region.box) {
    const std::string& name = shell ? region.surface : region.volume;
    const auto& tags = shell ? mesh.surface_tags : mesh.volume_tags;
    const auto tag = tags.find(name);
    if (name.empty() || tag == tags.end()) return {};
    std::vector<int> elements = tag->second;
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    return elements;
  }
  // Named, not bound with `auto [lower, upper]`: clang before 16 cannot capture a structured
  // binding.
  const Vec3d& lower = (*region.box)[0];
  const Vec3d& upper = (*region.box)[1];
  // The elements (triangles or tetrahedra: arrays of corner nodes) whose centroid is in the box.
  const auto in_box = [&](const auto& corners) {
    std::vector<int> elements;
    for (std::size_t t = 0; t < corners.size(); ++t) {
      const double n = static_cast<double>(corners[t].size());
      Vec3d centroid = Vec3d::Zero();
      for (int v : corners[t]) centroid += mesh.nodes[static_cast<std::size_t>(v)] / n;
      if ((centroid.array() >= lower.array()).all() && (centroid.array() <= upper.array()).all())
        elements.push_back(static_cast<int>(t));
    }
    return elements;
  };
  return shell ? in_box(mesh.triangles) : in_box(mesh.tets);
}

namespace {

/// The case's mesh as its file holds it or its generator makes it (load_case_mesh).
Mesh read_or_generate_mesh(const Case& c) {
  namespace fs = std::filesystem;
  if (c.mesh.file) {
    const std::string& path = *c.mesh.file;
    std::error_code ec;
    const std::string note = c.directory.empty()
                                 ? std::string()
                                 : " (relative paths are read from the case file's directory)";
    if (!fs::exists(path, ec))
      throw InputError(c.mesh.file_place, "mesh file '" + path + "' does not exist" + note);
    if (fs::is_directory(path, ec))
      throw InputError(c.mesh.file_place, "'" + path + "' is a directory, not a mesh file");
    try {
      if (c.element != ElementFamily::shell) return read_gmsh(path);
      if (!c.mesh.file_thickness)
        throw InputError(c.mesh.file_place,
                         "element: shell needs the wall thickness of the mid-surface this file "
                         "holds: give it as 'mesh.thickness' [mm]");
      Mesh mesh = read_gmsh_surface(path);
      try {
        make_shell_surface(mesh, *c.mesh.file_thickness);
      } catch (const InputError&) {
        throw;
      } catch (const Error& e) {
        throw InputError(InputPlace{path, 0, 0, c.mesh.file_place.key},
                         std::string("the mesh is not the mid-surface of a shell: ") + e.what());
      }
      return mesh;
    } catch (const InputError& e) {
      // The reader names the mesh file (the error is in it, not in the YAML); add the case key
      // that chose it.
      if (!e.place().key.empty()) throw;
      InputPlace place = e.place();
      place.key = c.mesh.file_place.key;
      throw InputError(place, e.rule());
    }
  }
  if (!c.mesh.generate) throw InputError(c.mesh.place, "no mesh file and nothing to generate");
  try {
    // The element chooses the order of a generated mesh unless `mesh.order` says otherwise (a
    // mismatch is then reported by the model builder, naming both keys' meaning).
    MeshGenerationSpec spec = *c.mesh.generate;
    if (c.element == ElementFamily::shell) return generate_shell_surface(spec);
    if (!c.mesh.option_places.count("order")) spec.order = mesh_order_of(c.element);
    return generate_mesh(spec);
  } catch (const InputError& e) {
    // The generator names the option ("mesh.thickness") but not the case file: place the error at
    // that key's line, or at `mesh:` when the option took its default.
    if (!e.place().file.empty()) throw;
    InputPlace place = c.mesh.place;
    const std::string& key = e.place().key;
    const std::string prefix = "mesh.";
    const std::string option = key.rfind(prefix, 0) == 0 ? key.substr(prefix.size()) : key;
    if (const auto it = c.mesh.option_places.find(option); it != c.mesh.option_places.end())
      place = it->second;
    place.key = key.empty() ? c.mesh.place.key : prefix + option;
    throw InputError(place, e.rule());
  } catch (const SolverError&) {
    throw;
  } catch (const Error& e) {
    // The generators are deterministic functions of the options: when one fails on options that
    // passed validate_mesh_spec (a shell of radius 1e-300 mm, 64 layers in a 1e-12 mm wall), the
    // options are what cannot be meshed. This was exit status 1, an "internal" error.
    throw InputError(c.mesh.place,
                     std::string("cannot generate this mesh from these options: ") + e.what());
  }
}

}  // namespace

Mesh load_case_mesh(const Case& c) {
  Mesh mesh = read_or_generate_mesh(c);
  // A shell region's own thickness (check_regions checks the regions against this mesh).
  if (mesh.is_shell())
    for (const Region& r : c.regions)
      if (r.thickness) set_shell_thickness(mesh, region_elements(r, mesh), *r.thickness);
  return mesh;
}

void check_case_against_mesh(const Case& c, const Mesh& mesh) {
  check_element_family(c, mesh);
  check_regions(c, mesh);
  const TermMeshCheck terms{mesh, [&](const SurfaceRef& ref) { check_surface(c, mesh, ref); },
                            [&](const SurfaceRef& ref) { check_condition(c, mesh, ref); }};
  for (const TermSection& section : term_sections())
    for (const TermEntry* entry : c.terms_in(section.key)) entry->kind->check_mesh(*entry, terms);
  for (const Probe& probe : c.probes) check_probe(c, mesh, probe);
  check_wall_thickness(c);
  if (c.output.wrinkles.enabled()) {
    const WrinkleSettings& w = c.output.wrinkles;
    check_surface(c, mesh, {w.surface, w.surface_place.line > 0 ? w.surface_place : w.place});
    for (const WrinkleLine& line : w.lines) check_wrinkle_line(c, mesh, line);
  }

  const MeshReport report = check_mesh(mesh);
  if (!report.ok()) {
    const InputPlace place =
        c.mesh.file ? InputPlace{*c.mesh.file, 0, 0, c.mesh.file_place.key} : c.mesh.place;
    const std::size_t shown = std::min<std::size_t>(report.errors.size(), 5);
    std::string rule = (c.mesh.file ? "the mesh" : mesh_name(c)) + " fails its check: ";
    for (std::size_t i = 0; i < shown; ++i) rule += (i ? "; " : "") + report.errors[i];
    if (report.errors.size() > shown)
      rule += "; and " + std::to_string(report.errors.size() - shown) + " more";
    throw InputError(place, rule);
  }
}

}  // namespace plisse
