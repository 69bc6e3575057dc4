// Die contact term: tangent against central differences of the residual for every shape and both
// contact kinds, exact resultants of a uniform penetration and of a glued region, the glue
// history across accept/reject, and the factory's defaults (docs/theory/contact.md).
#include "physics/die_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

#include "app/model_builder.hpp"
#include "case/case.hpp"
#include "mesh/generate.hpp"
#include "physics/die_surface.hpp"
#include "physics/surface.hpp"
#include "support/term_testing.hpp"

namespace plisse {
namespace {

using test::DenseSink;
using test::random_state;
using test::term_residual;

/// [0, 2]^3 with 2 divisions: top nodes (z = 2) at x, y in {0, 1, 2}.
Mesh cube(int divisions = 2) {
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.edge = 2.0;
  spec.divisions = divisions;
  return generate_mesh(spec);
}

int n_dofs(const Mesh& mesh) { return kValuesPerNode * mesh.n_nodes(); }

DieContactSettings settings(ContactKind kind, double penalty = 3.0, double tolerance = 1e-12) {
  DieContactSettings s;
  s.name = "die";
  s.contact = kind;
  s.penalty = penalty;
  s.tolerance = tolerance;
  return s;
}

/// Dies over the top of the cube, moving down 0.3 mm over t in [0, 1]; the gaps of the nodes stay
/// at least 0.04 mm away from 0 at t = 0 and t = 1 (random states below move nodes by <= 0.01).
///   plane through (0, 0, 1.95 - 0.3 t), tilted (normal ~ (0.2, 0, -1)): the top row x = 0 at
///     t = 0, also the row x = 1 at t = 1;
///   sphere R = 1.5 centred above (1, 1): the top centre node at t = 0, also the four edge
///     mid-nodes at t = 1;
///   cylinder R = 1.5 along x above y = 1: the three nodes y = 1 at t = 0, also y = 0, 2 at t = 1.
DieGeometry die(DieShape shape) {
  const Vec3d move(0, 0, -0.3);
  switch (shape) {
    case DieShape::plane:
      return DieGeometry(shape, Vec3d(0, 0, 1.95), Vec3d(0.2, 0, -1).normalized(), Vec3d::UnitZ(),
                         0.0, move, Ramp{0.0, 1.0});
    case DieShape::sphere:
      return DieGeometry(shape, Vec3d(1, 1, 3.35), Vec3d::UnitY(), Vec3d::UnitZ(), 1.5, move,
                         Ramp{0.0, 1.0});
    case DieShape::cylinder:
      return DieGeometry(shape, Vec3d(0, 1, 3.35), Vec3d::UnitY(), Vec3d::UnitX(), 1.5, move,
                         Ramp{0.0, 1.0});
  }
  return DieGeometry(shape, Vec3d::Zero(), Vec3d::UnitY(), Vec3d::UnitZ(), 1.0, move, Ramp{});
}

/// The tangent of `term` at (t, x), its largest entry, and its largest difference to central
/// differences of the residual (h = 1e-6), recorded relative to that entry as fd_relative_error.
struct CheckedTangent {
  Eigen::MatrixXd K;
  double scale;
  double max_error;
};
CheckedTangent checked_tangent(DieContact& term, double t, const std::vector<double>& x) {
  DenseSink sink(static_cast<int>(x.size()));
  std::vector<double> r(x.size(), 0.0);
  term.assemble(t, x, r, &sink);
  const double scale = sink.K.cwiseAbs().maxCoeff();
  const double max_error = test::max_tangent_error(term, t, x, sink.K, 1e-6);
  std::ostringstream relative;
  relative << std::scientific << max_error / scale;
  ::testing::Test::RecordProperty("fd_relative_error", relative.str());
  return {sink.K, scale, max_error};
}

struct TangentCase {
  DieShape shape;
  ContactKind kind;
};

std::string tangent_case_name(const ::testing::TestParamInfo<TangentCase>& info) {
  const char* shapes[] = {"Plane", "Sphere", "Cylinder"};
  return std::string(shapes[static_cast<int>(info.param.shape)]) +
         (info.param.kind == ContactKind::sticking ? "Sticking" : "Frictionless");
}

class DieContactTangent : public ::testing::TestWithParam<TangentCase> {};

TEST_P(DieContactTangent, IsTheDerivativeOfTheResidualAndSymmetric) {
  const Mesh mesh = cube();
  const int n = n_dofs(mesh);
  DieContact term(mesh, die(GetParam().shape), settings(GetParam().kind), boundary_faces(mesh));
  // Sticking: glue what touches at the reference state at t = 0 (accepted step), then move on.
  const std::vector<double> zero(n, 0.0);
  std::vector<double> r(n, 0.0);
  term.assemble(0.0, zero, r, nullptr);
  term.accept_step(zero);
  if (GetParam().kind == ContactKind::sticking) {
    EXPECT_GT(term.n_glued(), 0);
  }
  // A state near the reference at t = 1 with non-zero multipliers (one Uzawa update there).
  const double t = 1.0;
  const auto x = random_state(n, 11, 0.01);
  term.assemble(t, x, r, nullptr);
  ASSERT_TRUE(term.update_multipliers(x));
  const int glued = term.n_glued();
  EXPECT_GT(term.n_contact_nodes(t, x), glued);  // some sliding nodes are in contact too
  const auto [K, scale, max_error] = checked_tangent(term, t, x);
  // Away from the kink lambda - eps g = 0 the residual is smooth (quadratic for the plane and the
  // glue): central differences agree to h^2 |third derivative| + round-off / h ~ 1e-10 relative.
  EXPECT_LT(max_error, 1e-8 * scale);
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
  EXPECT_TRUE(term.symmetric());
}

INSTANTIATE_TEST_SUITE_P(ShapesAndKinds, DieContactTangent,
                         ::testing::Values(TangentCase{DieShape::plane, ContactKind::frictionless},
                                           TangentCase{DieShape::sphere, ContactKind::frictionless},
                                           TangentCase{DieShape::cylinder,
                                                       ContactKind::frictionless},
                                           TangentCase{DieShape::plane, ContactKind::sticking},
                                           TangentCase{DieShape::sphere, ContactKind::sticking},
                                           TangentCase{DieShape::cylinder, ContactKind::sticking}),
                         tangent_case_name);

struct CoulombCase {
  DieShape shape;
  double friction;
  bool sticks;  ///< whether the nodes in contact stick (else they slide) at the tested state
};

std::string coulomb_case_name(const ::testing::TestParamInfo<CoulombCase>& info) {
  const char* shapes[] = {"Plane", "Sphere", "Cylinder"};
  return std::string(shapes[static_cast<int>(info.param.shape)]) +
         (info.param.sticks ? "Sticking" : "Sliding");
}

DieContactSettings coulomb(double friction, double tolerance = 1e-12) {
  DieContactSettings s = settings(ContactKind::coulomb, 3.0, tolerance);
  s.friction = friction;
  return s;
}

/// Sticking and sliding nodes of a Coulomb die at (t, x), in the step being solved.
std::pair<int, int> stick_and_slip(const DieContact& term, double t, std::span<const double> x) {
  return term.sticking_and_sliding(t, x);
}

/// stick_nodes:<die> and slip_nodes:<die> of a Coulomb die at (t, x) (after an accepted step).
std::pair<int, int> stick_and_slip_columns(const DieContact& term, double t,
                                           std::span<const double> x) {
  const std::vector<double> v = term.history_values(t, x);
  return {static_cast<int>(v.at(5)), static_cast<int>(v.at(6))};
}

class DieContactCoulombTangent : public ::testing::TestWithParam<CoulombCase> {};

TEST_P(DieContactCoulombTangent, IsTheDerivativeOfTheResidual) {
  const Mesh mesh = cube();
  const int n = n_dofs(mesh);
  DieContact term(mesh, die(GetParam().shape), coulomb(GetParam().friction), boundary_faces(mesh));
  EXPECT_FALSE(term.symmetric());
  // Accepted at t = 0 with the nodes that touch pressed (one Uzawa update): they carry lambda > 0
  // and stick from their reference positions. At t = 1 the die has moved 0.3 mm down, which for
  // each shape has a component along its surface at the nodes in contact; an update there gives
  // the tangential multipliers Lambda a value, then a random state is tested (D18-D20).
  const std::vector<double> zero(n, 0.0);
  std::vector<double> r(n, 0.0);
  term.assemble(0.0, zero, r, nullptr);
  ASSERT_TRUE(term.update_multipliers(zero));
  term.accept_step(zero);
  const double t = 1.0;
  const auto x = random_state(n, 11, 0.01);
  term.assemble(t, x, r, nullptr);
  ASSERT_TRUE(term.update_multipliers(x));
  const auto [stick, slip] = stick_and_slip(term, t, x);
  EXPECT_EQ(stick + slip, term.n_contact_nodes(t, x));
  if (GetParam().sticks) {
    EXPECT_GT(stick, 0);
    EXPECT_EQ(slip, 0);
  } else {
    EXPECT_GT(slip, 0);  // the node under a sphere's or a cylinder's axis moves normal to it
  }
  const auto [K, scale, max_error] = checked_tangent(term, t, x);
  // Smooth away from the cone's surface and the kink lambda_hat = 0: as for D8.
  EXPECT_LT(max_error, 1e-8 * scale);
  // Sliding, the tangent is unsymmetric (the cone's radius grows with the pressure, D20).
  if (!GetParam().sticks) {
    EXPECT_GT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-6 * scale);
  }
}

INSTANTIATE_TEST_SUITE_P(ShapesAndStates, DieContactCoulombTangent,
                         ::testing::Values(CoulombCase{DieShape::plane, 0.05, false},
                                           CoulombCase{DieShape::sphere, 0.05, false},
                                           CoulombCase{DieShape::cylinder, 0.05, false},
                                           CoulombCase{DieShape::plane, 50.0, true},
                                           CoulombCase{DieShape::sphere, 50.0, true},
                                           CoulombCase{DieShape::cylinder, 50.0, true}),
                         coulomb_case_name);

/// A flat die 0.05 mm into the top face of the cube (normal -z), translated along x by `slide`
/// over t in [0, 1].
DieGeometry sliding_plane(double slide) {
  return DieGeometry(DieShape::plane, Vec3d(0, 0, 1.95), Vec3d(0, 0, -1), Vec3d::UnitZ(), 0.0,
                     Vec3d(slide, 0, 0), Ramp{0.0, 1.0});
}

TEST(DieContactCoulomb, ASlidingFaceCarriesFrictionTimesItsPressureAgainstTheSlip) {
  const Mesh mesh = cube();
  const auto top = outward_triangles(mesh, "top");
  DieContact term(mesh, sliding_plane(0.2), coulomb(0.3), top);
  const std::vector<double> x(n_dofs(mesh), 0.0);
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  term.accept_step(x);
  // At t = 1 the die has slid 0.2 mm along +x over the fixed face: each node's trial traction
  // eps * 0.2 = 0.6 MPa exceeds mu * eps * 0.05 = 0.045 MPa, so all 9 slide, and the die drags
  // the body along +x with mu times the normal force (D19): the body pushes the die up (+z) and
  // along -x.
  const Vec3d f = term.force_on_die(1.0, x);
  EXPECT_NEAR(f.z(), 3.0 * 4.0 * 0.05, 1e-14);
  EXPECT_NEAR(f.x(), -0.3 * f.z(), 1e-14);
  EXPECT_NEAR(f.y(), 0.0, 1e-14);
  EXPECT_EQ(stick_and_slip(term, 1.0, x), std::make_pair(0, 9));
  // Penetration alone counts as violation for sliding nodes.
  EXPECT_NEAR(term.violation(1.0, x), 0.05, 1e-14);
  // Accepted, the nodes start the next step on the cone's surface, with no slip since: the
  // history reports that they slid (and the point field gives 1 at the 9 top nodes).
  term.assemble(1.0, x, r, nullptr);
  term.accept_step(x);
  EXPECT_EQ(stick_and_slip_columns(term, 1.0, x), std::make_pair(0, 9));
  EXPECT_TRUE(term.force_on_die(1.0, x).isApprox(f, 1e-14));
  const std::vector<NodeField> fields = term.node_fields(1.0, x, mesh.n_nodes());
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].name, "contact_die");
  EXPECT_EQ(std::count(fields[0].values.begin(), fields[0].values.end(), 1.0), 9);
  EXPECT_EQ(std::count(fields[0].values.begin(), fields[0].values.end(), 0.0), mesh.n_nodes() - 9);
  // The contact pressure eps * 0.05 and the gap -0.05 mm at the 9 top nodes, 0 elsewhere.
  EXPECT_EQ(fields[1].name, "contact_pressure_die");
  EXPECT_EQ(fields[2].name, "gap_die");
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const bool top = mesh.nodes[v].z() == 2.0;
    EXPECT_NEAR(fields[1].values[v], top ? 3.0 * 0.05 : 0.0, 1e-14) << "node " << v;
    EXPECT_NEAR(fields[2].values[v], top ? -0.05 : 0.0, 1e-14) << "node " << v;
  }
  // Friction 0 is the frictionless die, residual and tangent.
  DieContact none(mesh, sliding_plane(0.2), coulomb(0.0), top);
  DieContact frictionless(mesh, sliding_plane(0.2), settings(ContactKind::frictionless), top);
  EXPECT_TRUE(none.symmetric());
  const auto y = random_state(n_dofs(mesh), 5, 0.01);
  for (DieContact* t : {&none, &frictionless}) {
    t->assemble(0.0, x, r, nullptr);
    t->accept_step(x);
  }
  DenseSink a(n_dofs(mesh)), b(n_dofs(mesh));
  std::vector<double> ra(x.size(), 0.0), rb(x.size(), 0.0);
  none.assemble(1.0, y, ra, &a);
  frictionless.assemble(1.0, y, rb, &b);
  EXPECT_EQ(ra, rb);
  EXPECT_EQ((a.K - b.K).cwiseAbs().maxCoeff(), 0.0);
}

