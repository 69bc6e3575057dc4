#pragma once
/// The kinds of model term a case can ask for: the boundary conditions, loads, cavities, dies, caps
/// and contacts of its term sections. Each kind is one entry, in a file of its own in this folder,
/// that says everything plisse needs to know about it:
/// - its section of the case file and its input word (`loads:` with `type: pressure`);
/// - its key table over the settings type of its physics (schema::Schema<S>), which reads and
///   checks an entry and renders the kind's rows of docs/case-file.md;
/// - its checks against the mesh;
/// - make(settings, context): the ModelTerm it adds to the model, or, for a condition (the
///   `boundary:` section), constrain(settings, mesh, set): the components it prescribes;
/// - the ramps `plisse check` warns about and the lines it adds to a run's log.
/// The table (term_kinds(), registry.cpp) lists the entries; the case reader (case/case.cpp), the
/// mesh checks (case/mesh_checks.cpp), the model builder (app/model_builder.cpp) and the history's
/// reaction columns loop over it (docs/architecture.md, "Term kinds").
///
/// Ownership: the kinds are built once and never change; a TermEntry points at its kind and owns
/// its settings.
#include <any>
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/cap_closure.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "physics/ramp.hpp"
#include "schema/table.hpp"

namespace plisse {

class TermKind;

/// One output quantity of the reference of docs/output.md (app/output_reference.hpp). `name` is the
/// exact name, or a pattern in which `<...>` stands for a name from the case file (e.g.
/// `force_x:<die>`, `contact_<die>`) or a number (`mode_<k>`).
struct OutputEntry {
  std::string name;
  std::string unit;     ///< in the case's consistent units (mm, N, MPa, s); "–" dimensionless
  std::string when;     ///< when it is written ("always", or the case keys that add it)
  std::string meaning;  ///< meaning, and sign where it has one
};

/// One item of a term section of the case: its kind and its settings (the kind's settings type).
struct TermEntry {
  const TermKind* kind = nullptr;
  std::any settings;
  std::string name;  ///< the item's `name`
  InputPlace place;  ///< where the item is

  /// The settings as the kind's type; throws std::bad_any_cast for another type.
  template <class S>
  const S& as() const {
    return std::any_cast<const S&>(settings);
  }
};

/// What the mesh checks of a kind get besides its settings.
struct TermMeshCheck {
  const Mesh& mesh;
  /// The surface tag exists in the mesh and is not empty; else an InputError at its place that
  /// lists the tags there are.
  std::function<void(const SurfaceRef&)> surface;
  /// A condition's tag: as `surface` on a solid mesh; on a shell an edge tag (Mesh::edge_tags) or
  /// a surface tag.
  std::function<void(const SurfaceRef&)> condition;
};

/// What make() gets besides its settings: the mesh and what the case's other sections decide.
struct TermContext {
  const Mesh& mesh;  ///< borrowed by the terms
  /// The constrained components of the boundary conditions and rigid regions.
  const std::vector<ConstrainedComponent>& constraints;
  int mirrors = 0;  ///< mirror planes of the case's symmetry conditions (dirichlet.hpp)
  /// The small-strain shear modulus of the case's `material` [MPa]: the contact penalties' scale.
  std::function<double()> shear_modulus;
  /// The density of every element [tonne/mm^3]: of each tetrahedron (its material's; 0 in a
  /// rigid region), or of each triangle of a shell.
  std::function<std::vector<double>()> element_densities;
  /// The faces a die touches when it names no `surface`: the boundary without the symmetry
  /// planes' faces (docs/theory/contact.md, D5).
  std::function<std::vector<std::array<int, 3>>()> default_die_faces;
  /// The case's caps and the nodes each ties (condition_nodes of its `surface`), in the order of
  /// `caps:`: what a cavity or a pressure closes its rims with (cavities.md, C14).
  std::function<std::vector<CapNodes>()> caps;
  /// The largest distance [mm] the case's imperfection moved a node of `mesh`
  /// (solver.stability.imperfection × the wall's thickness; 0 without one): how far from flat a
  /// cavity's wall that lay flat may start (cavities.md, C8).
  double imperfection = 0.0;
};

/// A ramp of an entry that `plisse check` compares with solver.end_time, and what it moves
/// ("load 'p'").
struct RampUse {
  Ramp ramp;
  std::string what;
};

/// A kind of model term (see the file comment). Made by make_term_kind from a TermDefinition.
class TermKind {
 public:
  /// The case file's list: "boundary", "loads", "cavities", "dies", "caps", "contacts".
  std::string section;
  /// The word of the section's selector key (`type: pressure`); empty in a section of one kind.
  std::string word;
  std::string summary;  ///< what the word means, in a phrase (the selector key's help)

