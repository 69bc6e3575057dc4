#pragma once
/// VTU (VTK XML UnstructuredGrid) writer for ParaView and other VTK readers.
///
/// Format (VTK file formats, "XML File Formats": UnstructuredGrid): version 1.0, byte order
/// LittleEndian, header_type UInt64, one piece, every data array in a single
/// <AppendedData encoding="raw"> block. Uncompressed (VtuCompression::none), each array there is
/// a UInt64 byte count followed by the raw little-endian values. Compressed
/// (VtuCompression::zlib, the attribute compressor="vtkZLibDataCompressor"), each array is a
/// UInt64 header [number of blocks, block size, size of the last block or 0 when it is full,
/// compressed size of each block] followed by its blocks of at most 1 MiB, each deflated by zlib
/// on its own. Points are Float64, connectivity and offsets Int64, types UInt8, fields Float64.
/// The file is written atomically (output/atomic_file.hpp).
///
/// Field component conventions (what ParaView expects):
///   1 component  scalar
///   3 components vector (x, y, z)
///   6 components symmetric tensor in VTK order xx, yy, zz, xy, yz, xz
///   9 components full tensor, row-major: T(i, j) at component 3 i + j
/// Values are stored point-major (or cell-major): all components of point 0, then of point 1...
#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// The XML comment after the declaration of every VTU, PVTU and PVD file plisse writes: the units
/// of its numbers (readers skip it).
inline constexpr const char* kUnitsComment =
    "<!-- plisse: in the case file's consistent units (mm, N, MPa, s in plisse's docs); each "
    "field's unit: plisse outputs vtu-point, plisse outputs vtu-cell -->\n";

/// How the arrays of the appended block are stored (file comment).
enum class VtuCompression {
  none,  ///< raw: the fastest to write and read, about twice the size
  zlib,  ///< deflated blocks (vtkZLibDataCompressor), read by ParaView, VTK and meshio
};

/// VTK cell type ids (vtkCellType.h) of the cells plisse writes. Node order is VTK's.
enum class VtkCellType : std::uint8_t {
  kTriangle = 5,            ///< 3 nodes
  kTetra = 10,              ///< 4 nodes
  kQuadraticTriangle = 22,  ///< 6 nodes: corners, then edges 01, 12, 20 (same as Gmsh)
  kQuadraticTetra = 24,     ///< 10 nodes: corners, then edges 01, 12, 20, 03, 13, 23
};

/// Number of nodes of one cell of `type`.
int n_cell_nodes(VtkCellType type);

/// The cells write_vtu(path, mesh, ...) writes for `mesh`: its triangles for the mid-surface of a
/// shell (Mesh::is_shell), else its tetrahedra.
int n_mesh_cells(const Mesh& mesh);

/// `text` with the XML special characters & < > " ' replaced by entities, for attribute values
/// (field names here, file names in output/pvd_writer).
std::string escape_xml(std::string_view text);

/// A named point or cell field. Owns its values: n_components values per point (or cell),
/// point-major, Float64; n_components is 1, 3, 6 or 9 (see the file comment for their order).
struct VtuField {
  std::string name;  ///< shown in ParaView; unique among the point (resp. cell) fields
  int n_components = 1;
  std::vector<double> values;
};

/// Field builders that put components in VTK's order (file comment), so callers cannot mix it up.
VtuField make_scalar_field(std::string name, std::span<const double> values);
VtuField make_vector_field(std::string name, std::span<const Vec3d> vectors);
/// Symmetric tensors (e.g. Cauchy stress [MPa]) as xx, yy, zz, xy, yz, xz. Reads the upper
/// triangle; the caller guarantees symmetry.
VtuField make_symmetric_tensor_field(std::string name, std::span<const Mat3d> tensors);
/// The tensors of a field written by make_symmetric_tensor_field (6 components a tensor: xx, yy,
/// zz, xy, yz, xz), e.g. read back with read_vtu_cell_field. Throws Error when the field does not
/// have 6 components.
std::vector<Mat3d> symmetric_tensors(const VtuField& field);
/// Full tensors (e.g. F) row-major: T(0,0), T(0,1), T(0,2), T(1,0), ...
VtuField make_tensor_field(std::string name, std::span<const Mat3d> tensors);

/// Writes one piece whose cells all have `type`. `connectivity` lists n_cell_nodes(type) node
/// indices (0-based, into `points`, VTK node order) per cell. `points` [mm] are whatever the
/// caller wants shown: reference or deformed coordinates. Checks every size and index before
/// writing (plisse::Error on violation; no file is written then); throws plisse::Error naming the
/// path when the file cannot be written. An existing file at `path` is replaced atomically.
void write_vtu(const std::filesystem::path& path, std::span<const Vec3d> points, VtkCellType type,
               std::span<const int> connectivity, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields,
               VtuCompression compression = VtuCompression::none);

/// Linear tetrahedra (VTK_TETRA), corner order as in Mesh::tets.
void write_vtu(const std::filesystem::path& path, std::span<const Vec3d> points,
               std::span<const std::array<int, 4>> tets, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields,
               VtuCompression compression = VtuCompression::none);

/// Triangles (VTK_TRIANGLE), e.g. a surface piece for wrinkle metrics.
void write_vtu(const std::filesystem::path& path, std::span<const Vec3d> points,
               std::span<const std::array<int, 3>> triangles,
               const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields,
               VtuCompression compression = VtuCompression::none);

/// The elements of `mesh`: its tetrahedra, VTK_TETRA for a linear mesh, VTK_QUADRATIC_TETRA for a
/// 10-node mesh (edge nodes reordered from Gmsh's 01, 12, 20, 30, 32, 31 to VTK's 01, 12, 20, 03,
/// 13, 23); or, for the mid-surface of a shell (Mesh::is_shell), its triangles, VTK_TRIANGLE.
/// `points` replaces mesh.nodes (e.g. deformed positions) and must have mesh.n_nodes() entries;
/// cell fields hold one value set per element (n_mesh_cells).
void write_vtu(const std::filesystem::path& path, const Mesh& mesh, std::span<const Vec3d> points,
               const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields,
               VtuCompression compression = VtuCompression::none);

}  // namespace plisse
