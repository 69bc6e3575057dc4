#include "app/output_reference.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace plisse::app {
namespace {

const std::vector<OutputEntry> kHistoryBefore = {
    {"step", "–", "always", "converged step, counted from 1"},
    {"time", "–", "always",
     "the step's time t in [0, `solver.end_time`]: the quasi-static load parameter every ramp is a "
     "function of (`loads[].ramp`, `dies[].move.ramp`, ...); with `solver.control: arc-length` "
     "it falls where the path passes a limit load"},
    {"load_factor", "–", "always",
     "t / `solver.end_time`, the fraction of the run done; each load's own magnitude is its "
     "column (`pressure:<load>`, `load_x:<load>`, ...), since ramps may start and end anywhere"},
    {"newton_iterations", "–", "always",
     "Newton iterations (tangents factorised) of the step's accepted attempt, over all its contact "
     "passes and a branch switch's re-solve; the attempts cut back before it are not counted "
     "here (summary.json `failed_newton_iterations`)"},
    {"residual_norm", "N", "always",
     "‖R‖₂ of the free equations at the converged state (nodal forces, and the pressure "
     "equations' volume change times μ/h: docs/theory/mixed_up.md, X1)"},
};

/// After the term kinds' columns.
const std::vector<OutputEntry> kHistoryAfter = {
    {"dissipated_energy", "mJ", "`solver.viscosity` > 0",
     "energy the viscous stabilisation has dissipated since t = 0; keep it small against "
     "`strain_energy`"},
    {"stretch", "–", "`output.stretch_axis`",
     "the reference-volume average of F along that axis (F_xx, F_yy or F_zz)"},
    {"stretch_x", "–", "always",
     "reference-volume average of F_xx over the body (likewise `stretch_y`, `stretch_z`); the "
     "stretch along x of a homogeneous deformation"},
    {"stretch_y", "–", "always", "reference-volume average of F_yy"},
    {"stretch_z", "–", "always", "reference-volume average of F_zz"},
    {"cauchy_xx", "MPa", "always",
     "current-volume average of the Cauchy stress σ_xx over the body, tension positive "
     "(likewise `cauchy_yy`, `cauchy_zz`, and the shear components `cauchy_xy`, `cauchy_yz`, "
     "`cauchy_xz`)"},
    {"cauchy_yy", "MPa", "always", "average σ_yy"},
    {"cauchy_zz", "MPa", "always", "average σ_zz"},
    {"cauchy_xy", "MPa", "always", "average σ_xy"},
    {"cauchy_yz", "MPa", "always", "average σ_yz"},
    {"cauchy_xz", "MPa", "always", "average σ_xz"},
    {"force_x:<region>", "N", "`regions[]` rigid, with a `name`",
     "x component of the reaction on a rigid region: the force the region exerts on the body, "
     "summed over the nodes of its tetrahedra (a held base under a membrane pressed down onto it "
     "pushes up; likewise y, z)"},
    {"force_y:<region>", "N", "`regions[]` rigid, with a `name`",
     "y component of the rigid region's reaction"},
    {"force_z:<region>", "N", "`regions[]` rigid, with a `name`",
     "z component of the rigid region's reaction"},
    {"ux:<probe>", "mm", "`probes[]` (`fields` has `displacement`, the default)",
     "x displacement at the probe's material point, interpolated by the element's shape "
     "functions (likewise y, z; see Probes)"},
    {"uy:<probe>", "mm", "`probes[]`, `displacement`", "y displacement at the probe"},
    {"uz:<probe>", "mm", "`probes[]`, `displacement`", "z displacement at the probe"},
    {"x:<probe>", "mm", "`probes[]`, `position`",
     "x coordinate of the probe's material point in the deformed state, X + u (likewise y, z)"},
    {"y:<probe>", "mm", "`probes[]`, `position`", "deformed y coordinate of the probe"},
    {"z:<probe>", "mm", "`probes[]`, `position`", "deformed z coordinate of the probe"},
    {"pressure:<probe>", "MPa", "`probes[]`, `pressure`",
     "the pressure field interpolated at the probe, positive in compression (VTU `pressure`); "
     "where regions meet, the pressure of the probe's element's region (`region_pressure`)"},
    {"cauchy_xx:<probe>", "MPa", "`probes[]`, `cauchy`",
     "σ_xx of the element holding the probe, its volume average (VTU `cauchy_stress`), tension "
     "positive (likewise `cauchy_yy`, `cauchy_zz`, `cauchy_xy`, `cauchy_yz`, `cauchy_xz`)"},
    {"cauchy_yy:<probe>", "MPa", "`probes[]`, `cauchy`", "the element's σ_yy"},
    {"cauchy_zz:<probe>", "MPa", "`probes[]`, `cauchy`", "the element's σ_zz"},
    {"cauchy_xy:<probe>", "MPa", "`probes[]`, `cauchy`", "the element's σ_xy"},
    {"cauchy_yz:<probe>", "MPa", "`probes[]`, `cauchy`", "the element's σ_yz"},
    {"cauchy_xz:<probe>", "MPa", "`probes[]`, `cauchy`", "the element's σ_xz"},
    {"von_mises:<probe>", "MPa", "`probes[]`, `von_mises`",
     "von Mises stress of the element holding the probe (VTU `von_mises`)"},
    {"stretch_1:<probe>", "–", "`probes[]`, `principal_stretches`",
     "largest principal stretch of the element holding the probe (VTU `principal_stretches`; "
     "`stretch_2`, `stretch_3` the middle and smallest)"},
    {"stretch_2:<probe>", "–", "`probes[]`, `principal_stretches`", "middle principal stretch"},
    {"stretch_3:<probe>", "–", "`probes[]`, `principal_stretches`", "smallest principal stretch"},
    {"stress_1:<probe>", "MPa", "`probes[]`, `principal_stresses`",
     "largest principal Cauchy stress of the element holding the probe (VTU "
     "`principal_stresses`; `stress_2`, `stress_3` the middle and smallest)"},
    {"stress_2:<probe>", "MPa", "`probes[]`, `principal_stresses`",
     "middle principal Cauchy stress"},
    {"stress_3:<probe>", "MPa", "`probes[]`, `principal_stresses`",
     "smallest principal Cauchy stress"},
    {"J:<probe>", "–", "`probes[]`, `J`",
     "volume ratio of the element holding the probe (VTU `J`)"},
    {"thickness:<probe>", "mm", "`probes[]`, `thickness` (a case with a wall)",
     "the current wall thickness interpolated at the probe (VTU `thickness`)"},
    {"volume", "mm³", "always", "the body's volume in the deformed state, of the modelled part"},
    {"min_J", "–", "always",
     "the smallest element average of det F: 1 for an exactly incompressible material up to the "
     "discretisation; below 1 a nearly incompressible one is compressed"},
    {"strain_energy", "mJ", "always",
     "energy stored in the body, of the modelled part (N mm = mJ)"},
    {"min_thickness", "mm",
     "a shell or sheet (the mesh has a wall thickness and wall faces), or a shell mesh",
     "the smallest current wall thickness over the nodes (VTU point field `thickness`); of a "
     "shell mesh, over its triangles (VTU cell field `thickness`)"},
    {"negative_pivots", "–", "`solver.stability.check`",
     "negative pivots of the tangent's LDLᵀ factorisation at the converged state"},
    {"expected_negative_pivots", "–", "`solver.stability.check`",
     "the negative pivots of a stable state (one per pressure unknown and constraint "
     "multiplier); more means the state is unstable"},
    {"stable", "–", "`solver.stability.check`",
     "1 when negative_pivots = expected_negative_pivots and no pivot is zero, else 0"},
    {"wrinkle_amplitude", "mm", "`output.wrinkles.rings_deg`",
     "the largest ring amplitude at the step (peak to peak of the ring's wrinkle band)"},
    {"wrinkle_count", "–", "`output.wrinkles.rings_deg`",
     "the full-circle wave count of that ring when its amplitude is above the threshold "
     "(`output.wrinkles.threshold` times the thickness), else 0: the body has wrinkled"},
    {"wrinkle_peak_count", "–", "`output.wrinkles.rings_deg`",
     "the same ring's count whether or not its amplitude is above the threshold (0 when no ring "
     "has a wrinkle band): the count of wrinkles still growing, or of the mesh's noise"},
    {"wrinkled_fraction", "–", "`output.wrinkles.rings_deg` or `lines`",
     "fraction of the measured surface's area that is wrinkled in the tension-field sense (one "
     "principal membrane stress compressive)"},
    {"slack_fraction", "–", "`output.wrinkles.rings_deg` or `lines`",
     "fraction of that area that is slack (both principal membrane stresses compressive)"},
    {"wrinkle_crests:<line>", "–", "`output.wrinkles.lines[]`",
     "the crests and troughs counted along the line when its amplitude is above the threshold "
     "(`output.wrinkles.threshold` times the thickness), else 0: the body has wrinkled there "
     "(docs/theory/wrinkles.md, W24, W27)"},
    {"wrinkle_peak_crests:<line>", "–", "`output.wrinkles.lines[]`",
     "the same count whether or not the amplitude is above the threshold (0 below the line's "
     "`min_crests`): wrinkles still growing, or the mesh's noise"},
    {"wrinkle_amplitude:<line>", "mm", "`output.wrinkles.lines[]`",
     "the largest height of a crest over the troughs beside it (W25); 0 without crests"},
    {"wrinkle_wavelength:<line>", "mm", "`output.wrinkles.lines[]`",
     "twice the mean distance between the zeros that separate its crests, along the deformed "
     "line's smooth shape (W26); 0 with fewer than 2 crests"},
};

const std::vector<OutputEntry> kSummary = {
    {"units", "–", "always",
     "the units of every number plisse writes, for a case in the docs' consistent units: "
     "{\"length\": \"mm\", \"force\": \"N\", \"stress\": \"MPa\", \"time\": \"s\", "
     "\"energy\": \"mJ\", \"density\": \"t/mm³\"} (plisse computes in the case's own "
     "consistent units: see Units)"},
    {"units.<quantity>", "–", "always", "one entry of `units`"},
    {"history_units.<column>", "–", "always",
     "the unit of each history.csv column, as in this reference (`–` dimensionless), so a script "
     "can label its axes"},
    {"case", "–", "always", "the case file as given on the command line"},
    {"case_path", "–", "always", "the case file's absolute path"},
    {"overrides", "–", "always", "the `--set KEY=VALUE` overrides of the run, in order"},
    {"title", "–", "always", "the case's `title`"},
    {"completed", "–", "always",
     "true when the run reached `solver.end_time`, or (arc-length control) its load factor fell "
     "below `solver.stop_load_factor` past a limit load, or it stopped at an instability "
     "(`solver.stability.stop_when_unstable`; `ended` says which)"},
    {"ended", "–", "the run completed",
     "what ended it: `end_time`, or `stop_load_factor` (arc-length control: the load factor fell "
     "below `solver.stop_load_factor` past a limit load), or `instability` (the last step is the "
     "first the stability check found unstable, `solver.stability.stop_when_unstable`)"},
    {"interrupted", "–", "always", "true when a signal (Ctrl-C, SIGTERM) stopped the run"},
    {"failure", "–", "the run did not complete", "why the run stopped early"},
    {"limit.time", "s", "the step fell below `solver.min_step`",
     "the last converged step's time: no step past it converged, so the load could not be raised "
     "there (a limit load if the body collapses there; prescribe a displacement to pass it)"},
    {"limit.load_factor", "–", "the step fell below `solver.min_step`",
     "that step's load factor (time / end_time)"},
    {"limit.step", "–", "the step fell below `solver.min_step`", "that step's number"},
    {"limit.loads.<column>", "the column's", "the step fell below `solver.min_step`",
     "the loads at that step, by their history.csv columns (`pressure:<name>`, `load_x:<name>` "
     "..., caps' and dies' `force_x:<name>`, `moment_x:<name>` ...); the log's error names them "
     "too"},
    {"nodes", "–", "always", "mesh nodes (corner and edge nodes)"},
    {"elements", "–", "always", "tetrahedra, or the triangles of a shell mesh"},
    {"element", "–", "always", "the element family: `mini`, `taylor-hood` or `shell`"},
    {"dofs", "–", "always", "all unknowns, constrained ones included"},
    {"free_dofs", "–", "always", "the unknowns solved for (the size of the linear systems)"},
    {"pressure_dofs", "–", "always", "free pressure unknowns"},
    {"pressure_twins", "–", "always",
     "pressure unknowns a region has of its own where regions meet (`region_pressure: "
     "discontinuous`, docs/theory/regions.md): one per region beyond the first at each corner "
     "node they share; 0 with one region, with `continuous` and on a shell"},
    {"steps", "–", "always",
     "converged steps of the whole run, the number of its last step: after --resume the steps "
     "before the resume are counted too, as in history.csv's rows (the counters below are this "
     "process's alone)"},
    {"newton_iterations", "–", "always",
     "Newton iterations of this process (after --resume, since the resume), over all attempts: "
     "the sum of the history column over its steps plus `failed_newton_iterations`"},
    {"failed_newton_iterations", "–", "always",
     "Newton iterations spent in attempts that failed and were cut back"},
    {"reused_factor_solves", "–", "always",
     "linear solves with a factorisation already at hand, over all attempts: chord steps (no new "
     "tangent) and the GMRES iterations of Krylov steps"},
    {"krylov_steps", "–", "always",
     "Newton steps without factorisation, over all attempts: the tangent assembled and its "
     "system solved by GMRES preconditioned with a factorisation already at hand "
     "(`solver.newton.reuse_krylov_iterations`)"},
    {"cutbacks", "–", "always", "failed attempts that were retried with a smaller step"},
    {"final_time", "–", "always", "time t of the last converged step"},
    {"factorisations", "–", "always", "numerical factorisations of the tangent"},
    {"factor_entries", "–", "a direct solver and at least one iteration",
     "entries of the last factor (its fill is this over the tangent's nonzeros)"},
    {"wall_time.mesh", "s", "always", "reading or generating the mesh"},
    {"wall_time.setup", "s", "always", "building the model and the solver"},
    {"wall_time.assembly", "s", "always", "assembling residuals and tangents"},
    {"wall_time.linear_solve", "s", "always",
     "linear solves, factorisations included (the next two are parts of it)"},
    {"wall_time.factorisation", "s", "always", "numerical factorisations"},
    {"wall_time.triangular_solve", "s", "always", "forward and backward substitutions"},
    {"wall_time.output", "s", "always", "history rows, step files, wrinkle metrics"},
    {"wall_time.total", "s", "always", "the whole run"},
    {"ranks", "–", "always", "MPI processes"},
    {"peak_memory_mib", "MiB", "always", "peak resident memory summed over the ranks"},
    {"peak_memory_per_rank_mib", "MiB", "always", "the largest rank's peak resident memory"},
    {"material_stability.stable_stretches", "–",
     "the case's `material` not stable over all of 0.1 to 10 in some test",
     "the stretches over which the material is stable in Drucker's sense, per test (the keys "
     "below; docs/fit.md, \"Stability\"); every step then checks the state of each element "
     "of it"},
    {"material_stability.stable_stretches.uniaxial", "–", "the same",
     "[lowest, highest] stretch of the uniaxial test (0.1 and 10: the ends of the search)"},
    {"material_stability.stable_stretches.equibiaxial", "–", "the same",
     "the same for the equibiaxial test"},
    {"material_stability.stable_stretches.planar", "–", "the same", "the same for the planar test"},
    {"material_stability.regions.<volume>", "–",
     "a region's material not stable over all of 0.1 to 10 in some test",
     "the same ranges for the material of the region with that volume tag (a `box` region: "
     "its key, e.g. `regions[1]`): `uniaxial`, `equibiaxial`, `planar` as above"},
    {"material_stability.regions.<volume>.uniaxial", "–", "the same",
     "[lowest, highest] stretch of the uniaxial test"},
    {"material_stability.regions.<volume>.equibiaxial", "–", "the same",
     "the same for the equibiaxial test"},
    {"material_stability.regions.<volume>.planar", "–", "the same", "the same for the planar test"},
    {"material_stability.first_unstable_step", "–", "a watched material (either above)",
     "the first step with an element whose state is not stable (the log warns then), or null"},
    {"material_stability.unstable_elements", "–", "the same",
     "elements whose state is not stable at the last step"},
    {"material_stability.most_unstable_elements", "–", "the same",
     "the largest number of such elements over the steps of this run"},
    {"stability.checks", "–", "`solver.stability.check`", "states whose inertia was checked"},
    {"stability.check_seconds", "s", "`solver.stability.check`", "time spent on the checks"},
    {"stability.eigenmode_seconds", "s", "`solver.stability.check`",
     "time spent computing eigenmodes"},
    {"stability.stable_at_end", "–", "`solver.stability.check`", "the last state's `stable`"},
    {"stability.instabilities", "–", "`solver.stability.check`",
     "the steps where the state became unstable, in order (empty: none), each with the keys "
     "below"},
    {"stability.instabilities[].step", "–", "`solver.stability.check`",
     "a step where the state became unstable (more negative pivots than the step before)"},
    {"stability.instabilities[].time", "–", "`solver.stability.check`", "its time t"},
    {"stability.instabilities[].negative_pivots", "–", "`solver.stability.check`",
     "negative pivots of the unperturbed state there"},
    {"stability.instabilities[].expected_negative_pivots", "–", "`solver.stability.check`",
     "those of a stable state"},
    {"stability.instabilities[].eigenvalues", "N/mm", "`solver.stability.check`",
     "the lowest eigenvalues of the tangent there, ascending (negative: unstable directions)"},
    {"stability.instabilities[].branch_switched", "–", "`solver.stability.check`",
     "true when the run went on along the first mode (`branch_switch`)"},
    {"stability.instabilities[].perturbation_mm", "mm", "`solver.stability.check`",
     "the amplitude of the mode that switched branch"},
    {"stability.instabilities[].file", "–", "`solver.stability.check`",
     "the step file holding the modes (`mode_1`, `mode_2`, ...)"},
    {"wrinkles.wrinkled", "–", "`output.wrinkles`",
     "true when a ring or a line of the last state is wrinkled"},
    {"wrinkles.max_amplitude", "mm", "`output.wrinkles`", "the largest ring amplitude"},
    {"wrinkles.threshold", "mm", "`output.wrinkles`",
     "the amplitude above which a ring or line is wrinkled (`threshold` × wall thickness)"},
    {"wrinkles.peak_ratio", "–", "`output.wrinkles`", "the option `peak_ratio`"},
    {"wrinkles.min_count", "–", "`output.wrinkles`", "the option `min_count`"},
    {"wrinkles.thickness", "mm", "`output.wrinkles`", "the wall thickness of the case"},
    {"wrinkles.axis", "–", "`output.wrinkles`", "the rings' axis"},
    {"wrinkles.surface", "–", "`output.wrinkles`",
     "the surface the rings lie on and whose tension-field state is counted"},
    {"wrinkles.rings", "–", "`output.wrinkles`",
     "one entry per ring, in the order of `rings_deg` (empty without rings), with the keys below"},
    {"wrinkles.rings[].latitude_deg", "deg", "`output.wrinkles.rings_deg`",
     "the ring's latitude (0 the equator)"},
    {"wrinkles.rings[].decision", "–", "`output.wrinkles.rings_deg`",
     "why the ring is or is not wrinkled (docs/case-file.md, Wrinkle metrics)"},
    {"wrinkles.rings[].count", "–", "`output.wrinkles.rings_deg`",
     "full-circle wave count of the wrinkles (0 when none)"},
    {"wrinkles.rings[].amplitude", "mm", "`output.wrinkles.rings_deg`",
     "peak-to-peak amplitude of the wrinkle band"},
    {"wrinkles.rings[].wavelength", "mm", "`output.wrinkles.rings_deg`",
     "the wrinkles' wavelength along the ring"},
    {"wrinkles.rings[].dominant_count", "–", "`output.wrinkles.rings_deg`",
     "the largest harmonic m ≥ `min_count`, wrinkles or not"},
    {"wrinkles.rings[].residual_amplitude", "mm", "`output.wrinkles.rings_deg`",
     "peak to peak without the harmonics below `min_count`"},
    {"wrinkles.rings[].band", "–", "`output.wrinkles.rings_deg`",
     "the harmonics whose sum is the amplitude"},
    {"wrinkles.rings[].mean_radius", "mm", "`output.wrinkles.rings_deg`",
     "the ring's mean distance from the axis"},
    {"wrinkles.rings[].points", "–", "`output.wrinkles.rings_deg`", "points sampled on the ring"},
    {"wrinkles.rings[].sector_deg", "deg", "`output.wrinkles.rings_deg`",
     "the angle the modelled part spans (90 for a quarter)"},
    {"wrinkles.rings[].spectrum", "mm", "`output.wrinkles.rings_deg`",
     "rows [m, A_m, E_m]: each harmonic's amplitude and the global shape's envelope there"},
    {"wrinkles.lines", "–", "`output.wrinkles.lines`",
     "one entry per measurement line, in the order of `lines`, with the keys below"},
    {"wrinkles.lines[].name", "–", "`output.wrinkles.lines`", "the line's name"},
    {"wrinkles.lines[].wrinkled", "–", "`output.wrinkles.lines`",
     "true when the line has crests whose amplitude is above the threshold (W27)"},
    {"wrinkles.lines[].crests", "–", "`output.wrinkles.lines`",
     "crests and troughs along the line, threshold or not (0 below `min_crests`; W24)"},
    {"wrinkles.lines[].amplitude", "mm", "`output.wrinkles.lines`",
     "the largest height of a crest over the troughs beside it (W25)"},
    {"wrinkles.lines[].wavelength", "mm", "`output.wrinkles.lines`",
     "twice the mean distance between the zeros that separate its crests, along the deformed "
     "line's smooth shape (W26)"},
    {"wrinkles.lines[].reference_wavelength", "mm", "`output.wrinkles.lines`",
     "the same along the undeformed line (the material wavelength)"},
    {"wrinkles.lines[].deviation", "mm", "`output.wrinkles.lines`",
     "peak to peak of the line's deviation from its smooth shape, crests or not (W23)"},
    {"wrinkles.lines[].from", "mm", "`output.wrinkles.lines`", "the line's first end"},
    {"wrinkles.lines[].to", "mm", "`output.wrinkles.lines`", "the line's other end"},
    {"wrinkles.lines[].points", "–", "`output.wrinkles.lines`", "points sampled along it"},
    {"wrinkles.lines[].min_crests", "–", "`output.wrinkles.lines`", "the option `min_crests`"},
    {"wrinkles.lines[].mirror", "–", "`output.wrinkles.lines`",
     "the option `mirror`: the end measured with its mirror image"},
    {"first_wrinkled", "–", "`output.wrinkles`",
     "the first recorded step at which a ring or line was wrinkled (null if none was): the "
     "keys below"},
    {"first_wrinkled.step", "–", "`output.wrinkles`", "its step"},
    {"first_wrinkled.time", "s", "`output.wrinkles`", "its time (load parameter)"},
    {"first_wrinkled.by", "–", "`output.wrinkles`",
     "what was wrinkled: `ring <latitude> deg` or `line <name>`, the one of the largest "
     "amplitude"},
    {"first_wrinkled.stable", "–", "`output.wrinkles`",
     "with `solver.stability.check`, whether the stability check found every step up to it "
     "stable: true means the wrinkles grew without a bifurcation, from the imperfection or the "
     "mesh's own asymmetry (null without the check)"},
    {"wrinkles.tension_field.taut", "–", "`output.wrinkles`",
     "through-thickness columns (of a shell, triangles) in tension both ways"},
    {"wrinkles.tension_field.wrinkled", "–", "`output.wrinkles`",
     "columns (triangles) with one compressive principal membrane stress"},
    {"wrinkles.tension_field.slack", "–", "`output.wrinkles`",
     "columns (triangles) with two compressive principal membrane stresses"},
    {"probes[].name", "–", "`probes[]`", "the probe's name"},
    {"probes[].point", "mm", "`probes[]`", "the point as given, [x, y, z]"},
    {"probes[].position", "mm", "`probes[]`",
     "the point of the mesh the probe reports at, [x, y, z] in the undeformed body"},
    {"probes[].distance", "mm", "`probes[]`",
     "the distance between the two: 0 (to rounding) inside the body; on a curved surface, how far "
     "the mesh's facets are from the point"},
    {"probes[].inside", "–", "`probes[]`",
     "true when the point lies in an element; false when it was taken to the nearest point of "
     "the body's surface"},
    {"probes[].element", "–", "`probes[]`",
     "the element holding the probe (0-based, the VTU cell index)"},
    {"final.<column>", "as the column", "at least one step",
     "every history.csv column at the last converged step"},
};

const std::vector<OutputEntry> kVtuPoint = {
    {"displacement", "mm", "always", "u = x − X, 3 components"},
    {"velocity", "mm", "always",
     "the displacement's change over the step divided by the step's Δt (3 components; Δt in "
     "units of the load parameter t, so not a physical speed)"},
    {"pressure", "MPa", "always",
     "the pressure unknown p, positive in compression (σ = −p I + the isochoric part); on a "
     "Taylor-Hood mesh's edge nodes the mean of the edge's corners; at a node where regions "
     "with pressures of their own meet (`region_pressure`), the first region's (each element's "
     "own: cell field `element_pressure`); 0 on a shell, which has no pressure unknown (its cell "
     "field "
     "`pressure`)"},
    {"reaction", "N", "always",
     "the force the constraints exert on the body at each node (3 components): zero on the free "
     "components, the nodal reaction on the prescribed ones; summed over a surface it is "
     "`force_x:<boundary>` ..."},
    {"thickness", "mm", "a shell or sheet (the mesh has a wall thickness and wall faces)",
     "the current wall thickness at the node: its distance to one face of the wall plus its "
     "distance to the other (\"Wall thickness\" below)"},
    {"mode_<k>", "–", "the step where stability was lost (`solver.stability.modes`)",
     "the displacement part of the k-th lowest eigenmode of the tangent (a shape: its scale is "
     "arbitrary)"},
};

const std::vector<OutputEntry> kVtuCell = {
    {"cauchy_stress", "MPa", "always",
     "the element's volume average of the Cauchy stress σ, 6 components xx, yy, zz, xy, yz, xz, "
     "tension positive; of a shell, its average through the thickness"},
    {"von_mises", "MPa", "always", "√(3/2 dev σ̄ : dev σ̄) of that average"},
    {"element_pressure", "MPa", "a solid mesh",
     "the element's volume average of its pressure field p, positive in compression: where "
     "regions with pressures of their own meet (`region_pressure`), its region's, which the "
     "point field `pressure` shows for the first region only"},
    {"J", "–", "always",
     "the element's volume average of det F (of a shell, its average through the thickness: 1 "
     "when exactly incompressible)"},
    {"principal_stretches", "–", "always",
     "λ1 ≥ λ2 ≥ λ3, the square roots of the eigenvalues of C = Fᵀ F of the element's average F "
     "(3 components); on a membrane the smallest is usually the through-thickness stretch; of a "
     "shell, the F of its mid-surface"},
    {"principal_stresses", "MPa", "always",
     "σ1 ≥ σ2 ≥ σ3, the eigenvalues of the element's average Cauchy stress (3 components), "
     "tension positive"},
    {"material", "–", "`regions`",
     "the element's material: 0 the case's `material`, k the k-th region with a material (in "
     "the order of `regions`), −1 a rigid region"},
    {"wrinkle_state", "–", "`output.wrinkles.rings_deg`",
     "the tension-field state of the element's through-thickness column: 0 taut, 1 wrinkled, "
     "2 slack; of a shell, of the triangle itself, from its stress averaged through the "
     "thickness"},
    {"pressure", "MPa", "a shell mesh",
     "−tr σ̄ / 3 of the stress averaged through the thickness, positive in compression: the "
     "pressure that plane stress eliminated (a solid element's pressure field for the isotropic "
     "models)"},
    {"thickness", "mm", "a shell mesh",
     "the current thickness t λ3 of the mid-surface, λ3 its thickness stretch (1/(λ1 λ2) when "
     "exactly incompressible)"},
    {"membrane_force", "N/mm", "a shell mesh",
     "the membrane force per unit current length N = ∫ σ dz over the current thickness, a "
     "symmetric tensor tangent to the deformed mid-surface in the global axes (6 components as "
     "`cauchy_stress`), tension positive: N · m is the force per length on a cut of unit "
     "normal m in the surface; t λ3 σ on a flat sheet in a homogeneous stretch"},
    {"bending_moment", "N", "a shell mesh",
     "the bending moment per unit current length M = ∫ σ z dz, z the current distance from the "
     "mid-surface towards the top face (6 components as `cauchy_stress`; N mm/mm): positive where "
     "the top face is in tension; (μ t³/6)(κ + tr κ I) with κ = `curvature_change` when an "
     "incompressible sheet bends a little, of size D/R across a cylinder of radius R, D = μ t³/3"},
    {"curvature_change", "1/mm", "a shell mesh",
     "κ = B − b, the reference curvature minus the current one (docs/theory/shell.md, KL7), as "
     "a symmetric tensor in the global axes of the reference triangle's plane (6 components as "
     "`cauchy_stress`); its nonzero eigenvalues are the principal changes of curvature, "
     "negative where the surface curves further towards the top face"},
    {"cauchy_stress_bottom", "MPa", "a shell mesh",
     "the Cauchy stress at the bottom face of the shell (6 components as `cauchy_stress`): the "
     "face the triangles' normals point away from (a generated shell's `inner` or `bottom`)"},
    {"cauchy_stress_middle", "MPa", "a shell mesh", "the Cauchy stress at the mid-surface"},
    {"cauchy_stress_top", "MPa", "a shell mesh",
     "the Cauchy stress at the top face, the one the triangles' normals point out of (`outer`, "
     "`top`)"},
    {"principal_stretches_bottom", "–", "a shell mesh",
     "λ1 ≥ λ2 ≥ λ3 at the bottom face (3 components), λ3 the thickness stretch there"},
    {"principal_stretches_middle", "–", "a shell mesh",
     "the principal stretches at the mid-surface"},
    {"principal_stretches_top", "–", "a shell mesh", "the principal stretches at the top face"},
};

/// The literal characters of a pattern (its length without the `<...>` parts).
std::size_t literal_length(std::string_view pattern) {
  std::size_t n = 0;
  for (bool inside = false; char ch : pattern) {
    if (ch == '<') inside = true;
    if (!inside) ++n;
    if (ch == '>') inside = false;
  }
  return n;
}

/// Whether `name` matches `pattern`, where each `<...>` matches one or more characters.
bool matches(std::string_view pattern, std::string_view name) {
  const std::size_t open = pattern.find('<');
  if (open == std::string_view::npos) return pattern == name;
  const std::size_t close = pattern.find('>', open);
  if (close == std::string_view::npos) return false;
  if (name.substr(0, open) != pattern.substr(0, open)) return false;
  const std::string_view rest = pattern.substr(close + 1);
  for (std::size_t cut = open + 1; cut <= name.size(); ++cut)
    if (matches(rest, name.substr(cut))) return true;
  return false;
}

const char* table_name(OutputTable table) {
  switch (table) {
    case OutputTable::history:
      return "history.csv column";
    case OutputTable::summary:
      return "summary.json key";
    case OutputTable::vtu_point:
      return "VTU point field";
    case OutputTable::vtu_cell:
      return "VTU cell field";
  }
  return "output";
}

/// `text` with '|' escaped, for a markdown table cell.
std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return out;
}