  /// Reads one item of the section. `selector` is the section's selector key (empty: none) and
  /// `others` the keys of the section's other kinds, named as not applying to this one.
  std::function<TermEntry(const schema::Field& item, schema::ReadContext& context,
                          const std::string& selector, const std::vector<std::string>& others)>
      read;
  std::function<schema::SectionDoc()> doc;  ///< the kind's rows and rules
  /// Checks the entry against the mesh (InputError at the offending key).
  std::function<void(const TermEntry&, const TermMeshCheck&)> check_mesh;
  /// The entry's term; may throw InputError for what only the built term can judge.
  /// Empty for a condition, which adds constraints instead of a term.
  std::function<std::unique_ptr<ModelTerm>(const TermEntry&, const TermContext&)> make;
  /// A condition's constrained components; empty for the other kinds.
  std::function<void(const TermEntry&, const Mesh&, ConstraintSet&)> constrain;
  /// A condition's surface: its reaction force is reported when the entry has a name.
  std::function<SurfaceRef(const TermEntry&)> surface;
  /// A condition whose surface is a mirror plane of the model: a cut through the whole body
  /// (`symmetry`). Its reaction is internal to the whole body; the default contact surface of a
  /// die leaves its faces out; an imperfection keeps its nodes in the plane.
  bool mirror = false;
  /// A condition that holds the slope across a shell's edge (clamped, symmetry): marks the sides
  /// of its edge in Mesh::side_mirrors (docs/theory/shell.md, KL8a). Empty for the others.
  std::function<void(const TermEntry&, Mesh&)> hold_slope;
  /// Which meshes the kind works on: a solid's tetrahedra, a shell's mid-surface (element:
  /// shell). Anything else is refused by the mesh checks, naming the kind and the element.
  bool solid = true;
  bool shell = false;
  std::function<std::vector<RampUse>(const TermEntry&)> ramps;  ///< for the end-time warnings
  /// Lines for the run's log (e.g. the node a point force acts on).
  std::function<std::vector<std::string>(const TermEntry&, const Mesh&)> notes;
  std::vector<OutputEntry> history;       ///< the history.csv columns its term writes
  std::vector<OutputEntry> point_fields;  ///< the point fields it adds to the step files
};

/// What a kind's file gives, over its settings type S (which has the members `name` and `place`).
template <class S>
struct TermDefinition {
  std::string section;
  std::string word;
  std::string summary;
  schema::Schema<S> keys;
  std::function<void(const S&, const TermMeshCheck&)> check_mesh;
  /// A term's maker, or for a condition the two below and `mirror`.
  std::function<std::unique_ptr<ModelTerm>(const S&, const TermContext&)> make;
  std::function<void(const S&, const Mesh&, ConstraintSet&)> constrain;
  std::function<SurfaceRef(const S&)> surface;
  bool mirror = false;
  std::function<void(const S&, Mesh&)> hold_slope;
  bool solid = true;
  bool shell = false;
  std::function<std::vector<RampUse>(const S&)> ramps;                   ///< empty: none
  std::function<std::vector<std::string>(const S&, const Mesh&)> notes;  ///< empty: none
  std::vector<OutputEntry> history;
  std::vector<OutputEntry> point_fields;
};

/// The kind of `definition`, its functions typed on S.
template <class S>
TermKind make_term_kind(TermDefinition<S> definition) {
  TermKind kind;
  kind.section = definition.section;
  kind.word = definition.word;
  kind.summary = definition.summary;
  const auto keys = std::make_shared<const schema::Schema<S>>(std::move(definition.keys));
  kind.read = [keys, word = kind.word](const schema::Field& item, schema::ReadContext& context,
                                       const std::string& selector,
                                       const std::vector<std::string>& others) {
    S settings;
    if (selector.empty())
      keys->read(item, settings, context);
    else
      keys->read_selected(item, settings, context, selector, word, others);
    TermEntry entry;
    entry.name = settings.name;
    entry.place = settings.place;
    entry.settings = std::move(settings);
    return entry;
  };
  kind.doc = [keys] { return keys->doc(); };
  kind.check_mesh = [check = std::move(definition.check_mesh)](const TermEntry& entry,
                                                               const TermMeshCheck& mesh) {
    check(entry.as<S>(), mesh);
  };
  if (definition.make)
    kind.make = [make = std::move(definition.make)](const TermEntry& entry,
                                                    const TermContext& context) {
      return make(entry.as<S>(), context);
    };
  if (definition.constrain)
    kind.constrain = [constrain = std::move(definition.constrain)](
                         const TermEntry& entry, const Mesh& mesh, ConstraintSet& set) {
      constrain(entry.as<S>(), mesh, set);
    };
  if (definition.surface)
    kind.surface = [surface = std::move(definition.surface)](const TermEntry& entry) {
      return surface(entry.as<S>());
    };
  kind.mirror = definition.mirror;
  if (definition.hold_slope)
    kind.hold_slope = [hold = std::move(definition.hold_slope)](
                          const TermEntry& entry, Mesh& mesh) { hold(entry.as<S>(), mesh); };
  kind.solid = definition.solid;
  kind.shell = definition.shell;
  kind.ramps = [ramps = std::move(definition.ramps)](const TermEntry& entry) {
    return ramps ? ramps(entry.as<S>()) : std::vector<RampUse>{};
  };
  kind.notes = [notes = std::move(definition.notes)](const TermEntry& entry, const Mesh& mesh) {
    return notes ? notes(entry.as<S>(), mesh) : std::vector<std::string>{};
  };
  kind.history = std::move(definition.history);
  kind.point_fields = std::move(definition.point_fields);
  return kind;
}

/// A term section of the case file.
struct TermSection {
  std::string key;  ///< "boundary", "loads"
  /// The key whose word picks the item's kind ("type"); empty when the section has one kind.
  std::string selector;
  std::string help;  ///< the section's meaning in the case's table
};

/// The term sections, in the order their terms are added to the model.
const std::vector<TermSection>& term_sections();

/// The section called `key`; throws plisse::Error for another key.
const TermSection& term_section(const std::string& key);

/// The entries of `entries` in `section`, in their order.
std::vector<const TermEntry*> entries_in(const std::vector<TermEntry>& entries,
                                         const std::string& section);

/// Every kind, section by section in term_sections()'s order, within a section in the order of
/// its selector's words. Built once; safe to call concurrently.
const std::vector<TermKind>& term_kinds();

/// The kinds of one section.
std::vector<const TermKind*> term_kinds(const std::string& section);

/// The constrained components of the conditions among `entries` (the `boundary:` section), in
/// their order (ConstraintSet judges conflicts between them).
std::vector<ConstrainedComponent> collect_constraints(const std::vector<TermEntry>& entries,
                                                      const Mesh& mesh);

/// The surfaces of the mirror conditions among `entries` (`symmetry`), in their order.
std::vector<std::string> mirror_surfaces(const std::vector<TermEntry>& entries);

/// Reads one item of `section`: its selector (a required choice among the kinds' words), then
/// the kind's keys. Throws InputError at the offending key.
TermEntry read_term(const std::string& section, const schema::Field& item,
                    schema::ReadContext& context);

/// The table of `section` for docs/case-file.md: the selector's row, then every kind's rows (a
/// key whose row is the same in several kinds once, applying to all of them), then the rules.
schema::SectionDoc term_section_doc(const std::string& section);

}  // namespace plisse
