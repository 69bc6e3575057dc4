#pragma once
/// Reading and writing Gmsh `.msh` files through the Gmsh SDK (v2 and v4, ASCII and binary):
/// tetrahedral meshes and the triangulated mid-surfaces of shells.
///
/// Conventions of the Mesh produced by `read_gmsh` (docs/meshes.md, "Your own mesh"):
/// - nodes are all nodes of the file, renumbered 0..n-1 in increasing Gmsh node tag; nodes that no
///   tetrahedron uses are kept (check_mesh warns about them);
/// - tetrahedra and triangles are in increasing Gmsh element tag; an element repeated with the
///   same nodes (as Gmsh's v2 writer does for an element in several physical groups) is kept once
///   and belongs to all those groups;
/// - tetrahedra numbered with negative volume are renumbered (corners 1 and 2 swapped, edge nodes
///   accordingly): in a reference mesh the sign is only a numbering convention, so the reader
///   normalises it; degenerate (zero-volume) tetrahedra are left for check_mesh to report;
/// - boundary triangles are oriented with the outward normal by the right-hand rule (a triangle
///   that is not a boundary face of the tetrahedra keeps the file's orientation);
/// - physical groups of dimension 0 and 1, and the group "plisse:untagged" that `write_gmsh`
///   adds to v2 files, are ignored.
/// `read_gmsh_surface` reads the triangulated mid-surface of a shell instead (below).
#include <cstdint>
#include <string>

#include "mesh/isolated_process.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Name of the physical groups `write_gmsh` adds to v2 files to keep untagged elements and
/// unused nodes (Gmsh's v2 writer drops elements outside physical groups); `read_gmsh` skips it.
inline constexpr const char* kUntaggedGroupName = "plisse:untagged";

/// What `read_gmsh` normalised (for log messages).
struct GmshReadInfo {
  int n_flipped_tets = 0;        ///< tetrahedra renumbered to positive orientation
  int n_flipped_triangles = 0;   ///< boundary triangles turned to the outward orientation
  int n_duplicate_elements = 0;  ///< repeated tetrahedra/triangles merged
};

/// Reads a tetrahedral mesh. Physical groups of dimension 2 become surface tags, of dimension 3
/// volume tags (unnamed groups are called "<dim>:<tag>"). Linear and second-order (10-node)
/// tetrahedra are read; other volume element types, a missing or unreadable file, a mesh without
/// tetrahedra, and a file that is not named "*.msh" or does not begin like an MSH file
/// ("$MeshFormat", "$NOD", ...: Gmsh would run it as a .geo script) are reported as InputError
/// naming the file.
///
/// The Gmsh SDK reads the file in a forked child process with resource limits
/// (`gmsh_reader_limits`, isolated_process.hpp), which sends the model back through a pipe
/// (gmsh_raw_model.hpp): a file on which Gmsh crashes, allocates without bound or loops is an
/// InputError "the mesh file is malformed: ..." naming the signal or the limit, not a crash of
/// plisse. Gmsh's own error messages are kept. Thread-safe (readers are serialised).
Mesh read_gmsh(const std::string& path);
/// Same, and reports what was normalised in `info`.
Mesh read_gmsh(const std::string& path, GmshReadInfo& info);
/// Same with other limits for the reader process than `gmsh_reader_limits` (the fuzzer uses
/// tighter ones, so that an input on which Gmsh loops costs seconds, not minutes).
Mesh read_gmsh(const std::string& path, GmshReadInfo& info, const ChildLimits& limits);

/// Reads the mid-surface of a shell (docs/meshes.md, "Shell meshes"): a mesh of 3-node
/// triangles and no tetrahedra, whose triangles are the shell's elements. Nodes, duplicates and
/// the reader process as read_gmsh. Physical groups of dimension 2 become surface tags (indices
/// into `triangles`), of dimension 1 edge tags: the 2-node line elements of the physical curves
/// become Mesh::edges, once each, in increasing element tag, and the tags list indices into
/// them; line elements in no physical curve are ignored, as are groups of dimension 0 and the
/// group "plisse:untagged". Unnamed groups are called "<dim>:<tag>".
/// Orientation: the triangles are made consistent across every edge, piece by piece (pieces
/// connected through shared edges), breadth first from the piece's first triangle in the file,
/// whose orientation an open piece keeps; a closed piece (every edge shared by two of its
/// triangles) is then turned outward (positive enclosed volume). `info.n_flipped_triangles`
/// counts the triangles turned.
/// InputError naming the file and the rule, besides read_gmsh's: tetrahedra ("a shell mesh is a
/// surface: this file has N tetrahedra") or other volume elements, higher-order triangles or
/// lines, quadrilaterals (triangulate), no triangles, a triangle that repeats a node, an edge of
/// more than two triangles, a line element of a physical curve that is not a side of a triangle,
/// a surface that cannot be oriented (a Moebius strip).
/// Does not call make_shell_surface (mesh/shell_surface.hpp): the caller knows the thickness.
/// Nodes that no triangle uses are kept, as read_gmsh keeps them.
Mesh read_gmsh_surface(const std::string& path);
/// Same, and reports what was normalised in `info`.
Mesh read_gmsh_surface(const std::string& path, GmshReadInfo& info);
/// Same with other limits for the reader process than `gmsh_reader_limits`.
Mesh read_gmsh_surface(const std::string& path, GmshReadInfo& info, const ChildLimits& limits);

/// Resource limits of the reader process for a file of `file_bytes` bytes: memory 1 GiB + 64 bytes
/// per file byte (beyond what plisse had mapped), CPU time 10 s + 4 s per MiB, wall time twice the
/// CPU time + 10 s. Gmsh needs far less on a well-formed file: 5-6 bytes per byte of file and
/// about 0.02 s per MiB (fuzz/README.md).
ChildLimits gmsh_reader_limits(std::uintmax_t file_bytes);

/// Writes `mesh` with its tags as physical groups. `version` is 2.2 or 4.1. The file name must end
/// in ".msh" (InputError otherwise; also when the file cannot be written, or was not written
/// whole: a full disk or a file size limit, which Gmsh does not report, shows as a file that ends
/// before its last section's end line).
/// Round trip through `read_gmsh`: nodes, tetrahedra, triangles and non-empty tags come back
/// identical, coordinates bit for bit in binary files and to Gmsh's 16 significant digits in
/// ASCII files. Empty tags are not written (Gmsh stores no empty physical group).
/// A shell's mid-surface (triangles and no tetrahedra) is written as its triangles, with
/// `surface_tags` as physical groups of dimension 2, and its `edges` as 2-node line elements,
/// with `edge_tags` as physical groups of dimension 1; `read_gmsh_surface` reads it back with
/// the same nodes, triangles (consistently oriented, a closed piece outward, as the reader
/// makes them), tags and, when every edge is in an edge tag, edges. The thickness and the
/// other shell data (mesh/shell_surface.hpp) are not written.
void write_gmsh(const Mesh& mesh, const std::string& path, double version = 4.1,
                bool binary = false);

}  // namespace plisse