/// `before`, then the term kinds' entries (`of` picks the list; an entry that several kinds share
/// once), then `after`.
std::vector<OutputEntry> with_term_outputs(const std::vector<OutputEntry>& before,
                                           std::vector<OutputEntry> TermKind::*of,
                                           const std::vector<OutputEntry>& after) {
  std::vector<OutputEntry> out = before;
  for (const TermKind& kind : term_kinds())
    for (const OutputEntry& entry : kind.*of)
      if (std::none_of(out.begin(), out.end(),
                       [&](const OutputEntry& e) { return e.name == entry.name; }))
        out.push_back(entry);
  out.insert(out.end(), after.begin(), after.end());
  return out;
}

}  // namespace

std::vector<std::string> output_reference_sections() {
  return {"history", "summary", "vtu-point", "vtu-cell"};
}

const std::vector<OutputEntry>& output_reference(OutputTable table) {
  static const std::vector<OutputEntry> history =
      with_term_outputs(kHistoryBefore, &TermKind::history, kHistoryAfter);
  static const std::vector<OutputEntry> vtu_point =
      with_term_outputs(kVtuPoint, &TermKind::point_fields, {});
  switch (table) {
    case OutputTable::history:
      return history;
    case OutputTable::summary:
      return kSummary;
    case OutputTable::vtu_point:
      return vtu_point;
    case OutputTable::vtu_cell:
      return kVtuCell;
  }
  return history;
}