TEST(DieContactCoulomb, StickingNodesAreHeldWhereTheyTouchedUntilTheConeIsReached) {
  const Mesh mesh = cube();
  const auto top = outward_triangles(mesh, "top");
  const std::vector<double> x(n_dofs(mesh), 0.0);
  std::vector<double> r(x.size(), 0.0);
  // A slide of 0.01 mm: trial traction eps * 0.01 = 0.03 MPa < mu * 0.15 MPa with mu = 0.3, so
  // the nodes stick, and each Uzawa update adds eps * slip to the tangential traction (D21), as
  // it adds eps * penetration to the pressure (D9).
  DieContact term(mesh, sliding_plane(0.01), coulomb(0.3, 1e-3), top);
  term.assemble(0.0, x, r, nullptr);
  term.accept_step(x);
  term.assemble(1.0, x, r, nullptr);
  EXPECT_EQ(stick_and_slip(term, 1.0, x), std::make_pair(9, 0));
  EXPECT_NEAR(term.violation(1.0, x), 0.05, 1e-14);  // the penetration is larger here
  const double pressure = 3.0 * 0.05;
  EXPECT_NEAR(term.force_on_die(1.0, x).x(), -4.0 * 3.0 * 0.01, 1e-14);
  ASSERT_TRUE(term.update_multipliers(x));  // lambda = 0.15 MPa, Lambda = 0.03 MPa
  EXPECT_NEAR(term.force_on_die(1.0, x).x(), -4.0 * 2.0 * 3.0 * 0.01, 1e-14);
  EXPECT_NEAR(term.force_on_die(1.0, x).z(), 4.0 * 2.0 * pressure, 1e-14);
  EXPECT_EQ(stick_and_slip(term, 1.0, x), std::make_pair(9, 0));
  // With mu = 0.1 the cone's radius 0.015 MPa is below the trial traction: the nodes slide with
  // mu lambda_hat (D19).
  DieContact slippery(mesh, sliding_plane(0.01), coulomb(0.1, 1e-3), top);
  slippery.assemble(0.0, x, r, nullptr);
  slippery.accept_step(x);
  EXPECT_EQ(stick_and_slip(slippery, 1.0, x), std::make_pair(0, 9));
  EXPECT_NEAR(slippery.force_on_die(1.0, x).x(), -0.1 * 4.0 * pressure, 1e-14);
  // A rejected step forgets all of it; an accepted one keeps the traction and sticks from there.
  term.reject_step();
  EXPECT_NEAR(term.force_on_die(1.0, x).x(), -4.0 * 3.0 * 0.01, 1e-14);
  term.assemble(1.0, x, r, nullptr);
  term.update_multipliers(x);
  term.accept_step(x);
  const std::vector<double> saved = term.save_state();
  EXPECT_NEAR(term.force_on_die(1.0, x).x(), -4.0 * 2.0 * 3.0 * 0.01, 1e-14);
  DieContact restored(mesh, sliding_plane(0.01), coulomb(0.3, 1e-3), top);
  restored.load_state(saved);
  EXPECT_TRUE(restored.force_on_die(1.0, x).isApprox(term.force_on_die(1.0, x), 1e-15));
  EXPECT_NEAR(restored.violation(1.0, x), 0.05, 1e-15);  // no slip since the accepted step
}

