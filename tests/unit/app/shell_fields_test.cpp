// The step files of a shell: a shell model's element fields and shell outputs as the recorder
// writes them (shell_cell_fields after the fields every element has), written as a VTU of the
// mesh's triangles and read back with the right cell count, cell type and values; every field
// has its row in the output reference. And a shell run's files through the run recorder itself.
#include "app/shell_fields.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

#include "app/output_reference.hpp"
#include "app/run_recorder.hpp"
#include "case/case.hpp"
#include "core/error.hpp"
#include "core/wall_clock.hpp"
#include "material/registry.hpp"
#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/run_directory.hpp"
#include "output/vtu_reader.hpp"
#include "output/vtu_writer.hpp"
#include "solver/mixed_model.hpp"
#include "support/shell_mesh.hpp"
#include "unit/output/output_test_support.hpp"

namespace plisse::app {
namespace {

TEST(ShellFields, BiaxialSheetWrittenAsTrianglesReadsBack) {
  // The flat sheet of 4 × 4 mm, 0.2 mm thick, tilted, in 32 triangles, stretched homogeneously
  // by (a, b) in its plane: neo-Hookean plane stress σ = Q diag(2 c1 (a² - λ3²), 2 c1 (b² - λ3²),
  // 0) Qᵀ with λ3 = 1/(a b), the current thickness t λ3 and N = t λ3 σ in every triangle.
  const double c1 = 0.5, t = 0.2, a = 1.2, b = 1.1, l3 = 1.0 / (a * b);
  const Mat3d Q = Eigen::AngleAxisd(0.3, Vec3d(1.0, -0.5, 0.2).normalized()).toRotationMatrix();
  const Mesh mesh = test::flat_square(Q, 4, t);
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", c1}}), 0.0, {}, {},
                   ElementFamily::shell);
  const Mat3d stretch = Q * Vec3d(a, b, 1.0).asDiagonal() * Q.transpose();
  std::vector<Vec3d> points(mesh.nodes);
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d u = (stretch - Mat3d::Identity()) * mesh.nodes[v];
    for (int k = 0; k < 3; ++k) model.state()[DofMap::dof(v, k)] = u[k];
    points[v] += u;
  }
  const Mat3d sigma =
      Q * Vec3d(2 * c1 * (a * a - l3 * l3), 2 * c1 * (b * b - l3 * l3), 0.0).asDiagonal() *
      Q.transpose();

  const std::vector<ElementFields> fields = model.element_fields();
  const std::vector<shell::ShellOutputs> outputs = model.shell_outputs();
  const std::vector<VtuField> cells = shell_cell_fields(fields, outputs);
  for (const VtuField& f : cells)
    EXPECT_NO_THROW(require_output_entry(OutputTable::vtu_cell, f.name));
  EXPECT_THROW(shell_cell_fields(fields, {}), Error);

  const test::ScratchDir dir;
  const auto path = dir / "step_0001.vtu";
  write_vtu(path, mesh, points, {}, cells, VtuCompression::zlib);
  const VtuSummary summary = read_vtu_summary(path);
  EXPECT_EQ(summary.n_points, 25u);
  EXPECT_EQ(summary.n_cells, 32u);
  EXPECT_EQ(read_vtu_cell_types(path),
            std::vector<std::uint8_t>(32, static_cast<std::uint8_t>(VtkCellType::kTriangle)));
  ASSERT_EQ(summary.cell_fields.size(), cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    EXPECT_EQ(summary.cell_fields[k].name, cells[k].name);
    EXPECT_EQ(read_vtu_cell_field(path, cells[k].name).values, cells[k].values) << cells[k].name;
  }
  const VtuField thickness = read_vtu_cell_field(path, "thickness");
  const std::vector<Mat3d> N = symmetric_tensors(read_vtu_cell_field(path, "membrane_force"));
  const std::vector<Mat3d> M = symmetric_tensors(read_vtu_cell_field(path, "bending_moment"));
  const std::vector<Mat3d> top = symmetric_tensors(read_vtu_cell_field(path, "cauchy_stress_top"));
  const VtuField pressure = read_vtu_cell_field(path, "pressure");
  const VtuField bottom_stretches = read_vtu_cell_field(path, "principal_stretches_bottom");
  ASSERT_EQ(thickness.values.size(), 32u);
  for (std::size_t e = 0; e < 32; ++e) {
    EXPECT_NEAR(thickness.values[e], t * l3, 1e-14) << e;
    EXPECT_LT((N[e] - t * l3 * sigma).norm(), 1e-12 * t * sigma.norm()) << e;
    EXPECT_LT(M[e].norm(), 1e-12 * t * t * sigma.norm()) << e;
    EXPECT_LT((top[e] - sigma).norm(), 1e-12 * sigma.norm()) << e;
    EXPECT_NEAR(pressure.values[e], -sigma.trace() / 3.0, 1e-12 * sigma.norm()) << e;
    EXPECT_NEAR(bottom_stretches.values[3 * e], a, 1e-13) << e;
    EXPECT_NEAR(bottom_stretches.values[3 * e + 1], b, 1e-13) << e;
    EXPECT_NEAR(bottom_stretches.values[3 * e + 2], l3, 1e-13) << e;
  }
}

