#include "mesh/generate.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/boundary_tags.hpp"
#include "mesh/box_mesh.hpp"
#include "mesh/disc_surface.hpp"
#include "mesh/layered_shell.hpp"
#include "mesh/shell_surface.hpp"
#include "mesh/spheroid_surface.hpp"
#include "mesh/tube_mesh.hpp"

namespace plisse {
namespace {

using Spec = MeshGenerationSpec;

// Aggregate initialisation (not member assignment: GCC 12 reports a false -Wrestrict on
// assigning short literals to std::string members here).
MeshOption real_option(std::string key, double Spec::*member, std::string unit, Range range,
                       std::string help) {
  return MeshOption{std::move(key), std::move(unit), std::move(help), member, nullptr, nullptr,
                    range};
}

/// A tube's stations along its axis (tube_stations), graded when end_element_size is set.
std::vector<double> tube_stations_of(const MeshGenerationSpec& spec) {
  return tube_stations(spec.length, spec.element_size, spec.end_element_size, spec.end_length);
}

/// A tube's cells along its axis, for the size estimates.
double axial_cells(const MeshGenerationSpec& spec) {
  return tube_cells_along(spec.length, spec.element_size, spec.end_element_size, spec.end_length);
}

MeshOption integer_option(std::string key, int Spec::*member, Range range, std::string help) {
  return MeshOption{std::move(key), std::string("-"), std::move(help), nullptr, member, nullptr,
                    range};
}

/// The refinement `spec` asks for (size 0: none).
PoleRefinement pole_refinement(const Spec& spec) {
  return {spec.pole_element_size, spec.pole_radius};
}

/// A disc's refinement along its rim (size 0: none), by the pole's rule.
PoleRefinement rim_refinement(const Spec& spec) { return {spec.rim_element_size, spec.rim_width}; }

/// The symmetry option of a kind that meshes the parts `kept` (of full, half, quarter, octant,
/// in that order), with its help.
MeshOption symmetry_option(std::vector<std::string> kept) {
  static const std::vector<std::pair<std::string, std::string>> parts = {
      {"full", "full"},
      {"half", "half (z >= 0)"},
      {"quarter", "quarter (x >= 0, z >= 0)"},
      {"octant", "octant (x, y, z >= 0)"}};
  std::string help = "part meshed:";
  for (const auto& [name, text] : parts)
    if (std::find(kept.begin(), kept.end(), name) != kept.end())
      help += (help.back() == ':' ? " " : " | ") + text;
  return MeshOption{"symmetry",      "-",          help,           nullptr, nullptr,
                    &Spec::symmetry, Range::any(), std::move(kept)};
}

MeshOption symmetry_option() { return symmetry_option({"full", "half", "quarter", "octant"}); }

std::string number(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

[[noreturn]] void reject(const std::string& key, const std::string& rule) {
  throw InputError(InputPlace{"", 0, 0, "mesh." + key}, rule);
}

int sheet_cells(double length, double h) {
  return std::max(1, static_cast<int>(std::lround(length / h)));
}

/// r_j (or s_j): `first + j (last - first) / layers`, exactly `last` for j = layers.
double layer_value(double first, double last, int j, int layers) {
  return j == layers ? last : first + j * (last - first) / layers;
}

}  // namespace

const std::vector<MeshKind>& mesh_kinds() {
  static const std::vector<MeshKind> kinds = [] {
    // Lengths up to a kilometre: beyond, Gmsh's geometry tolerances break down (it aborts).
    const Range size{0.0, 1e6, true, false};
    const Range layers = Range::closed(1, 64);
    const auto thickness_help = "wall thickness";
    const auto layers_help = "tetrahedra through the thickness (exactly)";
    const MeshOption order =
        integer_option("order", &Spec::order, Range::closed(1, 2),
                       "element order: 1 (4-node tetrahedra) or 2 (10-node, one node per edge); "
                       "in a case file the order of its `element` when not given");
    // The refinement about the +y pole of the shell and the airbag (PoleRefinement).
    const MeshOption pole_size = real_option(
        "pole_element_size", &Spec::pole_element_size, "mm", Range::closed(0.0, 1e6),
        "element edge within pole_radius of the +y pole, growing by a fifth of the distance "
        "beyond it up to element_size; 0: no refinement");
    const MeshOption pole_radius =
        real_option("pole_radius", &Spec::pole_radius, "mm", Range::closed(0.0, 1e6),
                    "distance from the +y pole meshed at pole_element_size");
    std::vector<MeshKind> k;
    k.push_back({"cube",
                 "cube [0, edge]^3, structured (6 tetrahedra per cell); tags left/right (x), "
                 "front/back (y), "
                 "bottom/top (z), sym_x = left, sym_y = front, sym_z = bottom",
                 {real_option("edge", &Spec::edge, "mm", size, "edge length"),
                  integer_option("divisions", &Spec::divisions, Range::closed(1, 200),
                                 "element divisions per edge"),
                  order}});
    k.push_back({"spherical-shell",
                 "hollow sphere, inner radius R, layers of prisms cut into tetrahedra; tags inner, "
                 "outer and "
                 "sym_x/sym_y/sym_z on the cut planes",
                 {real_option("inner_radius", &Spec::inner_radius, "mm", size, "inner radius R"),
                  real_option("thickness", &Spec::thickness, "mm", size, thickness_help),
                  integer_option("layers", &Spec::layers, layers, layers_help),
                  real_option("element_size", &Spec::element_size, "mm", size,
                              "target element edge on the inner surface (<= inner_radius)"),
                  pole_size, pole_radius, symmetry_option(), order}});
    k.push_back(
        {"airbag",
         "round airbag: closed oblate shell, mid-surface x^2/r^2 + (2y/height)^2 + z^2/r^2 = 1, "
         "wall "
         "centred on it; tags inner, outer and sym_x/sym_y/sym_z on the cut planes",
         {real_option("radius", &Spec::radius, "mm", size,
                      "equatorial radius of the mid-surface (x-z plane)"),
          real_option("height", &Spec::height, "mm", size,
                      "total height of the mid-surface along y (<= 2 radius)"),
          real_option("thickness", &Spec::thickness, "mm", size,
                      "wall thickness (< 2 (height/2)^2 / radius, the rim's curvature limit)"),
          integer_option("layers", &Spec::layers, layers, layers_help),
          real_option("element_size", &Spec::element_size, "mm", size,
                      "target element edge on the mid-surface (<= height/2)"),
          pole_size, pole_radius, symmetry_option(), order}});
    k.push_back(
        {"sheet",
         "flat sheet [0, length] x [0, width] x [0, thickness], structured; tags as the cube",
         {real_option("length", &Spec::length, "mm", size, "extent along x"),
          real_option("width", &Spec::width, "mm", size, "extent along y"),
          real_option("thickness", &Spec::thickness, "mm", size, "extent along z"),
          integer_option("layers", &Spec::layers, layers, layers_help),
          real_option("element_size", &Spec::element_size, "mm", size, "in-plane element size"),
          order}});
    // The tube (air beam): axis x, bent in the x-y plane, so its half is z >= 0 like the shells'.
    k.push_back(
        {"tube",
         "open tube along x from 0 to length, wall centred on the mid radius, structured; tags "
         "inner, outer, left (x = 0), right (x = length) and sym_z (half)",
         {real_option("radius", &Spec::radius, "mm", size, "mid-surface radius R"),
          real_option("length", &Spec::length, "mm", size, "length along x"),
          real_option("thickness", &Spec::thickness, "mm", size, "wall thickness (< 2 radius)"),
          integer_option("layers", &Spec::layers, layers, layers_help),
          real_option("element_size", &Spec::element_size, "mm", size,
                      "target element edge along and about the axis (<= radius)"),
          real_option("end_element_size", &Spec::end_element_size, "mm", Range::closed(0.0, 1e6),
                      "cell length along the axis at the end x = 0 (a clamp), growing linearly "
                      "to element_size over end_length; 0: uniform"),
          real_option("end_length", &Spec::end_length, "mm", Range::closed(0.0, 1e6),
                      "distance from x = 0 over which the cells grow from end_element_size to "
                      "element_size"),
          symmetry_option({"full", "half"}), order}});
    // A flat round panel (an airbag's), in the plane y = 0 with y its axis as the airbag's: the
    // mid-surface of a shell only.
    k.push_back(
        {"disc",
         "flat round panel x^2 + z^2 <= radius^2 in the plane y = 0, shell mid-surface only "
         "(element: shell), facing +y; faces inner (-1, towards -y) and outer (+1), edge tags "
         "rim and sym_x/sym_z on the cut planes",
         {real_option("radius", &Spec::radius, "mm", size, "radius of the panel"),
          real_option("thickness", &Spec::thickness, "mm", size, thickness_help),
          real_option("element_size", &Spec::element_size, "mm", size,
                      "target element edge (<= radius)"),
          real_option("rim_element_size", &Spec::rim_element_size, "mm", Range::closed(0.0, 1e6),
                      "element edge within rim_width of the rim, growing by a fifth of the "
                      "distance beyond it up to element_size; 0: no refinement"),
          real_option("rim_width", &Spec::rim_width, "mm", Range::closed(0.0, 1e6),
                      "distance from the rim meshed at rim_element_size"),
          symmetry_option({"full", "half", "quarter"})}});
    return k;
  }();
  return kinds;
}

const MeshKind* find_mesh_kind(const std::string& name) {
  for (const auto& kind : mesh_kinds())
    if (kind.name == name) return &kind;
  return nullptr;
}

std::optional<Symmetry> parse_symmetry(const std::string& text) {
  if (text == "full") return Symmetry::full;
  if (text == "half") return Symmetry::half;
  if (text == "quarter") return Symmetry::quarter;
  if (text == "octant") return Symmetry::octant;
  return std::nullopt;
}

std::string to_string(Symmetry s) {
  switch (s) {
    case Symmetry::full:
      return "full";
    case Symmetry::half:
      return "half";
    case Symmetry::quarter:
      return "quarter";
    case Symmetry::octant:
      return "octant";
  }
  return "full";
}

double estimate_n_tets(const MeshGenerationSpec& spec) {
  if (spec.kind == "cube") return 6.0 * std::pow(static_cast<double>(spec.divisions), 3);
  if (spec.kind == "sheet")
    return 6.0 * std::max(1.0, std::round(spec.length / spec.element_size)) *
           std::max(1.0, std::round(spec.width / spec.element_size)) * spec.layers;
  if (spec.kind == "tube")
    return 6.0 * axial_cells(spec) *
           tube_divisions_around(spec.radius, spec.element_size, spec.symmetry == Symmetry::half) *
           spec.layers;
  if (spec.kind == "spherical-shell")
    return 3.0 * spec.layers *
           estimate_spheroid_triangles(spec.inner_radius, spec.inner_radius, spec.element_size,
                                       spec.symmetry, pole_refinement(spec));
  if (spec.kind == "airbag")
    return 3.0 * spec.layers *
           estimate_spheroid_triangles(spec.radius, std::min(spec.radius, spec.height / 2.0),
                                       spec.element_size, spec.symmetry, pole_refinement(spec));
  return 0.0;
}

double estimate_n_shell_triangles(const MeshGenerationSpec& spec) {
  if (spec.kind == "sheet")
    return 2.0 * sheet_cells(spec.length, spec.element_size) *
           sheet_cells(spec.width, spec.element_size);
  if (spec.kind == "tube")
    return 2.0 * axial_cells(spec) *
           tube_divisions_around(spec.radius, spec.element_size, spec.symmetry == Symmetry::half);
  if (spec.kind == "spherical-shell") {
    const double r = spec.inner_radius + 0.5 * spec.thickness;
    return estimate_spheroid_triangles(r, r, spec.element_size, spec.symmetry,
                                       pole_refinement(spec));
  }
  if (spec.kind == "airbag")
    return estimate_spheroid_triangles(spec.radius, std::min(spec.radius, spec.height / 2.0),
                                       spec.element_size, spec.symmetry, pole_refinement(spec));
  if (spec.kind == "disc")
    return estimate_disc_triangles(spec.radius, spec.element_size, spec.symmetry,
                                   rim_refinement(spec));
  return 0.0;
}

namespace {

/// validate_mesh_spec, or (`shell`) the rules of generate_shell_surface: no cube, `layers`
/// ignored, order 1, and the limit on triangles.
void validate_spec(const MeshGenerationSpec& spec, bool shell) {
  const MeshKind* kind = find_mesh_kind(spec.kind);
  if (kind == nullptr) {
    std::string known;
    for (const auto& k : mesh_kinds()) known += (known.empty() ? "" : ", ") + k.name;
    reject("generate", "unknown mesh kind '" + spec.kind + "' (known: " + known + ")");
  }
  if (!shell && spec.kind == "disc")
    reject("generate",
           "the disc is generated as a shell's mid-surface only: give `element: shell` (or "
           "`plisse mesh disc --element shell`); a solid panel can be read from a Gmsh file");
  if (shell && spec.kind == "cube")
    reject("generate",
           "the cube is a solid and has no mid-surface: shell meshes are generated for sheet, "
           "spherical-shell, airbag, tube and disc");
  for (const auto& option : kind->options) {
    if (shell && option.integer == &Spec::layers) continue;
    std::optional<std::string> violation;
    if (option.real) violation = option.range.violation(spec.*option.real);
    if (option.integer)
      violation = option.range.violation(static_cast<double>(spec.*option.integer));
    if (violation) reject(option.key, *violation);
  }
  if (shell && spec.order != 1)
    reject("order",
           "a shell mesh is a mid-surface of linear (3-node) triangles: order must be 1 (got " +
               std::to_string(spec.order) + ")");
  if (spec.kind == "spherical-shell" || spec.kind == "airbag") {
    if (spec.pole_element_size > spec.element_size)
      reject("pole_element_size", "must be <= element_size = " + number(spec.element_size) +
                                      " mm (got " + number(spec.pole_element_size) + ")");
    if (spec.pole_radius > 0.0 && spec.pole_element_size == 0.0)
      reject("pole_radius", "needs pole_element_size > 0 (the size within that radius)");
  }
  if (spec.kind == "disc") {
    if (spec.symmetry == Symmetry::octant)
      reject("symmetry",
             "a flat panel is meshed full, half (z >= 0) or quarter (x >= 0, z >= 0), not octant");
    if (spec.element_size > spec.radius)
      reject("element_size", "must be <= radius = " + number(spec.radius) + " mm (got " +
                                 number(spec.element_size) + ")");
    if (spec.rim_element_size > spec.element_size)
      reject("rim_element_size", "must be <= element_size = " + number(spec.element_size) +
                                     " mm (got " + number(spec.rim_element_size) + ")");
    if (spec.rim_width > 0.0 && spec.rim_element_size == 0.0)
      reject("rim_width", "needs rim_element_size > 0 (the size within that distance)");
    if (spec.rim_width > spec.radius)
      reject("rim_width", "must be <= radius = " + number(spec.radius) + " mm (got " +
                              number(spec.rim_width) + ")");
  }
  if (spec.kind == "spherical-shell" && spec.element_size > spec.inner_radius)
    reject("element_size", "must be <= inner_radius = " + number(spec.inner_radius) + " mm (got " +
                               number(spec.element_size) + ")");
  if (spec.kind == "airbag") {
    const double a = spec.radius, c = spec.height / 2.0;
    if (c > a)
      reject("height", "must be <= 2 radius = " + number(2.0 * a) +
                           " mm: the airbag is an oblate shell (got " + number(spec.height) + ")");
    // Offsetting by t/2 inwards folds the wall where t/2 reaches the smallest radius of curvature
    // of the mid-surface, c^2/a (meridian curvature at the rim of an oblate spheroid).
    const double limit = 2.0 * c * c / a;
    if (!(spec.thickness < limit))
      reject("thickness",
             "must be < 2 (height/2)^2 / radius = " + number(limit) +
                 " mm, twice the smallest radius of curvature of the mid-surface (at the rim); "
                 "a thicker wall folds over itself (got " +
                 number(spec.thickness) + ")");
    if (spec.element_size > c)
      reject("element_size",
             "must be <= height/2 = " + number(c) + " mm (got " + number(spec.element_size) + ")");
  }
  if (spec.kind == "tube") {
    if (spec.symmetry != Symmetry::full && spec.symmetry != Symmetry::half)
      reject("symmetry", "a tube is meshed full or half (z >= 0), not " + to_string(spec.symmetry));
    if (!(spec.thickness < 2.0 * spec.radius))
      reject("thickness", "must be < 2 radius = " + number(2.0 * spec.radius) + " mm (got " +
                              number(spec.thickness) + ")");
    if (spec.element_size > spec.radius)
      reject("element_size", "must be <= radius = " + number(spec.radius) + " mm (got " +
                                 number(spec.element_size) + ")");
    if (spec.end_element_size > 0.0 && !(spec.end_length > 0.0))
      reject("end_element_size",
             "needs end_length > 0 (the distance over which the cells grow "
             "to element_size)");
    if (spec.end_length > 0.0 && spec.end_element_size == 0.0)
      reject("end_length", "needs end_element_size > 0 (the cell length at x = 0)");
    if (spec.end_length > spec.length)
      reject("end_length", "must be <= length = " + number(spec.length) + " mm (got " +
                               number(spec.end_length) + ")");
  }
  if (shell) {
    const double n = estimate_n_shell_triangles(spec);
    if (n > kMaxGeneratedTriangles)
      reject("element_size", "the mid-surface would have about " + number(n) +
                                 " triangles, more than the limit of " +
                                 number(kMaxGeneratedTriangles) + "; choose a coarser mesh");
    return;
  }
  const double n = estimate_n_tets(spec);
  if (n > kMaxGeneratedTets) {
    const std::string key = spec.kind == "cube" ? "divisions" : "element_size";
    reject(key, "the mesh would have about " + number(n) + " tetrahedra, more than the limit of " +
                    number(kMaxGeneratedTets) + "; choose a coarser mesh");
  }
}

/// The mid-surface `surface` of a spheroid shell (outward triangles, mesh_spheroid_surface) or of
/// a disc (facing +y, mesh_disc_surface) cut by `symmetry`, with its tags: the faces inner (-1)
/// and outer (+1), the edges on the cut planes, and the rest of the boundary as `others` (the
/// disc's rim) when given.
Mesh faced_shell_surface(SurfaceTriangulation surface, Symmetry symmetry,
                         const std::string& others = "") {
  Mesh mesh;
  mesh.nodes = std::move(surface.nodes);
  mesh.triangles = std::move(surface.triangles);
  std::vector<int> all(mesh.triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  mesh.surface_tags["inner"] = all;
  mesh.surface_tags["outer"] = all;
  mesh.shell_face_side = {{"inner", -1}, {"outer", +1}};
  const auto planes = cut_planes(symmetry);
  std::vector<EdgePlane> edge_planes;
  for (int axis = 0; axis < 3; ++axis)
    if (planes[static_cast<std::size_t>(axis)])
      edge_planes.push_back({{std::string("sym_") + "xyz"[axis]}, axis, 0.0});
  tag_boundary_edges(mesh, edge_planes, others);
  return mesh;
}

}  // namespace

void validate_mesh_spec(const MeshGenerationSpec& spec) { validate_spec(spec, false); }

Mesh generate_mesh(const MeshGenerationSpec& spec) {
  validate_mesh_spec(spec);
  if (spec.kind == "cube")
    return make_box_mesh(Vec3d(spec.edge, spec.edge, spec.edge),
                         {spec.divisions, spec.divisions, spec.divisions}, spec.order);
  if (spec.kind == "sheet")
    return make_box_mesh(Vec3d(spec.length, spec.width, spec.thickness),
                         {sheet_cells(spec.length, spec.element_size),
                          sheet_cells(spec.width, spec.element_size), spec.layers},
                         spec.order);
  if (spec.kind == "tube")
    return make_tube_mesh(spec.radius, spec.length, spec.thickness, spec.layers, spec.element_size,
                          spec.symmetry == Symmetry::half, spec.order, tube_stations_of(spec));
  using Midpoint = std::function<Vec3d(int k1, int j1, int k2, int j2)>;
  if (spec.kind == "spherical-shell") {
    const double R = spec.inner_radius;
    const auto surface =
        mesh_spheroid_surface(R, R, spec.element_size, spec.symmetry, pole_refinement(spec));
    std::vector<Vec3d> direction;
    direction.reserve(surface.nodes.size());
    for (const auto& p : surface.nodes) direction.push_back(p / p.norm());
    auto radius = [&](int j) { return layer_value(R, R + spec.thickness, j, spec.layers); };
    // Node k of layer j at radius r_j = R + j t / layers along the k-th direction.
    const auto position = [&](int k, int j) {
      return Vec3d(radius(j) * direction[static_cast<std::size_t>(k)]);
    };
    // Edge nodes on the true spheres: radius (r_j1 + r_j2)/2 along the mean direction, so an edge
    // within one layer sphere stays on it and a through-wall edge (k1 = k2) is straight.
    Midpoint midpoint;
    if (spec.order == 2)
      midpoint = [&](int k1, int j1, int k2, int j2) {
        const auto d1 = static_cast<std::size_t>(k1), d2 = static_cast<std::size_t>(k2);
        const Vec3d d =
            k1 == k2 ? direction[d1] : Vec3d((direction[d1] + direction[d2]).normalized());
        return Vec3d(0.5 * (radius(j1) + radius(j2)) * d);
      };
    return make_layered_shell(surface, spec.layers, spec.symmetry, position, midpoint);
  }
  // airbag: mid-surface x^2/a^2 + y^2/c^2 + z^2/a^2 = 1, wall offset along the unit normal
  // n ~ (x/a^2, y/c^2, z/a^2) by o_j = -t/2 + j t / layers.
  const double a = spec.radius, c = spec.height / 2.0, t = spec.thickness;
  const auto surface =
      mesh_spheroid_surface(a, c, spec.element_size, spec.symmetry, pole_refinement(spec));
  auto unit_normal = [&](const Vec3d& p) {
    const Vec3d n(p.x() / (a * a), p.y() / (c * c), p.z() / (a * a));
    return Vec3d(n / n.norm());
  };
  std::vector<Vec3d> normal;
  normal.reserve(surface.nodes.size());
  for (const auto& p : surface.nodes) normal.push_back(unit_normal(p));
  auto offset = [&](int j) { return layer_value(-0.5 * t, 0.5 * t, j, spec.layers); };
  const auto position = [&](int k, int j) {
    const auto i = static_cast<std::size_t>(k);
    return Vec3d(surface.nodes[i] + offset(j) * normal[i]);
  };
  // Edge nodes on the true offset surfaces: the chord's midpoint projected onto the mid-surface
  // by the radial scaling of mesh_spheroid_surface, offset by the mean of the two layer offsets
  // along the normal there.
  Midpoint midpoint;
  if (spec.order == 2)
    midpoint = [&](int k1, int j1, int k2, int j2) {
      const double o = 0.5 * (offset(j1) + offset(j2));
      const auto i1 = static_cast<std::size_t>(k1), i2 = static_cast<std::size_t>(k2);
      if (k1 == k2) return Vec3d(surface.nodes[i1] + o * normal[i1]);
      const Vec3d p = 0.5 * (surface.nodes[i1] + surface.nodes[i2]);
      const Vec3d m = p / std::sqrt(p.x() * p.x() / (a * a) + p.y() * p.y() / (c * c) +
                                    p.z() * p.z() / (a * a));
      return Vec3d(m + o * unit_normal(m));
    };
  return make_layered_shell(surface, spec.layers, spec.symmetry, position, midpoint);
}

Mesh generate_shell_surface(const MeshGenerationSpec& spec) {
  validate_spec(spec, true);
  Mesh mesh;
  if (spec.kind == "sheet") {
    mesh = make_rectangle_surface(
        spec.length, spec.width, 0.5 * spec.thickness,
        {sheet_cells(spec.length, spec.element_size), sheet_cells(spec.width, spec.element_size)});
  } else if (spec.kind == "disc") {
    mesh = faced_shell_surface(
        mesh_disc_surface(spec.radius, spec.element_size, spec.symmetry, rim_refinement(spec)),
        spec.symmetry, "rim");
  } else if (spec.kind == "tube") {
    mesh = make_tube_surface(spec.radius, spec.length, spec.element_size,
                             spec.symmetry == Symmetry::half, tube_stations_of(spec));
  } else {
    // The sphere of the wall's mid radius, or the airbag's mid-surface (generate_mesh).
    const bool sphere = spec.kind == "spherical-shell";
    const double a = sphere ? spec.inner_radius + 0.5 * spec.thickness : spec.radius;
    const double c = sphere ? a : spec.height / 2.0;
    mesh = faced_shell_surface(
        mesh_spheroid_surface(a, c, spec.element_size, spec.symmetry, pole_refinement(spec)),
        spec.symmetry);
  }
  make_shell_surface(mesh, spec.thickness);
  return mesh;
}

}  // namespace plisse
