// The history table: its column names and its row come from one table, in the contract's order,
// and each column holds its quantity. Checked on a homogeneous incompressible uniaxial stretch of
// a cube (stretch λ along z), where every kinematic column has a closed form.
#include "app/history_columns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/model_builder.hpp"
#include "case/case.hpp"

namespace plisse {
namespace {

constexpr double kStretch = 1.2;
constexpr double kEdge = 2.0;
constexpr double kC1 = 0.5;

const char* const kCase = R"(
mesh: {generate: cube, edge: 2.0, divisions: 2}
material: {model: neo-hookean, c1: 0.5}
boundary:
  - {type: symmetry, surface: sym_x}
  - {type: symmetry, surface: sym_y}
  - {type: symmetry, surface: sym_z}
  - {type: displacement, name: pull, surface: top, value: [~, ~, 0.4]}
loads:
  - {type: pressure, name: gas, surface: right, value: 0.01, ramp: [0.0, 2.0]}
probes:
  - {name: corner, point: [2.1, 1.9, 2.0]}
solver: {stability: {check: true}}
output: {stretch_axis: z}
)";

/// u = ((λ^-1/2 - 1) X, (λ^-1/2 - 1) Y, (λ - 1) Z): isochoric uniaxial stretch, pressures 0.
void set_uniaxial_stretch(MixedModel& model) {
  const double lateral = 1.0 / std::sqrt(kStretch);
  auto& x = model.state();
  const Mesh& mesh = model.mesh();
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d& X = mesh.nodes[v];
    x[DofMap::dof(v, 0)] = (lateral - 1.0) * X.x();
    x[DofMap::dof(v, 1)] = (lateral - 1.0) * X.y();
    x[DofMap::dof(v, 2)] = (kStretch - 1.0) * X.z();
  }
}

