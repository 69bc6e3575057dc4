#pragma once
/// The 12-node patch of a shell triangle read from the mesh (docs/theory/shell.md, KL1b, KL8,
/// KL8a): which node fills each slot, and what each slot holds (a node, a mirror image of one,
/// or nothing). The shell's element policy (solver/shell_element.hpp) calls these once per
/// element when the model is made.
#include <array>
#include <span>
#include <vector>

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

/// One term of an image slot's displacement: u_target += map u_source, the source a slot that
/// holds a node of the mesh (KL8a).
struct SlotTerm {
  int target = 0;
  int source = 0;
  Mat3d map = Mat3d::Identity();
};

/// The reference positions and kinds of the slots of a patch, and the displacement of every image
/// slot as a linear form in the slots that hold nodes, u_target = Σ map u_source: the image of its
/// source under its side's map about the side's current midpoint, u = R u_source +
/// (I - R)(u_p + u_q)/2 with p, q the side's corners, composed where a slot is the image of an
/// image (KL8a). Empty without mirrored sides.
struct ShellPatchSlots {
  shell::PatchPositions X;
  shell::SlotKinds kinds;
  std::vector<SlotTerm> image_terms;
};

/// The slots of the patch with nodes `nodes` (shell_patch_nodes): a repeated node read as a
/// missing slot (KL8) or, across a side of Mesh::side_mirrors, as the image of its node under
/// that side's map (KL8a); beyond such a side, the images of the slots across the triangle's
/// other sides, so that the mirrored side's gradient is the mean of the triangle's fit and its
/// image's (KL3b).
ShellPatchSlots shell_patch_slots(const Mesh& mesh, std::span<const int, shell::kPatchNodes> nodes);

}  // namespace plisse