TEST(DieContactCoulomb, RefusesANegativeCoefficientAndFrictionOnOtherLaws) {
  const Mesh mesh = cube();
  const auto top = outward_triangles(mesh, "top");
  EXPECT_THROW(DieContact(mesh, sliding_plane(0.0), coulomb(-0.1), top), Error);
  DieContactSettings glue = settings(ContactKind::sticking);
  glue.friction = 0.2;
  EXPECT_THROW(DieContact(mesh, sliding_plane(0.0), glue, top), Error);
}

TEST(DieContact, UniformPenetrationGivesPenaltyTimesAreaTimesDepthOnEveryMesh) {
  // A flat die 0.05 mm into the top face (area 4 mm^2): force eps * 4 * 0.05, whatever the mesh.
  for (int divisions : {2, 3, 5}) {
    const Mesh mesh = cube(divisions);
    DieContact term(mesh,
                    DieGeometry(DieShape::plane, Vec3d(0, 0, 1.95), Vec3d(0, 0, -1), Vec3d::UnitZ(),
                                0.0, Vec3d::Zero(), Ramp{}),
                    settings(ContactKind::frictionless, 2.5), outward_triangles(mesh, "top"));
    const std::vector<double> x(n_dofs(mesh), 0.0);
    std::vector<double> r(x.size(), 0.0);
    term.assemble(0.0, x, r, nullptr);
    Vec3d on_body = Vec3d::Zero();
    for (int v = 0; v < mesh.n_nodes(); ++v)
      for (int k = 0; k < 3; ++k) on_body[k] -= r[node_dof(v, k)];  // residual = -f
    EXPECT_NEAR(on_body.z(), -2.5 * 4.0 * 0.05, 1e-14) << divisions << " divisions";
    EXPECT_LT(on_body.head<2>().norm(), 1e-15);
    // The body pushes the die up (+z): force on the die = - force on the body.
    EXPECT_TRUE(term.force_on_die(0.0, x).isApprox(-on_body, 1e-14));
    EXPECT_NEAR(term.violation(0.0, x), 0.05, 1e-14);
    EXPECT_EQ(term.n_contact_nodes(0.0, x), (divisions + 1) * (divisions + 1));
  }
}

