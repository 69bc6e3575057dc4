#pragma once
/// A plisse case: the typed, validated contents of a case file (YAML).
///
/// Keys of the file are the member names below (docs/architecture.md, "Coding conventions"). The
/// sections are made of the parameter types of the layers that use them (Ramp, Cavity in
/// physics/; SteppingSettings, NewtonSettings in solver/), and the term sections of the term
/// kinds' entries (terms/), so those layers never see this file. Every value that refers to the
/// user's input keeps its InputPlace, so later checks (tags against the mesh, material rules) can
/// name the file, line, column and key. The parser
/// (`parse_case_file`) fills and validates everything that can be checked without the mesh;
/// `check_case_against_mesh` does the rest.
///
/// Units: mm, MPa, s, tonne/mm^3 (so accelerations are mm/s^2, forces N).
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/wrinkle_lines.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "element/element_family.hpp"
#include "material/inelastic.hpp"
#include "mesh/generate.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "output/vtu_writer.hpp"
#include "physics/ramp.hpp"
#include "solver/stepping_settings.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

struct MeshSection {
  std::optional<std::string> file;             ///< `file:` resolved against the case directory
  std::optional<MeshGenerationSpec> generate;  ///< `generate: KIND` plus the kind's options
  InputPlace place;                            ///< where `mesh:` is
  InputPlace file_place;                       ///< where the `file:` value is (file meshes)
  /// Generated meshes: where each given option is, by key ("layers"); "generate" for the kind.
  std::map<std::string, InputPlace> option_places;
  /// File meshes: `thickness:` [mm], the wall thickness of a shell read from a file (optional).
  std::optional<double> file_thickness;

  /// The wall thickness [mm] of a shell (generated spherical-shell, airbag, sheet, or a file mesh
  /// with `thickness:`): the length imperfections, branch switching and the wrinkle threshold are
  /// relative to. Empty for a cube or a file mesh without `thickness:`.
  std::optional<double> wall_thickness() const {
    if (file) return file_thickness;
    if (generate && generate->kind != "cube") return generate->thickness;
    return std::nullopt;
  }
};

struct MaterialSection {
  std::string model;                     ///< registry name, e.g. "neo-hookean"
  std::map<std::string, double> params;  ///< validated against the material registry
  std::map<std::string, InputPlace> param_places;
  bool exact_incompressibility = true;  ///< `incompressibility: exact | nearly`
  double bulk_modulus = 0.0;            ///< [MPa], > 0, required when nearly incompressible
  double density = 0.0;                 ///< [tonne/mm^3], >= 0 (gravity loads)
  /// `fibre_frame: shell`: a fibre-reinforced model's directions are given in each element's
  /// surface frame (meridian, hoop, normal) of a generated spherical shell, airbag or tube, not in
  /// x, y, z.
  bool shell_fibre_frame = false;
  InputPlace fibre_frame_place;
  /// `viscoelastic:` and `mullins:` (material/inelastic.hpp); absent: none.
  Viscoelasticity viscoelastic;
  MullinsSoftening mullins;
  InelasticLaw inelastic() const { return {viscoelastic, mullins}; }
  InputPlace place;
  /// 1/κ [1/MPa] as the mixed formulation takes it: 0 for exact incompressibility.
  double inverse_bulk_modulus() const { return exact_incompressibility ? 0.0 : 1.0 / bulk_modulus; }
};

/// What a probe reports (docs/output.md, "Probes").
enum class ProbeField {
  displacement,         ///< ux, uy, uz [mm]
  position,             ///< x, y, z: the deformed position [mm]
  pressure,             ///< the pressure field [MPa]
  cauchy,               ///< the element's Cauchy stress, 6 components [MPa]
  von_mises,            ///< the element's von Mises stress [MPa]
  principal_stretches,  ///< the element's principal stretches, largest first [-]
  principal_stresses,   ///< the element's principal Cauchy stresses, largest first [MPa]
  J,                    ///< the element's volume ratio [-]
  thickness,            ///< the current wall thickness [mm] (a case with a wall)
};

/// A named material point of the undeformed body, reported at every step: nodal fields
/// interpolated there, element fields of the element that holds it.
struct Probe {
  std::string name;
  Vec3d point = Vec3d::Zero();
  std::vector<ProbeField> fields = {ProbeField::displacement};
  InputPlace place;
  InputPlace point_place;   ///< where `point` is written
  InputPlace fields_place;  ///< where `fields` is written (the entry's place when absent)
};

