#pragma once
/// Keys that many sections of the case file share: surface tags, names, time ramps, vectors and
/// components with free (`~`) entries. The term kinds (this folder) and the case reader
/// (case/case.cpp) declare their rows with them, so a key common to several sections reads and
/// reads out the same everywhere.
#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/dead_load.hpp"
#include "physics/dirichlet.hpp"
#include "physics/ramp.hpp"
#include "schema/field.hpp"
#include "schema/table.hpp"
#include "terms/term_kind.hpp"

namespace plisse::term_keys {

using schema::Field;
using schema::FieldMap;
using schema::ReadContext;
using schema::Schema;

/// A surface tag name (not empty) and where it is written.
SurfaceRef surface_ref(const Field& f);

/// A vector that is not zero (a load of zero is a mistake, not a way to switch it off).
Vec3d non_zero_vector(const Field& f);

/// A direction, normalised; the zero vector is an error.
Vec3d unit_vector(const Field& f);

/// `ramp: [start, end]` [s] with 0 <= start < end, or a load curve `[[t, factor], ...]`: at least
/// two points, t >= 0 strictly increasing, finite factors.
Ramp read_ramp(const Field& f);

/// A list of three numbers, `~` for a free (absent) component; `what` names them in the error.
std::array<std::optional<double>, 3> optional_components(const Field& f, const std::string& what);

/// A surface tag of the mesh, with where it is named.
template <class S>
typename Schema<S>::Row& surface_key(Schema<S>& schema, std::string key,
                                     std::type_identity_t<SurfaceRef S::*> member,
                                     std::string help) {
  return schema.add({std::move(key), "surface tag", "–", "", "", {}, std::move(help)},
                    [member](const Field& f, S& s, ReadContext&) { s.*member = surface_ref(f); });
}

/// An optional surface tag of the mesh.
template <class S>
typename Schema<S>::Row& optional_surface_key(
    Schema<S>& schema, std::string key, std::type_identity_t<std::optional<SurfaceRef> S::*> member,
    std::string fallback, std::string help) {
  return schema.add(
      {std::move(key), "surface tag", "–", "", std::move(fallback), {}, std::move(help)},
      [member](const Field& f, S& s, ReadContext&) { s.*member = surface_ref(f); });
}

/// The entry's name, unique across conditions, loads, cavities, dies and probes.
template <class S>
typename Schema<S>::Row& name_key(Schema<S>& schema, std::type_identity_t<std::string S::*> member,
                                  std::string help) {
  return schema.add(
      {"name", "name", "–", "", "none", {}, std::move(help)},
      [member](const Field& f, S& s, ReadContext& context) { s.*member = context.unique_name(f); });
}

/// What every `ramp` key's help adds about load curves.
extern const std::string load_curve_help;

/// A time ramp; default [0, solver.end_time].
template <class S>
typename Schema<S>::Row& ramp_key(Schema<S>& schema, std::type_identity_t<Ramp S::*> member,
                                  std::string help) {
  return schema
      .add({"ramp",
            "[start, end] or [[t, factor], ...]",
            "s",
            "0 <= start < end; t increasing",
            "[0, end_time]",
            {},
            std::move(help) + load_curve_help},
           [member](const Field& f, S& s, ReadContext&) { s.*member = read_ramp(f); })
      .when_absent([member](const FieldMap&, S& s, ReadContext& context) {
        s.*member = {0.0, context.end_time};
      });
}

/// The `name` of a `loads:` entry: the same row in every kind of load.
template <class S>
typename Schema<S>::Row& load_name_key(Schema<S>& schema,
                                       std::type_identity_t<std::string S::*> member) {
  return name_key(schema, member,
                  "history column `pressure:<name>` (pressure), and on a closed or "
                  "symmetry-closed surface `volume:<name>` and `full_volume:<name>` (the enclosed "
                  "volume); `load_x:<name>`, `load_y:<name>`, `load_z:<name>` (the applied force) "
                  "and `work:<name>` (its work) for the others (docs/output.md)")
      .required();
}

/// The `ramp` of a `loads:` entry: the same row in every kind of load.
template <class S>
typename Schema<S>::Row& load_ramp_key(Schema<S>& schema, std::type_identity_t<Ramp S::*> member) {
  return ramp_key(schema, member, "time ramp of the load");
}

/// The ramp of a `loads:` entry, which `plisse check` compares with solver.end_time.
template <class S>
std::vector<RampUse> load_ramps(const S& load) {
  return {{load.ramp, "load '" + load.name + "'"}};
}

/// The `name` and `surface` of a `boundary:` condition: the same rows in every kind.
template <class S>
void condition_keys(Schema<S>& schema, std::type_identity_t<std::string S::*> name,
                    std::type_identity_t<SurfaceRef S::*> surface) {
  name_key(schema, name,
           "when given, the reaction force on the surface is reported as `force_x:<name>`, "
           "`force_y:<name>`, `force_z:<name>`");
  surface_key(schema, "surface", surface,
              "where the condition acts; with `element: shell` an edge tag of the mid-surface, or "
              "a surface tag (all its nodes)")
      .required();
}

/// A dead load whose every non-zero nodal force component acts on a component the boundary
/// conditions prescribe (`constraints`) does no work: the supports take it, while the history
/// would report it as applied. Throws InputError at `place`, naming `what` ("point-force 'f'"),
/// the first node and the held components; a load that moves at least one free component passes.
void refuse_load_on_held_nodes(const std::vector<NodalForce>& forces,
                               const std::vector<ConstrainedComponent>& constraints,
                               const Mesh& mesh, const InputPlace& place, const std::string& what);

/// The history columns of a named condition's reaction; `whole`: also the whole body's, for a
/// condition that continues across a mirror plane (all but `symmetry`).
std::vector<OutputEntry> reaction_outputs(bool whole);

/// The history columns of the loads given as forces on a surface or a node (traction,
/// point-force, follower-traction): the total force and its work.
std::vector<OutputEntry> load_force_outputs();

/// The history columns of the contact state, which the dies and the surface contacts share.
std::vector<OutputEntry> contact_state_outputs();

}  // namespace plisse::term_keys
