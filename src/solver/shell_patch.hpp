#pragma once
/// The 12-node patch of a shell triangle read from the mesh (docs/theory/shell.md, KL1b, KL8,
/// KL8a): which node fills each slot, and what each slot holds (a node, a mirror image of one,
/// or nothing). The shell's element policy (solver/shell_element.hpp) calls these once per
/// element when the model is made.
#include <array>
#include <span>

#include "element/shell_geometry.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// The nodes of triangle e's patch, slot by slot (KL1b): the corners, the nodes across its sides
/// (mesh.triangle_neighbours) and across its neighbours' other sides (mesh.triangle_adjacent). A
/// slot without a node repeats the node whose image it stands for: corner i for slot 3 + i and
/// corner i + 1 + w for slot 6 + 2i + w (KL8), or, beyond a side of Mesh::side_mirrors, the node
/// of the slot across one of the triangle's other sides that the side's map takes there (KL8a).
/// Precondition: mesh.is_shell().
std::array<int, shell::kPatchNodes> shell_patch_nodes(const Mesh& mesh, int e);

/// The reference positions and kinds of the slots of a patch, with the linear part M of the map
/// that gives an image slot's displacement from its node's, u_slot = M u_node (the identity for
/// the other slots).
struct ShellPatchSlots {
  shell::PatchPositions X;
  shell::SlotKinds kinds;
  std::array<bool, shell::kPatchNodes> image{};
  std::array<Mat3d, shell::kPatchNodes> map;
};

/// The slots of the patch with nodes `nodes` (shell_patch_nodes): a repeated node read as a
/// missing slot (KL8) or, across a side of Mesh::side_mirrors, as the image of its node under
/// that side's map (KL8a); beyond such a side, the images of the slots across the triangle's
/// other sides, so that the mirrored side's gradient is the mean of the triangle's fit and its
/// image's (KL3b).
ShellPatchSlots shell_patch_slots(const Mesh& mesh, std::span<const int, shell::kPatchNodes> nodes);

}  // namespace plisse