TEST(DieContact, MultiplierUpdatesAreUzawaStepsAndStopAtTheTolerance) {
  const Mesh mesh = cube();
  DieContact term(mesh,
                  DieGeometry(DieShape::plane, Vec3d(0, 0, 1.95), Vec3d(0, 0, -1), Vec3d::UnitZ(),
                              0.0, Vec3d::Zero(), Ramp{}),
                  settings(ContactKind::frictionless, 2.0, 0.06), outward_triangles(mesh, "top"));
  const std::vector<double> x(n_dofs(mesh), 0.0);
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  EXPECT_FALSE(term.update_multipliers(x));  // 0.05 mm is within the tolerance 0.06 mm
  DieContact strict(mesh,
                    DieGeometry(DieShape::plane, Vec3d(0, 0, 1.95), Vec3d(0, 0, -1), Vec3d::UnitZ(),
                                0.0, Vec3d::Zero(), Ramp{}),
                    settings(ContactKind::frictionless, 2.0, 0.01), outward_triangles(mesh, "top"));
  strict.assemble(0.0, x, r, nullptr);
  const double before = strict.force_on_die(0.0, x).z();
  EXPECT_TRUE(strict.update_multipliers(x));
  // lambda = eps * 0.05, so at the same state the force doubles: A (lambda + eps * 0.05).
  EXPECT_NEAR(strict.force_on_die(0.0, x).z(), 2.0 * before, 1e-14);
  // A step that is abandoned forgets the update.
  strict.reject_step();
  EXPECT_NEAR(strict.force_on_die(0.0, x).z(), before, 1e-14);
}