/// A part of the body given by a volume tag: with a material of its own, or rigid. Tetrahedra in
/// no region have the case's `material`.
struct Region {
  std::string volume;  ///< the volume tag (a solid's); empty when the region is a surface or box
  InputPlace volume_place;
  std::string surface;  ///< a shell's: the surface tag of its triangles; else empty
  InputPlace surface_place;
  /// The region as a box instead: the elements (tetrahedra, or a shell's triangles) whose centroid
  /// lies in [lower, upper] [mm].
  std::optional<std::array<Vec3d, 2>> box;
  InputPlace box_place;
  std::optional<MaterialSection> material;  ///< a deformable region's model
  /// A shell's region: its own reference wall thickness [mm] (else the mesh's).
  std::optional<double> thickness;
  InputPlace thickness_place;
  bool rigid = false;
  /// A rigid region: its translation [mm] at the end of the ramp (it does not turn). Every node
  /// of its tetrahedra follows it.
  Vec3d displacement = Vec3d::Zero();
  Ramp ramp;
  std::string name;  ///< optional; a rigid region's force columns `force_x:<name>` ...
  InputPlace place;
  /// What messages and summary.json call the region: its volume or surface tag, else its name,
  /// else its key ("regions[1]").
  std::string label() const {
    return !volume.empty() ? volume : !surface.empty() ? surface : !name.empty() ? name : place.key;
  }
};

/// The pressure where regions of different materials meet (mixed solid elements): each region's
/// own, so that it may jump across their interface, or one field shared by all.
enum class RegionPressure { discontinuous, continuous };

enum class Scheme { total_lagrangian, incremental };

struct StabilitySettings {
  bool check = false;          ///< inertia of the tangent at every converged step
  bool branch_switch = false;  ///< perturb along the critical mode when stability is lost
  int modes = 4;               ///< eigenmodes computed at an instability, >= 1
  double imperfection = 0.0;   ///< amplitude / wall thickness, >= 0
  std::string imperfection_kind = "random";  ///< random | mode
  int seed = 1;                              ///< random imperfection seed
  /// mode: the run directory (or a .vtu file in it) whose `mode_<imperfection_mode>` point field
  /// shapes the imperfection; resolved against the case directory.
  std::string imperfection_from;
  int imperfection_mode = 1;      ///< >= 1
  double branch_amplitude = 0.1;  ///< perturbation along the critical mode / wall thickness, > 0
  /// Where a branch switch starts Newton: "koiter" (the asymptotic estimate, then the
  /// perturbations if it does not switch) or "perturbation" (the perturbations only).
  std::string branch_start = "koiter";
  /// End the run, completed, at the first step found unstable that a branch switch (when on) did
  /// not leave: the step before and this one bracket the buckling or collapse load.
  bool stop_when_unstable = false;
  InputPlace place;  ///< where `stability:` is
};

/// `solver:`: the stepping and Newton settings (solver/stepping_settings.hpp) and what the app
/// maps to the other layers.
struct SolverSettings : SteppingSettings {
  Scheme scheme = Scheme::total_lagrangian;
  double viscosity = 0.0;  ///< viscous stabilisation [MPa s], >= 0
  StabilitySettings stability;
  std::string petsc_options;       ///< extra PETSc options, e.g. "-ksp_type preonly -pc_type lu"
  InputPlace petsc_options_place;  ///< where they are written (for PETSc's refusals)
};

/// A measurement line of `output.wrinkles.lines`: a straight segment of the undeformed body along
/// which the crests of wrinkles are counted (docs/theory/wrinkles.md, W20-W26).
struct WrinkleLine {
  std::string name;            ///< names its history columns (`wrinkle_crests:<name>`, ...)
  Vec3d from = Vec3d::Zero();  ///< one end [mm]
  Vec3d to = Vec3d::Zero();    ///< the other end [mm], not `from`
  int points = 200;            ///< samples, equally spaced, in [16, 20000]
  int min_crests = 3;          ///< fewer crests are a smooth shape, not wrinkles, >= 1
  LineMirror mirror = LineMirror::none;  ///< the end on a mirror plane of the model
  InputPlace place;                      ///< where the entry is
  InputPlace from_place, to_place;
};

