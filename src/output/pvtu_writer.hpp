#pragma once
/// Parallel VTU output: one VTU piece per rank and a .pvtu file that lists the pieces, for
/// distributed runs (ParaView opens the .pvtu and shows the pieces as one mesh).
///
/// The .pvtu file (VTK file formats, "XML File Formats": parallel PUnstructuredGrid), as
/// write_pvtu writes it:
///
///   <?xml version="1.0"?>
///   <VTKFile type="PUnstructuredGrid" version="1.0" byte_order="LittleEndian"
///            header_type="UInt64">
///     <PUnstructuredGrid GhostLevel="0">
///       <PPointData>
///         <PDataArray type="Float64" Name="displacement" NumberOfComponents="3"/>
///         ...the caller's point fields, then
///         <PDataArray type="Float64" Name="global_node" NumberOfComponents="1"/>
///       </PPointData>
///       <PCellData>
///         <PDataArray type="Float64" Name="von_mises" NumberOfComponents="1"/>
///       </PCellData>
///       <PPoints>
///         <PDataArray type="Float64" Name="Points" NumberOfComponents="3"/>
///       </PPoints>
///       <Piece Source="step_0001/piece_0000.vtu"/>
///       <Piece Source="step_0001/piece_0001.vtu"/>
///     </PUnstructuredGrid>
///   </VTKFile>
///
/// Each Source is a VTU file (output/vtu_writer.hpp), named relative to the folder of the .pvtu
/// ('/' separated, no absolute paths and no ".." components, so a run directory can be moved
/// whole). Names and sources are XML-escaped (escape_xml).
///
/// Pieces (write_vtu_piece): every element of the mesh is in exactly one piece; a piece holds
/// the nodes its elements use, numbered locally in increasing global order, so a node on the
/// border of two pieces is written in both. Every piece carries, after the caller's point
/// fields, the point field `global_node` (1 component, Float64, exact up to 2^53): the global
/// index of each local node.
///
/// Merging back (read_vtu_point_field of a .pvtu, output/vtu_reader.hpp): with N = max global_node
/// + 1, the merged point field of node g is the value of any piece at the local node whose
/// global_node is g; every g in [0, N) must appear, and a node present in several pieces must
/// have bit-identical values there. Cell fields concatenate in piece order.
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"
#include "output/vtu_writer.hpp"

namespace plisse {

/// Name and component count of one field of a VTU or PVTU file (also what read_vtu_summary
/// reports).
struct VtuArrayInfo {
  std::string name;  ///< as shown in ParaView (XML entities decoded when read)
  int n_components = 1;
};

/// Name of the point field of every piece that holds the global node index of each point.
inline constexpr std::string_view kGlobalNodeField = "global_node";

/// The names and component counts of `fields`, in order (what write_pvtu declares).
std::vector<VtuArrayInfo> describe_fields(const std::vector<VtuField>& fields);

/// Why `source` cannot name a piece of a .pvtu, or "" if it can: it must be non-empty, relative
/// (no root name or root directory), without ".." components, backslashes or control
/// characters. Shared by write_pvtu and the reader, so whatever is written can be read.
std::string pvtu_piece_source_problem(std::string_view source);

/// Writes the .pvtu file `path` listing `piece_files` (each relative to path's folder, in this
/// order) with the point and cell fields every piece holds. The point field `global_node` is
/// declared after `point_fields` (write_vtu_piece writes it). Checks before writing, with
/// plisse::Error naming `path`: at least one piece; every piece name acceptable
/// (pvtu_piece_source_problem) and listed once ("a.vtu" and "./a.vtu" are the same); field names
/// non-empty, without control characters, unique within point (resp. cell) fields, and no point
/// field named global_node; n_components in {1, 3, 6, 9}. The pieces themselves are not opened
/// (other ranks may still be writing them). Written atomically (output/atomic_file.hpp).
void write_pvtu(const std::filesystem::path& path, const std::vector<std::string>& piece_files,
                const std::vector<VtuArrayInfo>& point_fields,
                const std::vector<VtuArrayInfo>& cell_fields);

/// Writes the VTU piece `path` holding the elements `elements` (indices into mesh.tets, or into
/// mesh.triangles for the mid-surface of a shell; each once, any order; written in the given
/// order) of `mesh`, linear or quadratic tetrahedra or triangles as write_vtu does.
/// The piece's points are the nodes those elements use (corners and, for a quadratic mesh, edge
/// nodes) in increasing global order; their coordinates come from `points` (mesh.n_nodes()
/// entries [mm], e.g. deformed positions). `point_fields` hold one value set per mesh node and
/// `cell_fields` one per mesh element (n_mesh_cells; VtuField's layout); the piece gets their
/// restrictions, then the point field global_node. An empty `elements` gives an empty piece (a rank
/// without elements). Throws plisse::Error naming `path` on any size, index or name violation (no
/// file is written then) and when the file cannot be written. `compression` as write_vtu's.
void write_vtu_piece(const std::filesystem::path& path, const Mesh& mesh,
                     std::span<const Vec3d> points, std::span<const int> elements,
                     const std::vector<VtuField>& point_fields,
                     const std::vector<VtuField>& cell_fields,
                     VtuCompression compression = VtuCompression::none);

}  // namespace plisse