TEST(ShellFields, RecorderWritesAShellRunsStepFilesHistoryAndSummary) {
  // A shell run's files through the run recorder, as `plisse run` writes them: step_0000.vtu (the
  // reference sheet), a step in the same biaxial stretch, history.csv and summary.json. The
  // mesh's faces are tagged `bottom` and `top` on the same triangles, as a generated shell's are:
  // its thickness is the triangles' own, not a distance between the two faces (which is 0).
  const Case c = parse_case_string(
      "mesh: {generate: sheet, length: 4.0, width: 4.0, thickness: 0.2, layers: 1}\n"
      "material: {model: neo-hookean, c1: 0.5}\n"
      "output: {every: 1, compression: none}\n",
      "shell.yaml");
  const double t = 0.2, a = 1.2, b = 1.1, l3 = 1.0 / (a * b);
  Mesh mesh = test::flat_square(Mat3d::Identity(), 4, t);
  mesh.surface_tags["bottom"] = mesh.surface_tags["top"] = mesh.surface_tags.at("all");
  MixedModel model(mesh, make_material("neo-hookean", {{"c1", 0.5}}), 0.0, {}, {},
                   ElementFamily::shell);
  Vec f = model.create_vector();
  model.assemble_residual(f);
  const LoadStepper stepper(model, c.solver);
  const test::ScratchDir dir;
  const RunDirectory directory(dir.path());
  RunRecorder recorder(c, directory, {"shell.yaml", {}, {}}, model, stepper, nullptr, nullptr);
  recorder.record_initial_state();

  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d u = Vec3d(a - 1.0, b - 1.0, 0.0).cwiseProduct(mesh.nodes[v]);
    for (int k = 0; k < 3; ++k) model.state()[DofMap::dof(v, k)] = u[k];
  }
  model.assemble_residual(f);
  VecDestroy(&f);
  StepInfo info;
  info.step = 1;
  info.time = 1.0;
  info.dt = 1.0;
  info.load_factor = 1.0;
  recorder.record(info);
  SteppingResult result;
  result.completed = true;
  result.steps = 1;
  recorder.finish(result, {WallClock::now(), 0.0, 0.0});

  for (const auto& [step, thickness] : {std::pair{0, t}, std::pair{1, t * l3}}) {
    const auto path = directory.step_vtu(step);
    const VtuSummary summary = read_vtu_summary(path);
    EXPECT_EQ(summary.n_cells, 32u) << path;
    EXPECT_EQ(read_vtu_cell_types(path),
              std::vector<std::uint8_t>(32, static_cast<std::uint8_t>(VtkCellType::kTriangle)));
    for (const VtuArrayInfo& field : summary.point_fields)
      EXPECT_NE(field.name, "thickness") << "a point field of the faces' distance on " << path;
    for (const double value : read_vtu_cell_field(path, "thickness").values)
      EXPECT_NEAR(value, thickness, 1e-14) << path;
    for (const double p : read_vtu_point_field(path, "pressure").values) EXPECT_EQ(p, 0.0);
  }
  const HistoryWriter history = HistoryWriter::reopen(directory.history_csv());
  const auto& columns = history.columns();
  const auto column = std::find(columns.begin(), columns.end(), "min_thickness");
  ASSERT_NE(column, columns.end());
  ASSERT_EQ(history.rows().size(), 1u);
  EXPECT_NEAR(history.rows()[0][static_cast<std::size_t>(column - columns.begin())], t * l3, 1e-14);
  const nlohmann::json summary = read_json_file(directory.summary_json());
  EXPECT_EQ(summary["elements"], 32);
  EXPECT_EQ(summary["element"], "shell");
  EXPECT_TRUE(std::filesystem::exists(directory.directory() / "checkpoint.bin"));
}

}  // namespace
}  // namespace plisse::app
