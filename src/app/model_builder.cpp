#include "app/model_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "app/wrinkling.hpp"
#include "mesh/bounding_box.hpp"
#include "mesh/topology.hpp"
#include "physics/body_force.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/cap_settings.hpp"
#include "physics/cavity.hpp"
#include "physics/dead_load.hpp"
#include "physics/die_contact.hpp"
#include "physics/die_contact_settings.hpp"
#include "physics/die_geometry.hpp"
#include "physics/die_surface.hpp"
#include "physics/follower_traction.hpp"
#include "physics/pressure_load.hpp"
#include "physics/rigid_cap.hpp"
#include "physics/rigid_motion.hpp"
#include "physics/surface.hpp"
#include "physics/surface_contact.hpp"
#include "physics/viscous_damping.hpp"

namespace plisse::app {
namespace {

/// The contact surface of a die without `surface:`: the whole boundary except the faces on the
/// case's symmetry planes, which are cuts through the body whose area would inflate the tributary
/// area of the nodes on the cut (docs/theory/contact.md, D5).
std::vector<std::array<int, 3>> default_die_candidates(const Case& c, const Mesh& mesh) {
  // A shell's symmetry sides are edges, which cut no triangle: every triangle is a candidate.
  if (mesh.is_shell()) return mesh.triangles;
  std::set<std::array<int, 3>> cut;
  for (const std::string& surface : mirror_surfaces(c.terms)) {
    for (int t : mesh.surface_tags.at(surface)) {
      auto key = mesh.triangles[t];
      std::sort(key.begin(), key.end());
      cut.insert(key);
    }
  }
  std::vector<std::array<int, 3>> out;
  for (const auto& face : boundary_faces(mesh))
    if (!cut.count(face)) out.push_back(face);
  return out;
}

/// InputError (key `boundary`) when `constraints` prescribe every displacement of `mesh`, so
/// that nothing is left to solve.
void check_free_displacements(const Case& c, const Mesh& mesh,
                              const std::vector<ConstrainedComponent>& constraints) {
  // One entry per constrained (node, component); pressures do not count.
  const auto displacements =
      std::count_if(constraints.begin(), constraints.end(),
                    [](const ConstrainedComponent& cc) { return cc.component < 3; });
  if (static_cast<std::size_t>(displacements) >= 3 * static_cast<std::size_t>(mesh.n_nodes()))
    throw InputError({c.path, 0, 0, "boundary"},
                     "every displacement is prescribed by the boundary conditions: nothing to "
                     "solve");
}

/// The density of every element [tonne/mm^3], as consistent_nodal_volumes weighs them: of each
/// tetrahedron, or each triangle of a shell, its material's, 0 in a rigid region (its weight rests
/// on whatever moves it).
std::vector<double> element_densities(const Case& c, const Mesh& mesh) {
  std::vector<double> density(mesh.is_shell() ? mesh.triangles.size() : mesh.tets.size(),
                              c.material.density);
  for (const Region& r : c.regions)
    for (int t : region_elements(r, mesh))
      density[static_cast<std::size_t>(t)] = r.material ? r.material->density : 0.0;
  return density;
}

/// The surface frame of a generated shell of revolution at X: meridian, hoop and normal, unit and
/// right-handed, about the axis y (spherical shell, airbag) or x (tube) through the origin. The
/// normal is the gradient of the mid-surface's equation at X: X/|X| on the sphere, the direction
/// away from the axis on the tube, (x/a², y/b², z/a²) on the airbag's spheroid of equatorial
/// radius a and half-height b. On the axis itself the hoop is undefined: the poles then take x as
/// the hoop.
Mat3d shell_frame(const MeshGenerationSpec& shell, const Vec3d& X) {
  const Vec3d axis = shell.kind == "tube" ? Vec3d::UnitX() : Vec3d::UnitY();
  Vec3d normal = X;
  if (shell.kind == "tube") normal = X - X.dot(axis) * axis;
  if (shell.kind == "airbag") {
    const double a2 = shell.radius * shell.radius, b2 = 0.25 * shell.height * shell.height;
    normal = Vec3d(X.x() / a2, X.y() / b2, X.z() / a2);
  }
  normal.normalize();
  Vec3d hoop = axis.cross(normal);
  hoop = hoop.norm() > 1e-12 ? hoop.normalized() : Vec3d::UnitX();
  Mat3d frame;
  frame.col(0) = hoop.cross(normal).normalized();  // meridian
  frame.col(1) = hoop;
  frame.col(2) = frame.col(0).cross(hoop);  // the normal, made orthogonal to the hoop
  return frame;
}

/// `fibre_frame: shell`: every element of material `index` (a fibre-reinforced model whose
/// section is `section`) gets its own copy with the fibre directions turned from the shell's
/// (meridian, hoop, normal) frame at its centroid into x, y, z. Only generated spherical shells,
/// airbags and tubes have that frame: anything else is an InputError at the key.
void orient_fibres_on_the_shell(const Case& c, const MaterialSection& section, int index,
                                const Mesh& mesh, ElementMaterials& m) {
  const std::string kind = c.mesh.generate ? c.mesh.generate->kind : std::string("a mesh file");
  if (kind != "spherical-shell" && kind != "tube" && kind != "airbag")
    throw InputError(section.fibre_frame_place,
                     "fibre_frame: shell needs a generated spherical-shell, airbag or tube mesh, "
                     "whose meridians and hoops plisse knows (this mesh: " +
                         kind + "); give the directions in x, y, z with fibre_frame: global");
  const FibreReinforced base = std::get<FibreReinforced>(m.materials[std::size_t(index)]);
  const double bulk = m.inverse_bulk_moduli[std::size_t(index)];
  const InelasticLaw law = m.laws[std::size_t(index)];
  if (m.of_element.empty()) m.of_element.assign(mesh.tets.size(), 0);
  const Vec3d a1(base.a1_x, base.a1_y, base.a1_z), a2(base.a2_x, base.a2_y, base.a2_z);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (m.of_element[t] != index) continue;
    Vec3d centroid = Vec3d::Zero();
    for (int v : mesh.tets[t]) centroid += mesh.nodes[std::size_t(v)] / 4.0;
    const Mat3d frame = shell_frame(*c.mesh.generate, centroid);
    FibreReinforced oriented = base;
    const Vec3d b1 = frame * a1, b2 = frame * a2;
    oriented.a1_x = b1.x(), oriented.a1_y = b1.y(), oriented.a1_z = b1.z();
    oriented.a2_x = b2.x(), oriented.a2_y = b2.y(), oriented.a2_z = b2.z();
    m.of_element[t] = static_cast<int>(m.materials.size());
    m.materials.push_back(oriented);
    m.inverse_bulk_moduli.push_back(bulk);
    m.laws.push_back(law);
  }
}

/// The material of every element: the case's `material` for the elements (tetrahedra, or a shell's
/// triangles) in no region, each deformable region's own, ElementMaterials::kRigid for a rigid
/// region's (check_case_against_mesh has checked the tags and that no element is in two regions).
/// With `region_pressure: discontinuous` a solid's tetrahedra also name their region for the
/// pressure: 0 in no region, k + 1 in regions[k], -1 rigid.
ElementMaterials element_materials(const Case& c, const Mesh& mesh) {
  ElementMaterials m = ElementMaterials::uniform(make_material(c.material.model, c.material.params),
                                                 c.material.inverse_bulk_modulus());
  std::vector<const MaterialSection*> sections = {&c.material};  // by material index
  if (!c.regions.empty())
    m.of_element.assign(mesh.is_shell() ? mesh.triangles.size() : mesh.tets.size(), 0);
  const bool own_pressures =
      !c.regions.empty() && !mesh.is_shell() && c.region_pressure == RegionPressure::discontinuous;
  if (own_pressures) m.pressure_region.assign(mesh.tets.size(), 0);
  for (std::size_t k = 0; k < c.regions.size(); ++k) {
    const Region& r = c.regions[k];
    int index = ElementMaterials::kRigid;
    if (r.material) {
      index = static_cast<int>(m.materials.size());
      m.materials.push_back(make_material(r.material->model, r.material->params));
      m.inverse_bulk_moduli.push_back(r.material->inverse_bulk_modulus());
      sections.push_back(&*r.material);
    }
    for (int t : region_elements(r, mesh)) {
      m.of_element[static_cast<std::size_t>(t)] = index;
      if (own_pressures)
        m.pressure_region[static_cast<std::size_t>(t)] = r.rigid ? -1 : static_cast<int>(k) + 1;
    }
  }
  for (const MaterialSection* section : sections) m.laws.push_back(section->inelastic());
  for (std::size_t k = 0; k < sections.size(); ++k)
    if (sections[k]->shell_fibre_frame)
      orient_fibres_on_the_shell(c, *sections[k], static_cast<int>(k), mesh, m);
  return m;
}

/// Adds the rigid regions' constraints to `constraints`: every node of their tetrahedra (of a
/// shell, triangles) follows the region's translation, and a corner node that no deformable
/// tetrahedron touches has its pressure held at 0 (no element gives it an equation). A node that a
/// boundary condition or another rigid region moves otherwise is an InputError at the region.
void add_rigid_constraints(const Case& c, const Mesh& mesh, const ElementMaterials& materials,
                           std::vector<ConstrainedComponent>& constraints) {
  if (std::none_of(c.regions.begin(), c.regions.end(), [](const Region& r) { return r.rigid; }))
    return;
  std::map<std::pair<int, int>, std::size_t> existing;  // (node, component) -> constraint
  for (std::size_t k = 0; k < constraints.size(); ++k)
    existing[{constraints[k].node, constraints[k].component}] = k;
  const auto same_motion = [&](const ConstrainedComponent& a, const ConstrainedComponent& b) {
    std::vector<double> times = {0.0,        c.solver.end_time, a.ramp.start,
                                 a.ramp.end, b.ramp.start,      b.ramp.end};
    for (const auto& point : a.ramp.table) times.push_back(point[0]);
    for (const auto& point : b.ramp.table) times.push_back(point[0]);
    return std::all_of(times.begin(), times.end(), [&](double t) {
      return std::abs(a.at(t) - b.at(t)) <= 1e-12 * (1.0 + std::abs(a.value) + std::abs(b.value));
    });
  };
  std::vector<char> deformable(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    if (!materials.rigid(static_cast<int>(t)))
      for (int v : mesh.tets[t]) deformable[static_cast<std::size_t>(v)] = 1;
  const char* axes = "xyz";
  for (const Region& r : c.regions) {
    if (!r.rigid) continue;
    const std::vector<int> elements = region_elements(r, mesh);
    for (int v : nodes_of_elements(mesh, elements)) {
      for (int k = 0; k < 3; ++k) {
        const ConstrainedComponent cc{v, k, r.displacement[k], r.ramp};
        const auto [it, added] = existing.try_emplace({v, k}, constraints.size());
        if (added) {
          constraints.push_back(cc);
        } else if (!same_motion(constraints[it->second], cc)) {
          const Vec3d& x = mesh.nodes[static_cast<std::size_t>(v)];
          char at[96];
          std::snprintf(at, sizeof at, "[%.6g, %.6g, %.6g]", x[0], x[1], x[2]);
          throw InputError(r.place, "node " + std::to_string(v) + " at " + at +
                                        " of rigid region '" + r.label() +
                                        "' is also moved otherwise along " + axes[k] +
                                        " (a boundary condition or another rigid region): a "
                                        "rigid region's nodes follow its own displacement only");
        }
      }
    }
    if (mesh.is_shell()) continue;  // a shell has no pressure unknowns: the model holds them all
    for (int t : elements)
      for (int v : mesh.tets[static_cast<std::size_t>(t)])
        if (!deformable[static_cast<std::size_t>(v)]) {
          deformable[static_cast<std::size_t>(v)] = 1;  // once
          constraints.push_back({v, 3, 0.0, Ramp{}});
        }
  }
}

}  // namespace

void check_rigid_pieces(const Case& c, const Mesh& mesh, const ModelParts& parts) {
  // Surface contacts can hold one piece against another, and viscosity (solver.viscosity) makes
  // a free one solvable: then the pieces are not judged.
  if (!c.terms_in("contacts").empty() || c.solver.viscosity > 0.0) return;
  // The supports at the first step's end: the dies that touch the body by then, the caps.
  const double t1 = c.solver.end_time / c.solver.steps;
  std::vector<RigidHold> holds;
  for (const auto& term : parts.terms) {
    std::vector<RigidHold> more = term->rigid_holds(t1);
    holds.insert(holds.end(), std::make_move_iterator(more.begin()),
                 std::make_move_iterator(more.end()));
  }
  const std::vector<FreePiece> free = free_rigid_motions(mesh, parts.constraints, holds);
  if (free.empty()) return;
  const FreePiece& piece = free.front();
  const std::string head = piece_text(piece, mesh);
  if (piece.motions.size() == 6)
    throw InputError({c.path, 0, 0, "boundary"},
                     head +
                         " is held by no boundary condition, die or cap: it can move as a rigid "
                         "body, so the tangent is singular; fix or prescribe some of its "
                         "displacements, or add solver.viscosity");
  std::string ways;
  for (std::size_t k = 0; k < piece.motions.size(); ++k)
    ways += (k == 0                          ? ""
             : k + 1 == piece.motions.size() ? " and "
                                             : ", ") +
            piece.motions[k].describe();
  char when[64];
  std::snprintf(when, sizeof when, "%g", t1);
  throw InputError(
      {c.path, 0, 0, "boundary"},
      head + " " + free_motion_text(ways, mesh, piece.nodes.front()) + ": nothing holds " +
          (piece.motions.size() > 1 ? "these" : "this") +
          ", so the tangent is singular. Hold it by a boundary condition (a symmetry plane "
          "holds only the motion across it), a cap, or a die that touches the body by the first "
          "step's end (t = " +
          when + "); or add solver.viscosity");
}

namespace {

/// The case's caps with the nodes each ties (TermContext::caps).
std::vector<CapNodes> case_caps(const Case& c, const Mesh& mesh) {
  std::vector<CapNodes> caps;
  for (const TermEntry* entry : c.terms_in("caps")) {
    const Cap& cap = entry->as<Cap>();
    caps.push_back({cap.name, condition_nodes(mesh, cap.surface)});
  }
  return caps;
}

}  // namespace

std::set<int> nodes_of_elements(const Mesh& mesh, const std::vector<int>& elements) {
  return mesh.is_shell() ? triangle_nodes(mesh, elements) : tet_nodes(mesh, elements);
}

ModelParts build_model_parts(const Case& c, const Mesh& mesh) {
  ModelParts parts{element_materials(c, mesh), collect_constraints(c.terms, mesh), {}, c.element};
  add_rigid_constraints(c, mesh, parts.materials, parts.constraints);
  check_free_displacements(c, mesh, parts.constraints);
  const auto& constraints = parts.constraints;
  const int mirrors = mirror_planes(mirror_surfaces(c.terms), mesh);
  const TermContext context{
      mesh, constraints, mirrors,
      // The contact penalties' default scale (contact.md, D11): the case's `material`.
      [&parts] { return shear_modulus(parts.materials.materials.front()); },
      [&] { return element_densities(c, mesh); }, [&] { return default_die_candidates(c, mesh); },
      [&] { return case_caps(c, mesh); }, imperfection_amplitude(c)};
  auto& terms = parts.terms;
  for (const TermSection& section : term_sections())
    for (const TermEntry* entry : c.terms_in(section.key))
      if (entry->kind->make) terms.push_back(entry->kind->make(*entry, context));
  if (c.solver.viscosity > 0.0) {
    // ℓ of docs/theory/viscous.md (Z1): the wall thickness (generated shell, airbag or sheet, or
    // `mesh.thickness` of a file mesh), else the mean edge length of the mesh.
    const double length = c.mesh.wall_thickness().value_or(mean_edge_length(mesh));
    terms.push_back(
        std::make_unique<ViscousDamping>(mesh, c.solver.viscosity, length, constraints));
  }
  return parts;
}

std::unique_ptr<MixedModel> make_model(const Mesh& mesh, ModelParts parts) {
  return std::make_unique<MixedModel>(mesh, std::move(parts.materials),
                                      std::move(parts.constraints), std::move(parts.terms),
                                      parts.element);
}

std::vector<InputError> setup_warnings(const Case& c, const Mesh* mesh) {
  std::vector<InputError> out;
  // A pressure on a surface whose rim a cap ties, without that cap in its `caps`: the cap gets no
  // end thrust (cavities.md, C14), which is a mistake unless the case loads the cap otherwise.
  const std::vector<CapNodes> caps = mesh ? case_caps(c, *mesh) : std::vector<CapNodes>{};
  // A traction or follower traction on a face the cap ties all of: the case loads the cap itself
  // (the air-beam validation case's hand-computed end thrusts).
  const auto loaded_otherwise = [&](const CapNodes& cap) {
    for (const TermEntry* entry : c.terms_in("loads")) {
      const SurfaceRef* surface = nullptr;
      if (entry->kind->word == "follower-traction")
        surface = &entry->as<FollowerTractionSettings>().surface;
      else if (entry->kind->word == "traction")
        surface = &entry->as<TractionLoadSettings>().surface;
      if (!surface) continue;
      const std::set<int> nodes = condition_nodes(*mesh, *surface);
      if (!nodes.empty() &&
          std::includes(cap.nodes.begin(), cap.nodes.end(), nodes.begin(), nodes.end()))
        return true;
    }
    return false;
  };
  for (const TermEntry* entry : c.terms_in("loads")) {
    if (caps.empty() || entry->kind->word != "pressure") continue;
    const auto& load = entry->as<PressureLoadSettings>();
    std::vector<SurfaceFace> faces;
    try {
      faces = outward_faces(*mesh, load.surface.name);
    } catch (const Error&) {
      continue;  // the model's build reports it
    }
    for (const CapNodes& cap : caps) {
      if (std::find(load.caps.begin(), load.caps.end(), cap.name) != load.caps.end() ||
          close_over_caps(*mesh, faces, {cap}).caps.empty() || loaded_otherwise(cap))
        continue;
      const InputPlace& at = entry->place;
      out.emplace_back(InputPlace{at.file, at.line, at.column, at.key + ".caps"},
                       "pressure load '" + load.name + "': cap '" + cap.name +
                           "' ties a rim of surface '" + load.surface.name +
                           "' but is not in the load's `caps`, so the pressure does not push on "
                           "that cap (no end thrust); add it to `caps` to close the surface over "
                           "it, unless the case loads the cap otherwise (a follower traction on "
                           "its face)");
    }
  }
  const double end = c.solver.end_time;
  const auto number = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return std::string(text);
  };
  const auto check = [&](const Ramp& ramp, const InputPlace& entry, const std::string& what) {
    const InputPlace place{entry.file, entry.line, entry.column, entry.key + ".ramp"};
    if (ramp.start >= end && ramp.factor(0.0) == 0.0)
      out.emplace_back(place, what + " starts at " + number(ramp.start) +
                                  " s, not before solver.end_time (" + number(end) +
                                  " s): it is never applied");
    else if (ramp.end > end)
      out.emplace_back(place, what + " ends at " + number(ramp.end) +
                                  " s, after solver.end_time (" + number(end) +
                                  " s): the run ends at " + number(100.0 * ramp.factor(end)) +
                                  " % of it");
  };
  for (const TermSection& section : term_sections())
    for (const TermEntry* entry : c.terms_in(section.key))
      for (const RampUse& use : entry->kind->ramps(*entry)) check(use.ramp, entry->place, use.what);
  // A rigid region that moves has a ramp too.
  for (const Region& r : c.regions)
    if (!r.material && !r.displacement.isZero(0.0))
      check(r.ramp, r.place, "the motion of region " + r.label());
  // A load far above the stiffness of the stiffest material: most often a value in other units
  // than the material's (a pressure in Pa in a case in MPa runs for hours, cutting its steps).
  double modulus = 3.0 * shear_modulus(make_material(c.material.model, c.material.params));
  for (const Region& r : c.regions)
    if (r.material)
      modulus = std::max(modulus,
                         3.0 * shear_modulus(make_material(r.material->model, r.material->params)));
  const auto stress = [&](double value, const InputPlace& item, const std::string& key,
                          const std::string& what) {
    if (!(modulus > 0.0) || !(std::abs(value) > kUnitsWarningFactor * modulus)) return;
    out.emplace_back(
        InputPlace{item.file, item.line, item.column, item.key + "." + key},
        what + " " + number(value) + " is " + number(std::abs(value) / modulus) +
            " times the material's small-strain Young's modulus " + number(modulus) +
            " (3 times its shear modulus), which crushes the body at once; plisse computes in "
            "the case's own consistent units (the docs use mm, N, MPa): check that the load and "
            "the material are in the same ones (a pressure in Pa where the material is in MPa "
            "is 10^6 times too large)");
  };
  for (const TermEntry* entry : c.terms_in("loads")) {
    const std::string& word = entry->kind->word;
    if (word == "pressure") {
      const auto& load = entry->as<PressureLoadSettings>();
      stress(load.value, entry->place, "value", "pressure load '" + load.name + "': its value");
    } else if (word == "traction") {
      const auto& load = entry->as<TractionLoadSettings>();
      if (load.traction)
        stress(load.traction->norm(), entry->place, "traction",
               "traction load '" + load.name + "': its traction's magnitude");
    } else if (word == "follower-traction") {
      const auto& load = entry->as<FollowerTractionSettings>();
      stress(std::hypot(load.normal, load.shear), entry->place, "normal",
             "follower traction '" + load.name + "': its magnitude");
    }
  }
  for (const TermEntry* entry : c.terms_in("cavities")) {
    const auto& cavity = entry->as<Cavity>();
    if (cavity.control == CavityControl::gas)
      stress(cavity.initial_pressure, entry->place, "initial_pressure",
             "cavity '" + cavity.name + "': its initial gauge pressure");
  }
  if (mesh && !mesh->nodes.empty()) {
    // A prescribed motion or a die far smaller than the body: most often a length in other
    // units than the mesh's (metres typed into a case meshed in millimetres).
    const BoundingBox box = bounding_box(mesh->nodes);
    const double size = (box.high - box.low).norm();
    const auto length = [&](double value, const InputPlace& item, const std::string& key,
                            const std::string& what) {
      if (value == 0.0 || !(std::abs(value) < kUnitsLengthFactor * size)) return;
      out.emplace_back(
          InputPlace{item.file, item.line, item.column, item.key + "." + key},
          what + " " + number(std::abs(value)) + " is " + number(std::abs(value) / size) +
              " of the mesh's size (the diagonal of its bounding box, " + number(size) +
              "); plisse computes in the case's own consistent units: check that the case's "
              "lengths are in the mesh's (a length in metres in a case meshed in millimetres is "
              "1000 times too small)");
    };
    const auto largest = [](const std::array<std::optional<double>, 3>& components) {
      double value = 0.0;
      for (const std::optional<double>& component : components)
        if (component) value = std::max(value, std::abs(*component));
      return value;
    };
    for (const TermEntry* entry : c.terms_in("boundary"))
      if (entry->kind->word == "displacement") {
        const auto& condition = entry->as<DisplacementConditionSettings>();
        length(largest(condition.value), entry->place, "value",
               "displacement condition '" + condition.name + "': its largest component");
      }
    for (const TermEntry* entry : c.terms_in("caps")) {
      const auto& cap = entry->as<Cap>();
      length(largest(cap.displacement), entry->place, "displacement",
             "cap '" + cap.name + "': its largest displacement component");
    }
    for (const TermEntry* entry : c.terms_in("dies")) {
      const auto& die = entry->as<DieSettings>();
      if (die.shape != DieShape::plane)
        length(die.radius, entry->place, "radius", "die '" + die.name + "': its radius");
      length(die.displacement.norm(), entry->place, "move.displacement",
             "die '" + die.name + "': its motion");
    }
    for (const Region& r : c.regions)
      if (!r.material)
        length(r.displacement.norm(), r.place, "displacement",
               "the motion of rigid region " + r.label());
  }
  return out;
}