struct WrinkleSettings {
  char axis = 'y';                 ///< 'x' | 'y' | 'z'
  Vec3d center = Vec3d::Zero();    ///< a point on the axis [mm]
  std::vector<double> rings_deg;   ///< latitudes [deg] in (-90, 90)
  double threshold = 0.1;          ///< wrinkled when amplitude > threshold * thickness, > 0
  int min_count = 3;               ///< smaller full-circle counts are global shape modes, >= 1
  double peak_ratio = 2.0;         ///< a wrinkle peak exceeds this times the shape envelope, >= 1
  std::string surface = "outer";   ///< the tagged surface the rings lie on
  std::vector<WrinkleLine> lines;  ///< measurement lines
  InputPlace place;                ///< where `wrinkles:` is
  InputPlace surface_place;
  /// Wrinkles are measured (rings, lines, and the tension-field state of `surface`).
  bool enabled() const { return !rings_deg.empty() || !lines.empty(); }
  bool has_rings() const { return !rings_deg.empty(); }
};

struct OutputSettings {
  int every = 1;                    ///< VTU every N converged steps (the last one always), >= 1
  int checkpoint_every = 10;        ///< checkpoint every N converged steps (and on SIGINT/SIGTERM),
                                    ///< >= 0; 0: only on signals
  double checkpoint_minutes = 5.0;  ///< also checkpoint when this much wall time has passed since
                                    ///< the last one, >= 0; 0: no time-based checkpoints
  bool deformed = false;            ///< write deformed coordinates instead of reference ones
  VtuCompression compression = VtuCompression::zlib;  ///< of the step files' arrays
  /// Optional 'x' | 'y' | 'z': adds a history column `stretch` = volume average of F along that
  /// axis (the columns `cauchy_xx` ... `cauchy_xz`, deformed-volume averages, are always there).
  std::optional<char> stretch_axis;
  WrinkleSettings wrinkles;
};

struct Case {
  std::string path;       ///< the case file as given
  std::string directory;  ///< its directory (relative paths in the case resolve against it)
  std::string title;      ///< optional one-line description
  /// The element of every tetrahedron; Taylor-Hood needs a second-order mesh (generated ones are
  /// made second-order for it).
  ElementFamily element = kDefaultElement;
  MeshSection mesh;
  MaterialSection material;
  std::vector<Region> regions;
  /// The pressure where the regions meet (solver/pressure_twins.hpp).
  RegionPressure region_pressure = RegionPressure::discontinuous;
  InputPlace region_pressure_place;  ///< where it was given (empty key: not given)
  /// The items of the term sections (`boundary`, `loads`, `cavities`, `dies`, `caps`, `contacts`),
  /// each with its kind and settings (terms/term_kind.hpp), in the order of the file.
  std::vector<TermEntry> terms;
  std::vector<Probe> probes;
  SolverSettings solver;
  OutputSettings output;

  /// The items of one term section ("loads"), in their order.
  std::vector<const TermEntry*> terms_in(const std::string& section) const {
    return entries_in(terms, section);
  }
};

/// Parses and validates `path`. `overrides` are "key.path=value" strings from `--set`
/// (e.g. "mesh.layers=4", "loads[0].value=1e-3", "dies[0].move.displacement=[0,-5,0]"): each
/// replaces or adds the value at that path before validation; the value is read as YAML.
/// Throws InputError naming file, line, column, key path and the rule broken.
Case parse_case_file(const std::string& path, const std::vector<std::string>& overrides = {});

/// Same, from text (tests); `name` stands for the file name in messages.
Case parse_case_string(const std::string& text, const std::string& name,
                       const std::vector<std::string>& overrides = {});

/// Reads or generates the case's mesh (InputError on failure, naming the case's mesh key).
Mesh load_case_mesh(const Case& c);

/// The elements of a region, increasing: of a solid, the tetrahedra (indices into mesh.tets) of its
/// volume tag or whose centroid lies in its box; of a shell, the triangles (indices into
/// mesh.triangles) of its surface tag or whose centroid lies in its box. Empty for a tag the mesh
/// lacks, or one of the other kind of mesh.
std::vector<int> region_elements(const Region& region, const Mesh& mesh);

/// Checks everything that needs the mesh: every SurfaceRef names an existing, non-empty surface
/// tag; symmetry surfaces are planar; the mesh passes check_mesh. Throws InputError at the place of
/// the offending key.
void check_case_against_mesh(const Case& c, const Mesh& mesh);

}  // namespace plisse