TEST(HistoryColumns, NamesAndValuesComeFromOneTableInTheContractOrder) {
  const Case c = parse_case_string(kCase, "history.yaml");
  const Mesh mesh = load_case_mesh(c);
  auto model = app::make_model(mesh, app::build_model_parts(c, mesh));
  model->set_time(1.0);
  set_uniaxial_stretch(*model);
  Vec f = model->create_vector();
  model->assemble_residual(f);  // the reactions of the named condition
  VecDestroy(&f);

  const app::HistoryColumns columns(c, *model, nullptr);
  const std::vector<std::string> expected{"step",
                                          "time",
                                          "load_factor",
                                          "newton_iterations",
                                          "residual_norm",
                                          "pressure:gas",
                                          "stretch",
                                          "stretch_x",
                                          "stretch_y",
                                          "stretch_z",
                                          "cauchy_xx",
                                          "cauchy_yy",
                                          "cauchy_zz",
                                          "cauchy_xy",
                                          "cauchy_yz",
                                          "cauchy_xz",
                                          "force_x:pull",
                                          "force_y:pull",
                                          "force_z:pull",
                                          "moment_x:pull",
                                          "moment_y:pull",
                                          "moment_z:pull",
                                          "full_force_x:pull",
                                          "full_force_y:pull",
                                          "full_force_z:pull",
                                          "full_moment_x:pull",
                                          "full_moment_y:pull",
                                          "full_moment_z:pull",
                                          "ux:corner",
                                          "uy:corner",
                                          "uz:corner",
                                          "volume",
                                          "min_J",
                                          "strain_energy",
                                          "negative_pivots",
                                          "expected_negative_pivots",
                                          "stable"};
  EXPECT_EQ(columns.names(), expected);
  EXPECT_EQ(columns.extra_names(), std::vector<std::string>(expected.begin() + 5, expected.end()));

  StepInfo info;
  info.step = 7;
  info.time = 1.0;
  info.load_factor = 1.0;
  info.newton_iterations = 3;
  info.residual_norm = 2.5e-11;
  info.negative_pivots = 12;
  info.expected_negative_pivots = 12;
  info.stable = true;
  const auto fields = model->element_fields();
  const BodyAverages averages = model->averages(fields);
  const std::vector<double> row = columns.row({info, *model, fields, averages, nullptr});
  ASSERT_EQ(row.size(), expected.size());
  const auto value = [&](const std::string& name) {
    for (std::size_t i = 0; i < expected.size(); ++i)
      if (expected[i] == name) return row[i];
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_EQ(value("step"), 7.0);
  EXPECT_EQ(value("newton_iterations"), 3.0);
  EXPECT_EQ(value("residual_norm"), 2.5e-11);
  EXPECT_DOUBLE_EQ(value("pressure:gas"), 0.005);  // half way up its ramp [0, 2] s
  const double lateral = 1.0 / std::sqrt(kStretch);
  EXPECT_NEAR(value("stretch"), kStretch, 1e-14);
  EXPECT_NEAR(value("stretch_z"), kStretch, 1e-14);
  EXPECT_NEAR(value("stretch_x"), lateral, 1e-14);
  EXPECT_NEAR(value("stretch_y"), lateral, 1e-14);
  // The probe, 0.1 mm off the face x = 2, reports at its nearest point (2, 1.9, 2).
  EXPECT_NEAR(value("ux:corner"), (lateral - 1.0) * kEdge, 1e-14);
  EXPECT_NEAR(value("uy:corner"), (lateral - 1.0) * 1.9, 1e-14);
  EXPECT_NEAR(value("uz:corner"), (kStretch - 1.0) * kEdge, 1e-14);
  const double volume = kEdge * kEdge * kEdge;
  EXPECT_NEAR(value("volume"), volume, 1e-12);  // isochoric
  EXPECT_NEAR(value("min_J"), 1.0, 1e-13);
  // W = c1 (I1 - 3) per unit reference volume.
  const double I1 = kStretch * kStretch + 2.0 / kStretch;
  EXPECT_NEAR(value("strain_energy"), kC1 * (I1 - 3.0) * volume, 1e-12);
  // The top's reaction pulls along z: the nodal forces of the unbalanced stress (p = 0) sum to
  // the Cauchy stress times the deformed top area, here through the averaged stress.
  const double top_area = kEdge * kEdge / kStretch;
  EXPECT_NEAR(value("force_z:pull"), value("cauchy_zz") * top_area, 1e-10);
  // The top reaches the mirror planes x = 0 and y = 0 (not z = 0): the whole body's top is four
  // of the modelled one, pulled along z only.
  EXPECT_EQ(value("full_force_z:pull"), 4.0 * value("force_z:pull"));
  EXPECT_EQ(value("full_force_x:pull"), 0.0);
  EXPECT_EQ(value("full_force_y:pull"), 0.0);
  // Its moment about the origin. The top's nodes lie at z = kStretch kEdge; the pull along z is
  // the uniform stress over the top, whose nodal forces have the first moment of a force at its
  // centre (c, c), c = lateral kEdge / 2; the lateral reactions (the unbalanced lateral stress on
  // the side faces, which reach the top's edge nodes) act at the top's height and, spread along
  // the edges x = 2 c and y = 2 c, at their middles. Two mirror planes leave the whole body none.
  const double centre = lateral * kEdge / 2, top = kStretch * kEdge;
  const double fx = value("force_x:pull"), fy = value("force_y:pull"), fz = value("force_z:pull");
  EXPECT_NEAR(value("moment_x:pull"), centre * fz - top * fy, 1e-10);
  EXPECT_NEAR(value("moment_y:pull"), top * fx - centre * fz, 1e-10);
  EXPECT_NEAR(value("moment_z:pull"), centre * fy - centre * fx, 1e-10);
  for (const char* axis : {"x", "y", "z"})
    EXPECT_EQ(value(std::string("full_moment_") + axis + ":pull"), 0.0);
  EXPECT_EQ(value("negative_pivots"), 12.0);
  EXPECT_EQ(value("stable"), 1.0);
}

}  // namespace
}  // namespace plisse
