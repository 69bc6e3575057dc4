// Distributed runs (`plisse run -n 2`) give the results of a one-rank run to solver tolerance:
// every history column, the counts of summary.json (steps, Newton iterations, instabilities,
// wrinkle rings) and the fields of the final VTU, read back from the ranks' pieces through the
// .pvtu. The cases exercise every kind of term a run distributes:
//  - the paper's indentation, coarsened (R = 12 mm, element 3 mm): follower pressure, a
//    frictionless moving die and a sticking die, the stability check and wrinkle rings;
//  - the clamped strip shortened past its Euler load (tests/regression/cases/strip-buckling.yaml):
//    an instability, its eigenmodes (SLEPc on the distributed tangent) and branch switching, and
//    a mode imperfection read back from the .pvtu of the distributed run;
//  - the paper's cube tension with the iterative linear solver on two ranks against the closed
//    form (homogeneous deformation);
//  - a strip under a point force, a dead resultant, a follower traction and a rigid end cap
//    (tests/regression/cases/strip-loads.yaml).
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/vtu_reader.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;
using test::example;
using test::run_plisse_captured;
using test::scratch_directory;

const std::string kStrip =
    std::string(PLISSE_SOURCE_DIR) + "/tests/regression/cases/strip-buckling.yaml";
const std::string kCoarseIndentation =
    " --set mesh.element_size=3 --set mesh.inner_radius=12 --set dies[0].point=[0,15,0]"
    " --set dies[1].point=[0,-13,0] --set dies[0].move.displacement=[0,-4,0]"
    " --set probes[0].point=[0,13,0]"
    " --set output.wrinkles.rings_deg=[30,50]";

/// Runs `plisse run CASE ARGS` on `ranks` ranks into a fresh directory; returns the directory.
fs::path run(const std::string& name, const std::string& case_file, const std::string& args,
             int ranks) {
  const fs::path dir = scratch_directory("distributed-" + name + "-" + std::to_string(ranks));
  const auto r = run_plisse_captured("run -n " + std::to_string(ranks) + " '" + case_file +
                                     "' -o '" + dir.string() + "'" + args);
  EXPECT_EQ(r.status, 0) << r.output;
  return dir;
}

/// Columns that belong together (the components of a stress, a force, a moment, a displacement, a
/// position or a rotation vector): a component that is zero up to rounding is compared on the
/// scale of its largest sibling.
std::string column_group(const std::string& name) {
  const std::size_t colon = name.find(':');
  const std::string suffix = colon == std::string::npos ? "" : name.substr(colon);
  if (name.rfind("cauchy_", 0) == 0) return "cauchy";
  if (name.rfind("stretch", 0) == 0) return "stretch";
  if (name.rfind("stress_", 0) == 0) return "stress" + suffix;  // a probe's principal stresses
  if (name.size() > 1 && name[1] == ':' && (name[0] == 'x' || name[0] == 'y' || name[0] == 'z'))
    return "position" + suffix;  // a probe's deformed position
  // The whole body's force is on the scale of the modelled part's (a component that a mirror
  // plane cancels leaves the others at rounding).
  if (name.rfind("full_force_", 0) == 0) return "force_" + suffix;
  for (const char* vector : {"force_", "load_", "moment_"})
    if (name.rfind(vector, 0) == 0) return vector + suffix;
  // ux:<name> ... (displacements), rx:<name> ... (a cap's rotation vector)
  if (name.size() > 2 && (name[0] == 'u' || name[0] == 'r') && name[2] == ':')
    return name.substr(0, 1) + suffix;
  return name;
}

