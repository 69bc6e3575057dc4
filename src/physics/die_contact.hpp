#pragma once
/// Contact between the body and a rigid analytic die (plane, sphere, cylinder) with prescribed
/// motion: frictionless (unilateral), sticking ("bilateral sticking": a node that touches stays
/// glued to the die point it touched) or Coulomb friction (a node in contact sticks while its
/// tangential traction is below the coefficient times its pressure, else slides). Node-based
/// augmented Lagrangian with a penalty per unit area, so forces do not depend on the mesh
/// (docs/theory/contact.md).
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/die_contact_settings.hpp"
#include "physics/die_geometry.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

class DieContact : public ModelTerm {
 public:
  /// Contact of the nodes of `candidates` (faces named by their corners, reference tributary areas
  /// D5; on a second-order mesh the edge nodes of the faces with the consistent weights of D16,
  /// and no corner) with `die`. Sticking only: glue is weighted by the tie areas of D17, which
  /// include the corners of second-order faces; the nodes of `region`, and the nodes that lie on
  /// the die at t = 0 (|g| <= touch_slack), are glued from the start at their reference positions
  /// (areas count the faces of both lists, each once). Borrows `mesh`.
  /// Throws plisse::Error when penalty or tolerance is not > 0, friction is < 0 or given to
  /// another law than Coulomb, or a region is given to a die that does not stick.
  /// `mirror_planes` (bits as physics/dirichlet.hpp's mirror_planes): those the die is symmetric
  /// about add the whole body's force to the history.
  DieContact(const Mesh& mesh, DieGeometry die, DieContactSettings settings,
             const std::vector<std::array<int, 3>>& candidates,
             const std::vector<std::array<int, 3>>& region = {}, int mirror_planes = 0);

  /// Residual -f_v on each node v in contact (f_v: force of the die on the body) and its tangent
  /// (contact.md, D6-D8, D12, D18-D20). Remembers t for the updates below.
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  /// Coulomb friction with a coefficient > 0 slides along the die's surface with an unsymmetric
  /// tangent (D20).
  bool symmetric() const override;
  /// When the largest violation at x exceeds the tolerance: Uzawa update of every multiplier
  /// (D9, D14, D21) and true; else false and nothing changes.
  bool update_multipliers(std::span<const double> x) override;
  /// Sticking: glues the nodes that touch the die at x (D13). Coulomb: the tangential traction
  /// and the stick point of every node start the next step from x (D22). Keeps the multipliers.
  void accept_step(std::span<const double> x) override;
  /// Back to the multipliers and glue state of the last accepted step.
  void reject_step() override;
  /// Glue (1) or slide (2) flags, anchors and multipliers of the accepted step (8 numbers per
  /// contact node).
  std::vector<double> save_state() const override;
  void load_state(std::span<const double> state) override;

  /// force_x/y/z:<name> (force of the body ON the die [N], D15), contact_nodes:<name>,
  /// penetration:<name> [mm] (largest violation, D10); Coulomb also stick_nodes:<name> and
  /// slip_nodes:<name>; a die symmetric about a mirror plane also full_force_x/y/z:<name>, the
  /// whole body's force on it.
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

