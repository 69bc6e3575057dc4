#pragma once
/// The rigid motions that nothing holds: for each piece of the mesh (elements connected through
/// their nodes), the motions u(X) = a + w x (X - c) that its constrained components and the
/// terms' supports (RigidHold: dies touching it, caps) leave free. A free one makes the tangent
/// singular at the first step: the elements resist no rigid motion, and neither do loads.
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

/// u(X) = translation + rotation x (X - centre).
struct RigidMotion {
  Vec3d translation = Vec3d::Zero();  ///< [mm]
  Vec3d rotation = Vec3d::Zero();     ///< [rad]
  Vec3d centre = Vec3d::Zero();       ///< [mm]

  Vec3d at(const Vec3d& X) const { return translation + rotation.cross(X - centre); }
  /// "translation along x", "translation along [0.6, 0.8, 0]", "rotation about z through
  /// [1, 0, 0]" (the axis through the point of it nearest the centre), or "screw motion about
  /// ..." when the motion also slides along its axis.
  std::string describe() const;
};

/// One piece of the mesh with the rigid motions nothing holds.
struct FreePiece {
  int n_elements = 0;  ///< tetrahedra, or a shell's triangles
  int n_pieces = 0;    ///< pieces in the mesh (1: the body)
  Vec3d centre = Vec3d::Zero();
  double size = 0.0;         ///< the largest distance of its nodes from the centre [mm]
  std::vector<int> members;  ///< its nodes, increasing
  /// A basis of the free motions (1 to 6): the coordinate translations and the rotations about
  /// the coordinate axes through the centre where they are free, else combinations.
  std::vector<RigidMotion> motions;
  /// Per motion, a node of the piece that it moves farthest.
  std::vector<int> nodes;
};

/// "the body of 48 tetrahedra (centred near [0.5, 0.5, 0.5])", or "a piece of the mesh of ..."
/// when the mesh has several: how the messages about `piece` name it.
std::string piece_text(const FreePiece& piece, const Mesh& mesh);
/// "can still move as a rigid body by <motion> (node N at [x, y, z] moves so)", N the node of
/// `piece` that `motion` moves farthest.
std::string free_motion_text(const std::string& motion, const Mesh& mesh, int node);

/// The node of `nodes` that `motion` moves farthest (the first of those it moves alike).
int farthest_moved(const RigidMotion& motion, const Mesh& mesh, const std::vector<int>& nodes);

/// The pieces of `mesh` that can move in some rigid way which neither `constraints` (their
/// displacement components) nor `holds` hold; the nodes of one hold move together, which joins
/// their pieces. Nodes of no element form no piece.
std::vector<FreePiece> free_rigid_motions(const Mesh& mesh,
                                          const std::vector<ConstrainedComponent>& constraints,
                                          const std::vector<RigidHold>& holds);

}  // namespace plisse