/// Every column of two histories agrees to `tolerance` relative to the largest magnitude of its
/// group (column_group).
void expect_same_history(const fs::path& a, const fs::path& b, double tolerance) {
  const HistoryTable ha = read_history(a / "history.csv"), hb = read_history(b / "history.csv");
  ASSERT_EQ(ha.columns, hb.columns);
  ASSERT_EQ(ha.rows.size(), hb.rows.size());
  for (std::size_t k = 0; k < ha.columns.size(); ++k) {
    const std::string& name = ha.columns[k];
    if (name == "residual_norm") continue;  // below the tolerance by definition, not reproducible
    double scale = 0.0;
    for (std::size_t j = 0; j < ha.columns.size(); ++j)
      if (column_group(ha.columns[j]) == column_group(name))
        for (const auto& row : ha.rows) scale = std::max(scale, std::abs(row[j]));
    for (std::size_t i = 0; i < ha.rows.size(); ++i)
      EXPECT_NEAR(ha.rows[i][k], hb.rows[i][k], tolerance * scale + 1e-300)
          << "column " << name << ", step " << i + 1;
  }
}

/// The largest difference of a point field between two step files, relative to its largest value.
double field_difference(const fs::path& a, const fs::path& b, const std::string& name) {
  const VtuField fa = read_vtu_point_field(a, name), fb = read_vtu_point_field(b, name);
  EXPECT_EQ(fa.values.size(), fb.values.size());
  double scale = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < std::min(fa.values.size(), fb.values.size()); ++i) {
    scale = std::max(scale, std::abs(fa.values[i]));
    difference = std::max(difference, std::abs(fa.values[i] - fb.values[i]));
  }
  return scale > 0 ? difference / scale : difference;
}

/// The last step file of a run of `steps` steps on one rank (.vtu) and on two (.pvtu of two
/// pieces): the same points, and each of `fields` the same to 1e-6 of its largest value.
void expect_last_step_the_same(const fs::path& one, const fs::path& two, int steps,
                               const std::vector<std::string>& fields) {
  const std::string number = std::to_string(steps);
  const std::string last = "step_" + std::string(4 - number.size(), '0') + number;
  ASSERT_TRUE(fs::exists(two / (last + "_p0.vtu")));
  ASSERT_TRUE(fs::exists(two / (last + "_p1.vtu")));
  EXPECT_EQ(read_vtu_point_count(one / (last + ".vtu")),
            read_vtu_point_count(two / (last + ".pvtu")));
  for (const std::string& field : fields)
    EXPECT_LT(field_difference(one / (last + ".vtu"), two / (last + ".pvtu"), field), 1e-6)
        << field;
  EXPECT_EQ(read_vtu_summary(one / (last + ".vtu")).n_cells,
            read_vtu_summary(two / (last + ".pvtu")).n_cells);
}

/// The coarse indentation on one and two ranks (`label`, `args` added to kCoarseIndentation).
void expect_indentation_the_same(const std::string& label, const std::string& args) {
  SCOPED_TRACE(label);
  const fs::path one = run(label, example("sphere-indentation.yaml"), kCoarseIndentation + args, 1);
  const fs::path two = run(label, example("sphere-indentation.yaml"), kCoarseIndentation + args, 2);
  // Newton stops at rtol 1e-8 of the residual: the states agree to about that.
  expect_same_history(one, two, 1e-6);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  EXPECT_EQ(s1["ranks"], 1);
  EXPECT_EQ(s2["ranks"], 2);
  for (const char* key : {"steps", "newton_iterations", "cutbacks", "free_dofs", "completed"})
    EXPECT_EQ(s1[key], s2[key]) << key;
  EXPECT_EQ(s1["stability"]["instabilities"].size(), s2["stability"]["instabilities"].size());
  ASSERT_EQ(s1["wrinkles"]["rings"].size(), s2["wrinkles"]["rings"].size());
  for (std::size_t i = 0; i < s1["wrinkles"]["rings"].size(); ++i)
    EXPECT_EQ(s1["wrinkles"]["rings"][i]["count"], s2["wrinkles"]["rings"][i]["count"]);
  // The last step: one VTU against the .pvtu of two pieces.
  expect_last_step_the_same(one, two, s1["steps"].get<int>(), {"displacement", "pressure"});
}

TEST(DistributedRun, IndentationIsTheSameOnOneAndTwoRanks) {
  expect_indentation_the_same("indentation", "");
}