  /// The reference nodes the die has glued, or touches or penetrates at time t (g <=
  /// touch_slack): a glued node, or a Coulomb one with friction (it starts sticking), along x, y
  /// and z; another along the die's normal.
  std::vector<RigidHold> rigid_holds(double t) const override;
  /// Force exerted by the body on the die at (t, x) [N] (D15).
  Vec3d force_on_die(double t, std::span<const double> x) const;
  /// Largest constraint violation [mm]: penetration -g of sliding nodes, |x - anchor| of glued
  /// ones (D10); 0 when nothing touches.
  double violation(double t, std::span<const double> x) const;
  /// Nodes carrying a contact force (sliding with lambda_hat > 0) plus glued nodes.
  int n_contact_nodes(double t, std::span<const double> x) const;
  /// Point fields over the mesh nodes, 0 off the die's contact surface: `contact_<name>`, the
  /// contact state: 0 free, 1 sliding, 2 sticking (glued, or a Coulomb node within its friction
  /// cone; a Coulomb node in contact reports how it ended the last accepted step);
  /// `contact_pressure_<name>`, the normal part of the die's force per reference area [MPa],
  /// positive when the die pushes; `gap_<name>`, the signed gap to the die [mm] (D2-D4).
  std::vector<NodeField> node_fields(double t, std::span<const double> x,
                                     int n_nodes) const override;
  int n_glued() const;
  /// Coulomb: the nodes in contact within their friction cone (first) and on it, sliding
  /// (second), at (t, x) in the step being solved (D19). The history columns stick_nodes and
  /// slip_nodes, written after accept_step, report how the nodes ended the accepted step.
  std::pair<int, int> sticking_and_sliding(double t, std::span<const double> x) const;
  bool glued(int node) const;
  double penalty() const { return settings_.penalty; }
  /// Tributary area of `node` [mm^2]; 0 for a node not on the contact surface (or a corner of a
  /// second-order one, D16).
  double area(int node) const;
  /// Tie area of `node` [mm^2] (D17): the weight of its glue; 0 for a node that the die cannot
  /// glue (not on the surface, or a corner of a second-order face of a frictionless die).
  double tie_area(int node) const;

 private:
  /// Per node: what the augmented Lagrangian carries from step to step.
  struct NodeState {
    bool glued = false;
    bool slid = false;  ///< Coulomb: the node slid in the last accepted step

    double multiplier = 0.0;  ///< lambda [MPa], sliding and Coulomb nodes (D6)
    /// Lambda [MPa]: glued nodes, the tie multiplier (D12); Coulomb nodes, the tangential
    /// traction (D18).
    Vec3d vector_multiplier = Vec3d::Zero();
    /// Glued: glue point minus the die point at gluing; Coulomb: the node's position minus the
    /// die point at the last accepted step, from which it sticks (D18) [mm].
    Vec3d anchor = Vec3d::Zero();
  };
  enum class Contact { none = 0, sliding = 1, sticking = 2 };  ///< the values of node_fields
  /// Force of the die on node i and its derivative K = -df/dx (D6-D8, D12, D18-D20).
  struct NodeResponse {
    Vec3d force = Vec3d::Zero();
    Mat3d K = Mat3d::Zero();
    Contact contact = Contact::none;  ///< none: no force (and not glued)
    double violation = 0.0;           ///< D10
    /// Coulomb: the tangential traction tau (D19) [MPa].
    Vec3d traction = Vec3d::Zero();
  };
  /// Adds the Coulomb friction of node i (D18-D20) to `out`, which holds its normal response
  /// with lambda_hat > 0 at the gap `gap`.
  void add_friction(int i, double t, const Vec3d& xi, const DieGap& gap, double lambda_hat,
                    bool with_tangent, NodeResponse& out) const;
  NodeResponse respond(int i, double t, std::span<const double> x, bool with_tangent) const;
  /// The state reported for node i whose state in the step is `in_step`: a Coulomb node in
  /// contact, how it ended the last accepted step.
  Contact reported(int i, Contact in_step) const;
  /// Nodes sticking (first) and sliding (second) at (t, x): in the step, or `as_reported`.
  std::pair<int, int> count_sticking_and_sliding(double t, std::span<const double> x,
                                                 bool as_reported) const;
  Vec3d position(int i, std::span<const double> x) const;
  /// Position of `node` in nodes_, if it is one of the die's nodes.
  std::optional<size_t> index_of(int node) const;

  const Mesh& mesh_;
  DieGeometry die_;
  DieContactSettings settings_;
  int cut_planes_;                 ///< the mirror planes the die is symmetric about
                                   ///< (DieGeometry::symmetric_planes)
  std::vector<int> nodes_;         ///< mesh node of each contact node, increasing
  std::vector<double> areas_;      ///< reference tributary area [mm^2] (D5, D16)
  std::vector<double> tie_areas_;  ///< reference tie area [mm^2] (D17)
  std::vector<NodeState> state_, accepted_;
  double time_ = 0.0;  ///< time of the last assemble (updates and gluing happen there)
};

/// Default penalty when the case gives 0: epsilon = 10 mu / h [MPa/mm], mu the small-strain shear
/// modulus, h the mean edge length of the contact surface (contact.md, D11).
double default_die_penalty(double shear_modulus, double element_size);

}  // namespace plisse