TEST(DieContact, GlueMadeAtAcceptedStepsSurvivesRejectionAndMultipliersAreRestored) {
  const Mesh mesh = cube();
  // Sphere R = 1.5 above the top centre: at t = 0.5 only the centre node is inside, at t = 1 also
  // the four edge mid-nodes (centre height 3.3 then 2.9).
  DieContact term(mesh,
                  DieGeometry(DieShape::sphere, Vec3d(1, 1, 3.7), Vec3d::UnitY(), Vec3d::UnitZ(),
                              1.5, Vec3d(0, 0, -0.8), Ramp{0.0, 1.0}),
                  settings(ContactKind::sticking, 3.0, 1e-6), boundary_faces(mesh));
  const std::vector<double> x(n_dofs(mesh), 0.0);
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  term.accept_step(x);
  EXPECT_EQ(term.n_glued(), 0);  // nothing touches at t = 0
  term.assemble(0.5, x, r, nullptr);
  term.accept_step(x);
  EXPECT_EQ(term.n_glued(), 1);
  int centre = -1;
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if ((mesh.nodes[v] - Vec3d(1, 1, 2)).norm() < 1e-12) centre = v;
  ASSERT_GE(centre, 0);
  EXPECT_TRUE(term.glued(centre));
  // The glue point is the die surface point nearest to the node, 0.2 mm below it (the node was
  // 0.2 mm inside); the die moves 0.4 mm further down by t = 1: the node is 0.6 mm from it.
  term.assemble(1.0, x, r, nullptr);
  const Vec3d before = term.force_on_die(1.0, x);
  EXPECT_NEAR(term.violation(1.0, x), 0.6, 1e-12);
  EXPECT_TRUE(term.update_multipliers(x));
  EXPECT_FALSE(term.force_on_die(1.0, x).isApprox(before, 1e-6));
  term.reject_step();  // the step to t = 1 is abandoned: multipliers back, glue of t = 0.5 kept
  EXPECT_EQ(term.n_glued(), 1);
  EXPECT_TRUE(term.force_on_die(1.0, x).isApprox(before, 1e-14));
  term.assemble(1.0, x, r, nullptr);
  term.accept_step(x);
  EXPECT_EQ(term.n_glued(), 5);  // the four edge mid-nodes touched at t = 1
  term.reject_step();            // rejecting the next step keeps what t = 1 accepted
  EXPECT_EQ(term.n_glued(), 5);
}