// The Taylor-Hood element (10-node tetrahedra: the ranks' pieces carry the edge nodes too) on the
// balloon through its pressure maximum (a cavity: a global unknown coupled to every wall node).
TEST(DistributedRun, TaylorHoodBalloonIsTheSameOnOneAndTwoRanks) {
  const std::string args =
      " --set element=taylor-hood --set mesh.element_size=4 --set mesh.layers=1";
  const fs::path one = run("balloon-taylor-hood", example("balloon-limit-point.yaml"), args, 1);
  const fs::path two = run("balloon-taylor-hood", example("balloon-limit-point.yaml"), args, 2);
  expect_same_history(one, two, 1e-6);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  EXPECT_EQ(s2["ranks"], 2);
  EXPECT_EQ(s2["element"], "taylor-hood");
  for (const char* key : {"steps", "newton_iterations", "free_dofs", "completed"})
    EXPECT_EQ(s1[key], s2[key]) << key;
  EXPECT_EQ(s1["steps"], 40);
  expect_last_step_the_same(one, two, 40, {"displacement", "pressure"});
}

// The shell (12-node patches: the ranks' pieces carry the nodes across the neighbours' sides,
// and the mirror images of the symmetry edges) on the party balloon through its pressure maximum,
// with wrinkle metrics on the mid-surface. Measured on the example's own mesh (element_size
// 2.5 mm): the time and pressure columns agree to 2.6e-12.
TEST(DistributedRun, ShellBalloonIsTheSameOnOneAndTwoRanks) {
  const std::string args =
      " --set mesh.element_size=5 --set output.wrinkles.rings_deg=[30,60] --set "
      "output.wrinkles.axis=y";
  const fs::path one = run("balloon-shell", example("shell-balloon.yaml"), args, 1);
  const fs::path two = run("balloon-shell", example("shell-balloon.yaml"), args, 2);
  expect_same_history(one, two, 1e-6);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  EXPECT_EQ(s2["ranks"], 2);
  EXPECT_EQ(s2["element"], "shell");
  // The iterations of the attempts that failed and were cut back may differ (measured 64 and
  // 72 at this mesh: the two ranks' factorisations pivot differently, and an attempt that does
  // not converge stops at a different iteration); the converged ones (28) and the cut-backs (4)
  // do not.
  EXPECT_EQ(s1["newton_iterations"].get<int>() - s1["failed_newton_iterations"].get<int>(),
            s2["newton_iterations"].get<int>() - s2["failed_newton_iterations"].get<int>());
  for (const char* key : {"steps", "cutbacks", "free_dofs", "completed"})
    EXPECT_EQ(s1[key], s2[key]) << key;
  expect_last_step_the_same(one, two, s1["steps"].get<int>(), {"displacement"});
  // A shell run orders its factorisations from MUMPS's analysis of the whole first tangent
  // (solver/linear_solver.hpp, choose_factor_ordering), and says so: the same on both.
  const auto ordering = [](const fs::path& run) {
    std::ifstream in(run / "log.txt");
    for (std::string line; std::getline(in, line);)
      if (const auto at = line.find("factorisations: ordered by"); at != std::string::npos)
        return line.substr(at);
    return std::string();
  };
  EXPECT_FALSE(ordering(one).empty()) << "no ordering in " << (one / "log.txt").string();
  EXPECT_EQ(ordering(one), ordering(two));
}

// Arc-length control (solver/arc_length.hpp): the arc's norms and dot products are over the
// ranks' pieces of the free vectors, and its predictor's orientation over the whole increment; the
// Mooney-Rivlin balloon followed through its pressure maximum and minimum takes the same steps
// and path on two ranks (measured: the histories agree to 1.6e-15).
TEST(DistributedRun, ArcLengthBalloonIsTheSameOnOneAndTwoRanks) {
  const fs::path one = run("balloon-arc-length", example("shell-balloon-arc-length.yaml"), "", 1);
  const fs::path two = run("balloon-arc-length", example("shell-balloon-arc-length.yaml"), "", 2);
  expect_same_history(one, two, 1e-10);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  EXPECT_EQ(s2["ranks"], 2);
  for (const char* key : {"steps", "cutbacks", "completed"}) EXPECT_EQ(s1[key], s2[key]) << key;
}

