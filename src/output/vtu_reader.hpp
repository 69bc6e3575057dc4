#pragma once
/// Reader for the VTU and PVTU files plisse writes (output/vtu_writer.hpp, output/pvtu_writer.hpp),
/// e.g. to seed a "mode" imperfection from the `mode_1` point field of an earlier run, serial or
/// distributed.
///
/// VTU, accepted format, exactly what write_vtu produces: VTKFile type="UnstructuredGrid",
/// byte_order="LittleEndian", header_type="UInt64", no compressor or
/// compressor="vtkZLibDataCompressor"; one Piece; every DataArray format="appended" in one
/// <AppendedData encoding="raw"> block, each array a UInt64 byte count then the data, or
/// compressed, the header of zlib blocks then the blocks (output/vtu_writer.hpp); point and cell
/// fields Float64. Anything else (ASCII or base64 data, other compressors or header types,
/// several pieces) is refused with plisse::Error naming the file and what is wrong.
///
/// PVTU (a path ending in ".pvtu", any case): what write_pvtu produces (format and merge rule in
/// output/pvtu_writer.hpp): VTKFile type="PUnstructuredGrid" (LittleEndian, UInt64), one
/// PUnstructuredGrid (GhostLevel 0 or absent) holding PPointData, PCellData, PPoints (one Float64
/// array of 3 components) and one or more <Piece Source="..."/>. Each Source must be relative to
/// the .pvtu's folder without ".." (pvtu_piece_source_problem), listed once (not again as
/// "./a.vtu" or "d//a.vtu"), and name a plisse VTU checked as above that holds every declared
/// field with the declared component count, plus the point field global_node (1 component, whole
/// numbers >= 0). Errors about a piece name the .pvtu and the piece ("PVTU 'a.pvtu': piece
/// 'p0.vtu': ...").
///
/// Robustness (tests try every truncation and single-byte corruption): every size and offset read
/// from the file is checked against the file size before it is used (a compressed array's
/// inflated size against what deflate can produce from its blocks, at most 1032 times, and against
/// half the machine's memory), so a truncated or corrupt file
/// gives plisse::Error, never a crash, a huge allocation or a read past the end. Every array block
/// must lie inside the appended block, and the file must end with the closing tags (a truncated
/// file is reported as such). A .pvtu larger than 16 MiB is refused before it is read; its XML must
/// be well nested and end with </VTKFile>. The merged node count is checked against the pieces'
/// point counts before anything of that size is allocated.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "output/pvtu_writer.hpp"
#include "output/vtu_writer.hpp"

namespace plisse {

/// What a plisse VTU file holds, after every block was checked to fit the file. For a .pvtu:
/// n_points is the merged node count N (max global_node + 1, every node present), n_cells the
/// sum over the pieces, and the fields are those the .pvtu declares (global_node included).
/// VtuArrayInfo is declared in output/pvtu_writer.hpp.
struct VtuSummary {
  std::uint64_t n_points = 0;
  std::uint64_t n_cells = 0;
  std::vector<VtuArrayInfo> point_fields;  ///< in file order
  std::vector<VtuArrayInfo> cell_fields;
};

/// Reads and checks the header of `path` and the byte counts of all its arrays; for a .pvtu, the
/// .pvtu, every piece that way, and every piece's global_node (the merged node count).
/// Throws plisse::Error ("VTU 'path': ..." or "PVTU 'path': ...") when a file cannot be read, is
/// not in the accepted format, or is truncated or inconsistent.
VtuSummary read_vtu_summary(const std::filesystem::path& path);

/// The number of points of `path` (read_vtu_summary(path).n_points).
std::uint64_t read_vtu_point_count(const std::filesystem::path& path);

/// The point field `name` of `path`: n_components values per point, point-major, as written
/// (VtuField's conventions). For a .pvtu, the pieces' values merged in global node order
/// (output/pvtu_writer.hpp): N points; a node present in several pieces must have bit-identical
/// values there. Throws plisse::Error as read_vtu_summary, and when there is no point field of
/// that name (the message lists the point fields there are).
VtuField read_vtu_point_field(const std::filesystem::path& path, const std::string& name);

/// The points of the VTU `path` (3 values per point: the reference positions the run's step
/// files are written at, an imperfection included). Serial files only, as read_vtu_cell_field.
/// Throws plisse::Error as read_vtu_summary.
VtuField read_vtu_points(const std::filesystem::path& path);

/// The cell field `name` of the VTU `path`: n_components values per cell, cell-major, as written
/// (e.g. cauchy_stress: xx, yy, zz, xy, yz, xz per tetrahedron). Serial files only: a .pvtu's
/// pieces carry no global cell numbering, so a .pvtu is refused. Throws plisse::Error as
/// read_vtu_summary, and when there is no cell field of that name (the message lists them).
VtuField read_vtu_cell_field(const std::filesystem::path& path, const std::string& name);

/// The VTK cell type id of every cell of the VTU `path`, in cell order (VtkCellType's values for
/// the files plisse writes: 10 tetrahedra, 24 quadratic tetrahedra, 5 the triangles of a shell).
/// Serial files only, as read_vtu_cell_field. Throws plisse::Error as read_vtu_summary.
std::vector<std::uint8_t> read_vtu_cell_types(const std::filesystem::path& path);

}  // namespace plisse