TEST(DieContact, GluedNodesPullBackWhenSeparatedAndAGluedNodeKeepsItsForceAtGluing) {
  const Mesh mesh = cube();
  const DieGeometry plane(DieShape::plane, Vec3d(0, 0, 1.9), Vec3d(0, 0, -1), Vec3d::UnitZ(), 0.0,
                          Vec3d(0, 0, 0.5), Ramp{1.0, 2.0});
  DieContact term(mesh, plane, settings(ContactKind::sticking, 4.0, 1e-9),
                  outward_triangles(mesh, "top"));
  const std::vector<double> x(n_dofs(mesh), 0.0);
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  term.update_multipliers(x);
  const Vec3d sliding = term.force_on_die(0.0, x);
  term.accept_step(x);
  EXPECT_EQ(term.n_glued(), 9);
  EXPECT_TRUE(term.force_on_die(0.0, x).isApprox(sliding, 1e-14));  // D13: no jump at gluing
  // The die lifts 0.5 mm: glued nodes are pulled up (tension), force on the die now -z.
  EXPECT_LT(term.force_on_die(2.0, x).z(), 0.0);
}

TEST(DieContact, RegionIsGluedFromTheStartAndFollowsTheDie) {
  const Mesh mesh = cube();
  const auto top = outward_triangles(mesh, "top");
  const Vec3d shift(0.1, -0.05, 0.2);
  DieContact term(mesh,
                  DieGeometry(DieShape::plane, Vec3d(0, 0, 3.0), Vec3d(0, 0, -1), Vec3d::UnitZ(),
                              0.0, shift, Ramp{0.0, 1.0}),
                  settings(ContactKind::sticking, 5.0, 1e-3), top, top);
  EXPECT_EQ(term.n_glued(), 9);  // glued although the die is 1 mm away
  const std::vector<double> x(n_dofs(mesh), 0.0);
  std::vector<double> r(x.size(), 0.0);
  term.assemble(0.0, x, r, nullptr);
  EXPECT_LT(Eigen::Map<Eigen::VectorXd>(r.data(), r.size()).norm(), 1e-15);
  // Translating the die drags the region: total force on the body eps * area * shift (area 4).
  EXPECT_TRUE(term.force_on_die(1.0, x).isApprox(-5.0 * 4.0 * shift, 1e-14));
  EXPECT_NEAR(term.violation(1.0, x), shift.norm(), 1e-14);
  EXPECT_THROW(
      DieContact(mesh, die(DieShape::plane), settings(ContactKind::frictionless), top, top), Error);
}