// A pressurised Taylor-Hood sphere resting with its pole, a corner node, on a sticking floor: the
// pole is tied from t = 0 (contact.md, D17), so the rigid motion normal to the floor is not left
// to the linear solver and both runs follow the same path.
TEST(DistributedRun, TaylorHoodSphereOnAStickingFloorIsTheSameOnOneAndTwoRanks) {
  const std::string plates =
      std::string(PLISSE_SOURCE_DIR) + "/tests/verification/contact/sphere-between-plates.yaml";
  const std::string args = " --set element=taylor-hood";
  const fs::path one = run("plates-taylor-hood", plates, args, 1);
  const fs::path two = run("plates-taylor-hood", plates, args, 2);
  expect_same_history(one, two, 1e-6);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  for (const char* key : {"steps", "newton_iterations", "free_dofs", "completed"})
    EXPECT_EQ(s1[key], s2[key]) << key;
}

// A rigid cap (a multiplier per tied node and component, and free motions: global unknowns owned
// by the last rank), a point force, a dead resultant and a follower traction on one strip.
TEST(DistributedRun, CapAndTractionsAreTheSameOnTwoRanks) {
  const std::string strip =
      std::string(PLISSE_SOURCE_DIR) + "/tests/regression/cases/strip-loads.yaml";
  const fs::path one = run("strip-loads", strip, "", 1);
  const fs::path two = run("strip-loads", strip, "", 2);
  expect_same_history(one, two, 1e-9);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  for (const char* key : {"steps", "newton_iterations", "free_dofs", "completed"})
    EXPECT_EQ(s1[key], s2[key]) << key;
}

// Regions (examples/sheet-patch-grips.yaml, coarsened): a patch of its own material, assembled by
// whichever rank holds it, with pressure unknowns of its own where it meets the sheet (twin nodes,
// which the partition hands out like any node), and two rigid grips whose elements no rank
// assembles and whose nodes every rank constrains alike. Also what the example says: the grips'
// forces balance and the stiff patch stretches less than the sheet beside it.
TEST(DistributedRun, RegionsOfTheirOwnMaterialAndRigidGripsAreTheSameOnTwoRanks) {
  const std::string args = " --set mesh.element_size=5 --set solver.steps=5";
  const fs::path one = run("patch-grips", example("sheet-patch-grips.yaml"), args, 1);
  const fs::path two = run("patch-grips", example("sheet-patch-grips.yaml"), args, 2);
  expect_same_history(one, two, 1e-6);
  const nlohmann::json s1 = read_json_file(one / "summary.json"),
                       s2 = read_json_file(two / "summary.json");
  for (const char* key : {"steps", "newton_iterations", "free_dofs", "pressure_twins", "completed"})
    EXPECT_EQ(s1[key], s2[key]) << key;
  EXPECT_GT(s1["pressure_twins"].get<int>(), 0) << "the patch has pressures of its own";
  const HistoryTable h = read_history(one / "history.csv");
  ASSERT_FALSE(h.rows.empty());
  const auto at_end = [&](const std::string& name) {
    const auto k = std::find(h.columns.begin(), h.columns.end(), name);
    EXPECT_NE(k, h.columns.end()) << name;
    return k == h.columns.end() ? NAN : h.rows.back()[std::size_t(k - h.columns.begin())];
  };
  const double pull = at_end("force_x:right_grip");
  EXPECT_GT(pull, 0.0) << "the moved grip pulls the sheet along +x";
  EXPECT_NEAR(at_end("force_x:left_grip"), -pull, 1e-8 * pull) << "the grips balance";
  EXPECT_LT(at_end("stretch_1:patch") - 1.0, 0.2 * (at_end("stretch_1:sheet") - 1.0));
}