const OutputEntry* find_output_entry(OutputTable table, std::string_view name) {
  const OutputEntry* best = nullptr;
  for (const OutputEntry& e : output_reference(table))
    if (matches(e.name, name) && (!best || literal_length(e.name) > literal_length(best->name)))
      best = &e;
  return best;
}

void require_output_entry(OutputTable table, std::string_view name) {
  PLISSE_CHECK(find_output_entry(table, name),
               "the " << table_name(table) << " '" << name
                      << "' has no entry in the output reference (app/output_reference.cpp, "
                         "docs/output.md)");
}

namespace {

void require_documented(const nlohmann::json& value, const std::string& path) {
  if (value.is_object()) {
    for (const auto& [key, item] : value.items())
      require_documented(item, path.empty() ? key : path + "." + key);
    return;
  }
  if (value.is_array() && !value.empty() && value.front().is_object()) {
    for (const auto& item : value) require_documented(item, path + "[]");
    return;
  }
  require_output_entry(OutputTable::summary, path);
}

}  // namespace

void require_documented_summary(const nlohmann::json& summary) { require_documented(summary, ""); }

std::string output_reference_markdown(const std::string& section) {
  OutputTable table = OutputTable::history;
  std::string head = "| column | unit | written | meaning |\n|---|---|---|---|\n";
  if (section == "summary") {
    table = OutputTable::summary;
    head = "| key | unit | written | meaning |\n|---|---|---|---|\n";
  } else if (section == "vtu-point" || section == "vtu-cell") {
    table = section == "vtu-point" ? OutputTable::vtu_point : OutputTable::vtu_cell;
    head = "| field | unit | written | meaning |\n|---|---|---|---|\n";
  } else if (section != "history") {
    throw Error("no output reference section '" + section +
                "' (history, summary, vtu-point, vtu-cell)");
  }
  std::string text = head;
  for (const OutputEntry& e : output_reference(table))
    text += "| `" + e.name + "` | " + markdown_cell(e.unit) + " | " + markdown_cell(e.when) +
            " | " + markdown_cell(e.meaning) + " |\n";
  return text;
}

}  // namespace plisse::app