TEST(DieContact, TributaryAreasAddUpToTheSurfaceArea) {
  const Mesh mesh = cube(3);
  const auto areas = tributary_areas(mesh, outward_faces(mesh, "top"));
  double sum = 0.0;
  for (const auto& [node, a] : areas) sum += a;
  EXPECT_NEAR(sum, 4.0, 1e-13);
  EXPECT_EQ(boundary_faces(mesh).size(), 6u * 2u * 9u);  // two triangles per boundary square
  EXPECT_NEAR(mean_edge_length(mesh, outward_triangles(mesh, "top")),
              (2.0 + std::sqrt(2.0)) / 3.0 * 2.0 / 3.0, 1e-13);
}

TEST(ModelBuilder, DefaultDiePenaltyIsTenShearModuliPerElementSizeAndSymmetryCutsAreNoContact) {
  const std::string text = R"(
element: mini
mesh: {generate: cube, edge: 2.0, divisions: 2}
material: {model: neo-hookean, c1: 0.5}
boundary:
  - {type: symmetry, surface: left}
dies:
  - {name: punch, shape: plane, point: [0, 0, 2.5], normal: [0, 0, -1]}
  - {name: stiff, shape: plane, point: [1, 1, 2], normal: [0, 0, -1], penalty: 7.5,
     tolerance: 0.01, surface: top, contact: sticking, region: top}
)";
  const Case c = parse_case_string(text, "contact.yaml");
  const Mesh mesh = load_case_mesh(c);
  const app::ModelParts parts = app::build_model_parts(c, mesh);
  ASSERT_EQ(parts.terms.size(), 2u);  // the two dies, in the case's order
  const auto& term = parts.terms[0];
  const auto* contact = dynamic_cast<const DieContact*>(term.get());
  ASSERT_NE(contact, nullptr);
  // mu = 2 c1 = 1 MPa; h = mean edge of the boundary without the symmetry face (the same on all
  // faces of this structured cube): 10 / h.
  const double h = mean_edge_length(mesh, outward_triangles(mesh, "top"));
  EXPECT_NEAR(contact->penalty(), 10.0 / h, 1e-12);
  for (int v = 0; v < mesh.n_nodes(); ++v) {
    const Vec3d& X = mesh.nodes[v];
    if (X.x() == 0.0 && X.y() > 0.0 && X.y() < 2.0 && X.z() > 0.0 && X.z() < 2.0) {
      EXPECT_EQ(contact->area(v), 0.0) << "node " << v << " lies only on the symmetry cut";
    }
  }
  // The punch's normal lies in the mirror plane x = 0: the whole body's force is reported too.
  EXPECT_EQ(
      term->history_columns(),
      (std::vector<std::string>{"force_x:punch", "force_y:punch", "force_z:punch",
                                "contact_nodes:punch", "penetration:punch", "full_force_x:punch",
                                "full_force_y:punch", "full_force_z:punch"}));
  const auto& other = parts.terms[1];
  const auto* sticking = dynamic_cast<const DieContact*>(other.get());
  ASSERT_NE(sticking, nullptr);
  EXPECT_EQ(sticking->penalty(), 7.5);
  EXPECT_EQ(sticking->n_glued(), 9);
}

}  // namespace
}  // namespace plisse