// Viscoelasticity and Mullins softening: each rank updates the history of the points of its own
// elements, and the checkpoint gathers every element's from its owner. A sticking cube pulled
// (first run), then let half way back in a second run from the first one's checkpoint (its
// history included), gives the same histories on one and two ranks.
TEST(DistributedRun, ViscoelasticAndMullinsHistoryIsTheSameOnTwoRanks) {
  const std::string cube = std::string(PLISSE_SOURCE_DIR) + "/tests/regression/restart-case.yaml";
  const std::string material =
      " --set 'material={model: mooney-rivlin, c1: 0.2, c2: 0.05, viscoelastic: {beta1: 0.8, "
      "tau1: 0.3}, mullins: {r: 2, m: 0.1}}' --set solver.steps=6"
      // Full Newton steps where the load turns back (docs/theory/materials.md, "Solving").
      " --set solver.newton.line_search=basic";
  const fs::path one = run("inelastic", cube, material, 1);
  const fs::path two = run("inelastic", cube, material, 2);
  expect_same_history(one, two, 1e-8);
  const std::string back = material + " --set 'boundary[1].ramp=[[0, 1], [1, 0.5]]' --from ";
  const fs::path one_back = run("inelastic-back", cube, back + one.string(), 1);
  const fs::path two_back = run("inelastic-back", cube, back + two.string(), 2);
  expect_same_history(one_back, two_back, 1e-8);
  // The load turns back at every point's largest energy: with full Newton steps and the bubble
  // solve's damping (docs/theory/materials.md, MR6) no step is cut back.
  for (const fs::path& dir : {one_back, two_back})
    EXPECT_EQ(read_json_file(dir / "summary.json")["cutbacks"].get<int>(), 0) << dir;
  // The second run starts from the first one's history: let back to 5 mm after the pull to 10, the
  // softened and relaxing cube pulls on the die less than a fresh one pulled to 5 mm.
  const fs::path fresh =
      run("inelastic-fresh", cube, material + " --set 'boundary[1].value=[0.0, 0.0, 5.0]'", 1);
  const auto die_force = [](const fs::path& dir) {
    const HistoryTable h = read_history(dir / "history.csv");
    const auto k = std::find(h.columns.begin(), h.columns.end(), "force_z:die");
    EXPECT_NE(k, h.columns.end());
    return k == h.columns.end() ? NAN : h.rows.back()[std::size_t(k - h.columns.begin())];
  };
  EXPECT_GT(die_force(one_back), 0.0);
  EXPECT_LT(die_force(one_back), die_force(fresh));
}

TEST(DistributedRun, SelfContactAndContactPatchTestAreTheSameOnTwoRanks) {
  // The pillow's contact pairs change and its tangent's sparsity grows as the faces approach
  // (surface-contact.md, N4 and N6); every rank finds the same pairs from the same state.
  const std::string pillow = std::string(PLISSE_SOURCE_DIR) + "/examples/pillow-deflated.yaml";
  expect_same_history(run("pillow", pillow, "", 1), run("pillow", pillow, "", 2), 1e-6);
  // The same as a shell: the faces half a wall off the mid-surfaces (N14).
  const std::string shell = " --set element=shell";
  expect_same_history(run("pillow-shell", pillow, shell, 1), run("pillow-shell", pillow, shell, 2),
                      1e-6);
  const std::string blocks =
      std::string(PLISSE_SOURCE_DIR) + "/tests/verification/contact/two-blocks-pressed.yaml";
  expect_same_history(run("blocks", blocks, "", 1), run("blocks", blocks, "", 2), 1e-8);
}