std::vector<InputError> unsupported_features(const Case& c, const Mesh& mesh) {
  std::vector<InputError> out;
  if (mesh.order() != mesh_order_of(c.element)) {
    const bool generated = !c.mesh.file;
    std::string rule;
    if (c.element == ElementFamily::mini)
      rule =
          "the mesh has second-order (10-node) tetrahedra; the MINI element needs linear ones (" +
          std::string(generated ? "remove `mesh.order` or set it to 1"
                                : "set `element: taylor-hood` to run them as P2/P1") +
          ")";
    else
      rule =
          "the mesh has linear (4-node) tetrahedra; the Taylor-Hood element needs "
          "second-order (10-node) ones (" +
          std::string(generated
                          ? "remove `mesh.order` or set it to 2, or set `element: mini`"
                          : "export the mesh with order 2, e.g. gmsh -3 -order 2 or plisse mesh "
                            "... --order 2, or set `element: mini` to run it with linear "
                            "elements") +
          ")";
    const auto order = c.mesh.option_places.find("order");
    out.emplace_back(!generated                            ? c.mesh.file_place
                     : order != c.mesh.option_places.end() ? order->second
                                                           : c.mesh.place,
                     rule);
  }
  if (c.solver.scheme != Scheme::total_lagrangian)
    out.emplace_back(InputPlace{c.path, 0, 0, "solver.scheme"},
                     "only the total-lagrangian scheme is available yet");
  // The arc length runs the load parameter backwards past a limit load: a rate-dependent
  // material would see time run backwards.
  if (c.solver.control == StepControl::arc_length) {
    std::vector<const MaterialSection*> materials = {&c.material};
    for (const Region& r : c.regions)
      if (r.material) materials.push_back(&*r.material);
    for (const MaterialSection* m : materials)
      if (m->viscoelastic.n_terms() > 0) {
        out.emplace_back(m->place,
                         "a viscoelastic material cannot run with 'solver.control: arc-length': "
                         "past a limit load the arc length lowers the load factor, which is the "
                         "time its relaxation follows; use load control, or the material without "
                         "'viscoelastic'");
        break;
      }
  }
  return out;
}

}  // namespace plisse::app
