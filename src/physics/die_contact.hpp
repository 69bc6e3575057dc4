#pragma once
/// Contact between the body and a rigid analytic die (plane, sphere, cylinder) with prescribed
/// motion: frictionless (unilateral) or sticking ("bilateral sticking": a node that touches stays
/// glued to the die point it touched). Node-based augmented Lagrangian with a penalty per unit
/// area, so forces do not depend on the mesh (docs/theory/contact.md).
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
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
  /// Throws plisse::Error when penalty or tolerance is not > 0, or frictionless with a region.
  DieContact(const Mesh& mesh, DieGeometry die, DieContactSettings settings,
             const std::vector<std::array<int, 3>>& candidates,
             const std::vector<std::array<int, 3>>& region = {});

  /// Residual -f_v on each node v in contact (f_v: force of the die on the body) and its tangent,
  /// symmetric (contact.md, D6-D8, D12). Remembers t for the updates below.
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  /// When the largest violation at x exceeds the tolerance: Uzawa update of every multiplier
  /// (D9, D14) and true; else false and nothing changes.
  bool update_multipliers(std::span<const double> x) override;
  /// Sticking: glues the nodes that touch the die at x (D13); keeps multipliers and glue state.
  void accept_step(std::span<const double> x) override;
  /// Back to the multipliers and glue state of the last accepted step.
  void reject_step() override;
  /// Glue flags, anchors and multipliers of the accepted step (8 numbers per contact node).
  std::vector<double> save_state() const override;
  void load_state(std::span<const double> state) override;

  /// force_x/y/z:<name> (force of the body ON the die [N], D15), contact_nodes:<name>,
  /// penetration:<name> [mm] (largest violation, D10).
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

  /// Force exerted by the body on the die at (t, x) [N] (D15).
  Vec3d force_on_die(double t, std::span<const double> x) const;
  /// Largest constraint violation [mm]: penetration -g of sliding nodes, |x - anchor| of glued
  /// ones (D10); 0 when nothing touches.
  double violation(double t, std::span<const double> x) const;
  /// Nodes carrying a contact force (sliding with lambda_hat > 0) plus glued nodes.
  int n_contact_nodes(double t, std::span<const double> x) const;
  int n_glued() const;
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
    double multiplier = 0.0;                ///< lambda [MPa], sliding nodes (D6)
    Vec3d glue_multiplier = Vec3d::Zero();  ///< Lambda [MPa], glued nodes (D12)
    Vec3d anchor = Vec3d::Zero();           ///< glue point minus the die point at gluing [mm]
  };
  /// Force of the die on node i and its derivative K = -df/dx (D6-D8, D12).
  struct NodeResponse {
    Vec3d force = Vec3d::Zero();
    Mat3d K = Mat3d::Zero();
    bool active = false;     ///< carries a force (sliding) or glued
    double violation = 0.0;  ///< D10
  };
  NodeResponse respond(int i, double t, std::span<const double> x, bool with_tangent) const;
  Vec3d position(int i, std::span<const double> x) const;
  /// Position of `node` in nodes_, if it is one of the die's nodes.
  std::optional<size_t> index_of(int node) const;

  const Mesh& mesh_;
  DieGeometry die_;
  DieContactSettings settings_;
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