TEST(DistributedRun, BucklingModesAndBranchSwitchingAreTheSameOnTwoRanks) {
  const std::string args = " --set solver.stability.branch_switch=true";
  const fs::path one = run("strip", kStrip, args, 1);
  const fs::path two = run("strip", kStrip, args, 2);
  expect_same_history(one, two, 1e-6);
  const nlohmann::json i1 = read_json_file(one / "summary.json")["stability"]["instabilities"];
  const nlohmann::json i2 = read_json_file(two / "summary.json")["stability"]["instabilities"];
  ASSERT_EQ(i1.size(), 1u);
  ASSERT_EQ(i2.size(), 1u);
  EXPECT_EQ(i1[0]["step"], i2[0]["step"]);
  EXPECT_EQ(i1[0]["negative_pivots"], i2[0]["negative_pivots"]);
  EXPECT_EQ(i2[0]["branch_switched"], true);
  ASSERT_EQ(i1[0]["eigenvalues"].size(), i2[0]["eigenvalues"].size());
  for (std::size_t k = 0; k < i1[0]["eigenvalues"].size(); ++k) {
    const double a = i1[0]["eigenvalues"][k], b = i2[0]["eigenvalues"][k];
    EXPECT_NEAR(a, b, 1e-6 * std::abs(a)) << "eigenvalue " << k;
  }
  // The buckling mode, normalised alike (largest nodal |u| = 1, positive largest component).
  const std::string file1 = i1[0]["file"], file2 = i2[0]["file"];
  EXPECT_EQ(fs::path(file2).extension(), ".pvtu");
  EXPECT_LT(field_difference(one / file1, two / file2, "mode_1"), 1e-6);
  // The partition is deterministic: a second run on 2 ranks cuts the mesh into the same pieces and
  // follows the same path. Not byte for byte: MUMPS assembles the contributions of the two ranks
  // in the order they arrive, which changes the last bits of a factorisation from run to run
  // (seen here as 1e-16 relative differences after a dozen steps).
  const fs::path again = run("strip-again", kStrip, args, 2);
  expect_same_history(two, again, 1e-9);
  const std::string last_piece = fs::path(file2).stem().string();
  for (const char* piece : {"_p0.vtu", "_p1.vtu"})
    EXPECT_EQ(read_vtu_point_count(two / (last_piece + piece)),
              read_vtu_point_count(again / (last_piece + piece)))
        << piece;
  // A mode imperfection read from the distributed run's .pvtu seeds the same run as one read from
  // the one-rank run's .vtu.
  const auto seeded = [&](const fs::path& source) {
    return " --set solver.stability.imperfection=0.01 --set solver.stability.imperfection_kind=mode"
           " --set solver.stability.imperfection_from='" +
           source.string() + "'";
  };
  expect_same_history(run("strip-seeded-by-1", kStrip, seeded(one), 1),
                      run("strip-seeded-by-2", kStrip, seeded(two), 1), 1e-6);
}

TEST(DistributedRun, IterativeSolverOnTwoRanksMatchesTheClosedForm) {
  // Homogeneous uniaxial tension of the neo-Hookean cube: sigma_zz = 2 c1 (lambda^2 - 1/lambda).
  const std::string args =
      " --set solver.newton.linear.type=iterative --set solver.newton.linear.rtol=1e-10";
  const fs::path two = run("cube-iterative", example("cube-tension-neo-hookean.yaml"), args, 2);
  const HistoryTable h = read_history(two / "history.csv");
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(h.columns.begin(), h.columns.end(), name) -
                                    h.columns.begin());
  };
  ASSERT_LT(col("cauchy_zz"), h.columns.size());
  ASSERT_LT(col("stretch"), h.columns.size());
  ASSERT_GE(h.rows.size(), 3u);
  EXPECT_NEAR(h.rows.back()[col("stretch")], 5.0, 1e-9);
  const double c1 = 0.25;  // examples/cube-tension-neo-hookean.yaml
  for (const auto& row : h.rows) {
    const double lambda = row[col("stretch")];
    const double exact = 2.0 * c1 * (lambda * lambda - 1.0 / lambda);
    EXPECT_NEAR(row[col("cauchy_zz")], exact, 1e-6 * exact) << "stretch " << lambda;
  }
  // Against the direct solver on one rank without factor reuse, which the iterative solver does
  // not have: the Newton iteration counts are compared too.
  const fs::path one = run("cube-direct", example("cube-tension-neo-hookean.yaml"),
                           " --set solver.newton.reuse_factor=false", 1);
  expect_same_history(one, two, 1e-6);
}

/// Two ranks started by the launcher itself, as a user's `mpirun -n 2 plisse run ...`.
const std::string kMpiexec2 =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
    "OMPI_MCA_rmaps_base_oversubscribe=1 mpiexec -q -n 2 ";

