#pragma once
/// Frictionless contact between two tagged surfaces of the body, or of one surface with itself:
/// each node of the first surface is kept out of the facets of the second by a node-based
/// augmented Lagrangian with a penalty per unit area, as for the rigid dies; the facets are the
/// surface's triangles (a 6-node face counts as its four flat sub-triangles). Candidate facets
/// are found with a bounding-volume hierarchy (Eigen's KdBVH). On a shell the surfaces are faces
/// of the shell, half its thickness off the mid-surface that carries the nodes and facets.
/// docs/theory/surface-contact.md.
#include <array>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/model_term.hpp"
#include "physics/node_facet_gap.hpp"

namespace plisse {

/// A `contacts:` entry as the case file gives it: two surfaces, or one with itself
/// (terms/surface_contact.cpp turns it into SurfaceContactSettings).
struct ContactPairSettings {
  std::string name;                  ///< history columns `force_x:<name>` ...
  std::optional<SurfaceRef> first;   ///< `surfaces: [first, second]`: nodes of first ...
  std::optional<SurfaceRef> second;  ///< ... kept out of the faces of second
  std::optional<SurfaceRef> self;    ///< `self:` one surface against itself
  double penalty = 0.0;              ///< [MPa/mm]; 0: chosen from the material and mesh
  double tolerance = 1e-3;           ///< allowed penetration [mm], > 0
  double search_distance = 0.0;      ///< [mm]; 0: the mean edge length of the surfaces
  InputPlace place;
};

/// Parameters of one surface contact (docs/theory/surface-contact.md).
struct SurfaceContactSettings {
  std::string name;         ///< history columns force_x:<name> ...
  double penalty = 0.0;     ///< epsilon [MPa/mm], > 0: contact pressure per unit penetration
  double tolerance = 1e-3;  ///< largest penetration [mm], > 0
  /// A node pairs with a facet when its gap lies within +- this [mm] (> 0); it also sets how far
  /// around a node the tangent's sparsity reaches (N6).
  double search_distance = 1.0;
};

class SurfaceContact : public ModelTerm {
 public:
  /// The nodes of `nodes_from` (faces named by their corners, outward; contact weights of D5 and
  /// D16) against the facets of `facets_from` (outward). `self`: the two lists are one surface,
  /// and a node skips the facets that touch its own faces (N4), as it does on a shell, whose
  /// faces are triangles of the mesh (Mesh::triangle_thickness gives their offsets, N14). Borrows
  /// `mesh`. Throws plisse::Error when penalty, tolerance or search distance is not > 0, or a list
  /// is empty.
  SurfaceContact(const Mesh& mesh, SurfaceContactSettings settings,
                 const std::vector<std::array<int, 3>>& nodes_from,
                 const std::vector<std::array<int, 3>>& facets_from, bool self);

  /// Residual and symmetric tangent of every pair in contact (N2, N3).
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  void add_couplings(std::vector<std::pair<int, int>>& pairs) const override;
  bool couplings_changed() override;
  /// Uzawa update of every multiplier when the largest penetration exceeds the tolerance (N5);
  /// new pairs where the state at x pairs nodes differently (N4). True when either happened.
  bool update_multipliers(std::span<const double> x) override;
  void accept_step(std::span<const double> x) override;
  void reject_step() override;
  /// Multipliers and pairs of the accepted step, then the declared node pairs (for an exact
  /// restart).
  std::vector<double> save_state() const override;
  void load_state(std::span<const double> state) override;

  /// force_x/y/z:<name> (force of the second surface on the first [N]), contact_nodes:<name>,
  /// penetration:<name> [mm].
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;
  /// `contact_<name>`: the contact pressure lambda_hat [MPa, per reference area] at the contact
  /// nodes, 0 elsewhere.
  std::vector<NodeField> node_fields(double t, std::span<const double> x,
                                     int n_nodes) const override;

  /// The facet each contact node is paired with (-1: none), in the order of nodes(): found at
  /// the last accepted step or multiplier update, and held while Newton iterates (N4).
  const std::vector<int>& pairs() const { return pairs_; }
  /// The facet each contact node would pair with at x (-1: none) (N4); a node keeps its facet
  /// in `keep` (one per contact node, or empty) while that one still qualifies.
  std::vector<int> find_pairs(std::span<const double> x, std::span<const int> keep = {}) const;
  /// Force of the second surface on the first at x [N] (N7).
  Vec3d force(std::span<const double> x) const;
  /// Largest penetration at x [mm] (0 when nothing penetrates).
  double penetration(std::span<const double> x) const;
  int n_contact_nodes(std::span<const double> x) const;
  const std::vector<int>& nodes() const { return nodes_; }
  const std::vector<std::array<int, 3>>& facets() const { return facets_; }
  double penalty() const { return settings_.penalty; }

 private:
  /// Gap, multiplier and pair of one node at x.
  struct Contact {
    int facet = -1;                ///< -1: no facet within reach
    double gap = 0.0;              ///< [mm]
    double lambda_hat = 0.0;       ///< max(0, lambda - eps g) [MPa]
    Vec3d normal = Vec3d::Zero();  ///< the facet's unit normal (N9)
  };
  std::vector<Contact> contacts(std::span<const double> x) const;
  /// The gap of contact node i to `facet` at x, with its derivatives (N9-N13).
  NodeFacetGap gap(size_t i, int facet, std::span<const double> x, bool with_hessian) const;
  /// Largest penetration -g of the paired nodes, 0 when none penetrates.
  static double largest_penetration(const std::vector<Contact>& contacts);
  /// Deformed positions of the facets' nodes (those of both surfaces; the others are zero).
  std::vector<Vec3d> positions(std::span<const double> x) const;
  /// Whether node i may pair with facet f at all (not one of its own or, for self contact,
  /// neighbouring facets).
  bool excluded(size_t i, int f) const;
  /// The node pairs (contact node, facet node) within reach at x (N6).
  std::set<std::pair<int, int>> reachable_pairs(std::span<const double> x) const;
  /// How far the faces of contact node i and of `facet` lie off the mid-surfaces that carry
  /// them, together [mm]: the gap is the planes' distance less this (N14; 0 on a solid).
  double offset(size_t i, int facet) const { return node_offsets_[i] + facet_offsets_[facet]; }

  const Mesh& mesh_;
  SurfaceContactSettings settings_;
  bool self_;
  std::vector<int> nodes_;     ///< contact nodes, increasing
  std::vector<double> areas_;  ///< their reference tributary areas [mm^2]
  /// On a shell, half the reference thickness at each contact node and of each facet [mm]; 0 on
  /// a solid (N14).
  std::vector<double> node_offsets_, facet_offsets_;
  double widest_offset_ = 0.0;  ///< the largest node offset plus the largest facet offset [mm]
  std::vector<std::array<int, 3>> facets_;      ///< outward flat facets (mesh nodes)
  std::vector<std::array<int, 3>> own_facets_;  ///< flat facets of the nodes' own surface
  std::vector<std::vector<int>> node_faces_;    ///< per contact node, its own facets (normals)
  std::vector<std::vector<int>> excluded_;      ///< per contact node, facets it skips, sorted
  std::vector<double> multipliers_, accepted_;  ///< lambda per contact node [MPa]
  std::vector<int> pairs_, accepted_pairs_;     ///< facet per contact node, -1: none
  std::set<std::pair<int, int>> declared_;      ///< node pairs in the tangent's sparsity
  bool declared_grew_ = false;
};

}  // namespace plisse