TEST(DistributedRun, RankCountOutsideTheJobIsABadInput) {
  // Inside an MPI job of 2 ranks, -n must say 2.
  const fs::path dir = scratch_directory("distributed-mismatch");
  const auto r = run_plisse_captured(
      "run -n 3 '" + example("cube-tension-neo-hookean.yaml") + "' -o '" + dir.string() + "'",
      kMpiexec2);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("-n 3 inside an MPI job of 2 ranks"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "history.csv"));
}

TEST(DistributedRun, WrinklesIsRefusedInsideAnMpiJob) {
  // Its copies would each take the run directory's lock and all but one be refused: each says
  // why instead, before touching the directory.
  const fs::path dir = scratch_directory("distributed-wrinkles");
  const auto r = run_plisse_captured("wrinkles '" + dir.string() + "'", kMpiexec2);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("plisse wrinkles runs on one process, not in an MPI job (here of 2 "
                          "ranks)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir));
}

TEST(DistributedRun, BadCaseIsRefusedBeforeTheRanksStart) {
  const auto r = run_plisse_captured("run -n 2 '" + example("cube-tension-neo-hookean.yaml") +
                                     "' --set mesh.divisions=0 -o '" +
                                     scratch_directory("distributed-bad").string() + "'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("mesh.divisions"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("mpiexec"), std::string::npos) << r.output;  // no launcher banner
}

TEST(DistributedRun, LaunchersStartTheRanksWithoutARankCount) {
  // mpirun -n 2 plisse run CASE: the ranks take the job's size; -n after `run` is optional.
  const fs::path dir = scratch_directory("distributed-launcher");
  const auto r = run_plisse_captured(
      "run '" + example("cube-tension-neo-hookean.yaml") + "' -o '" + dir.string() + "'",
      kMpiexec2);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_json_file(dir / "summary.json")["ranks"].get<int>(), 2);
}

TEST(DistributedRun, MoreRanksThanCpusOnlyWhenAskedFor) {
  const std::string command = "run -n 4096 '" + example("cube-tension-neo-hookean.yaml") +
                              "' -o '" + scratch_directory("distributed-too-many").string() + "'";
  const auto r = run_plisse_captured(command);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("-n 4096 is more ranks than the "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("mpiexec"), std::string::npos) << r.output;  // refused before it starts
}

/// Runs the two-rank job `command` (a shell command) and, as soon as `dir/trigger` appears,
/// creates the directory `dir/blocked`. Returns whether that directory was made before anything
/// stood at its name (so that the job's later write there fails); the job's exit status goes to
/// `status`. An obstacle planted before the run starts would be refused by the run's own checks
/// before its first step: it has to appear while the run goes on.
bool plant_during_run(const std::string& command, const fs::path& dir, const std::string& trigger,
                      const std::string& blocked, int& status) {
  const int watch = inotify_init1(IN_CLOEXEC);
  EXPECT_GE(watch, 0);
  EXPECT_GE(inotify_add_watch(watch, dir.c_str(), IN_CREATE | IN_MOVED_TO), 0);
  const pid_t launcher = fork();
  if (launcher == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  bool planted = false;
  // Events until the trigger's; the job ending first (it failed early) leaves the loop through
  // poll's timeout.
  alignas(inotify_event) char buffer[4096];
  for (bool seen = false; !seen;) {
    pollfd ready{watch, POLLIN, 0};
    if (poll(&ready, 1, 1000) <= 0) {
      if (waitpid(launcher, &status, WNOHANG) == launcher) {
        close(watch);
        return false;
      }
      continue;
    }
    const ssize_t n = read(watch, buffer, sizeof buffer);
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      if (event->len > 0 && trigger == event->name) seen = true;
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
  // mkdir fails if the file is already there: the job got past that write, and the attempt is
  // void (reported, not counted as a pass).
  planted = ::mkdir((dir / blocked).c_str(), 0755) == 0;
  close(watch);
  waitpid(launcher, &status, 0);
  return planted;
}

TEST(DistributedRun, AWriteThatFailsOnOneRankEndsEveryRank) {
  // A file that one rank cannot write: rank 1's piece of step 2, or the .pvtu that rank 0 alone
  // writes. A directory appears at its name once step 1 is written, so the rename onto it fails on
  // that rank only. Before the ranks agreed on such failures, the other rank waited in its next
  // collective call and the failing one blocked while freeing the factor: the job hung until
  // killed. The directory is made while step 2 is being solved (hundreds of milliseconds at
  // least); an attempt that comes too late is repeated, at most three times.
  for (const std::string blocked : {"step_0002_p1.vtu", "step_0002.pvtu"}) {
    SCOPED_TRACE(blocked);
    bool planted = false;
    fs::path dir;
    int status = -1;
    for (int attempt = 0; attempt < 3 && !planted; ++attempt) {
      dir = scratch_directory("distributed-write-fails-" + blocked + "-" + std::to_string(attempt));
      fs::create_directories(dir);
      const std::string command = "exec timeout -s KILL 120 env " + kMpiexec2 + PLISSE_BINARY_DIR +
                                  "/bin/plisse run '" + example("sphere-inflation.yaml") +
                                  "' -o '" + dir.string() + "' >'" +
                                  (dir / "launcher.log").string() + "' 2>&1";
      planted = plant_during_run(command, dir, "step_0001.pvtu", blocked, status);
    }
    ASSERT_TRUE(planted) << "step 2 was written before the directory could be made, three times";
    std::ifstream log(dir / "launcher.log");
    const std::string output{std::istreambuf_iterator<char>(log), {}};
    ASSERT_TRUE(WIFEXITED(status)) << output;
    EXPECT_EQ(WEXITSTATUS(status), 1) << output;
    const std::string rank = blocked == "step_0002_p1.vtu" ? "rank 1: " : "rank 0: ";
    EXPECT_NE(output.find("plisse: error: " + rank + "cannot"), std::string::npos) << output;
    EXPECT_NE(output.find(blocked), std::string::npos) << output;
    // The steps before it are kept.
    EXPECT_GE(read_history(dir / "history.csv").rows.size(), 1u);
    EXPECT_TRUE(fs::exists(dir / "step_0001.pvtu"));
  }
}

/// Processes of build/bin/plisse whose command line names `dir` (read from /proc).
std::vector<pid_t> plisse_processes_in(const fs::path& dir) {
  std::vector<pid_t> found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "cmdline", std::ios::binary);
    const std::string line{std::istreambuf_iterator<char>(in), {}};
    const std::string program = line.substr(0, line.find('\0'));
    if (program.size() >= 10 && program.compare(program.size() - 10, 10, "bin/plisse") == 0 &&
        line.find(dir.string()) != std::string::npos)
      found.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return found;
}

TEST(DistributedRun, NoRankOutlivesItsLauncher) {
  // The launcher killed outright (a scheduler's SIGKILL): its ranks end within seconds, they do
  // not go on computing or wait for ever in a collective call.
  const fs::path dir = scratch_directory("distributed-launcher-killed");
  const std::string exe = std::string(PLISSE_BINARY_DIR) + "/bin/plisse";
  // The main case on its preview mesh: its first step takes about a second in a Release build,
  // but ten times that under the sanitizers, with other tests on the same cores.
  const std::string command = "exec env " + kMpiexec2 + exe + " run '" +
                              example("sphere-indentation.yaml") +
                              "' --set mesh.element_size=2 -o '" + dir.string() + "' >'" +
                              (dir / "launcher.log").string() + "' 2>&1";
  fs::create_directories(dir);
  const pid_t launcher = fork();
  if (launcher == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  ASSERT_GT(launcher, 0);
  const bool started = test::wait_for_history_rows(dir, 1, std::chrono::seconds(180));
  EXPECT_EQ(plisse_processes_in(dir).size(), 2u);
  kill(launcher, SIGKILL);
  waitpid(launcher, nullptr, 0);
  ASSERT_TRUE(started) << "the run wrote no step within 3 minutes";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!plisse_processes_in(dir).empty() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::vector<pid_t> left = plisse_processes_in(dir);
  EXPECT_TRUE(left.empty()) << left.size() << " rank(s) still running 20 s after the launcher died";
  for (pid_t pid : left) kill(pid, SIGKILL);  // do not leave them to the next test
}

}  // namespace
}  // namespace plisse
