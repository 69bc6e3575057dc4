#include "output/vtu_writer.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <bit>
#include <memory>
#include <new>
#include <set>
#include <string_view>
#include <utility>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plisse {
namespace {

// The appended block holds the host's bytes as they are; the header declares LittleEndian.
static_assert(std::endian::native == std::endian::little,
              "VTU writer assumes a little-endian host");
// Points are written straight from memory as 3 contiguous Float64 per point.
static_assert(sizeof(Vec3d) == 3 * sizeof(double), "Vec3d must be 3 packed doubles");

/// Uncompressed bytes per zlib block. VTK's own writer uses 32 KiB; larger blocks deflate a
/// little better, and readers take the size from each array's header.
constexpr std::uint64_t kZlibBlockBytes = std::uint64_t{1} << 20;
/// The fastest level: on plisse's fields (doubles) the higher levels save a few per cent more for
/// several times the time. libdeflate writes the same zlib streams as zlib's compress2, 2.6 times
/// faster at level 1 on a shell's step file (18.8 against 48.6 ms for 3.2 MB, 0.748 against
/// 0.741 of the size).
constexpr int kZlibLevel = 1;

/// For each VTK edge slot of a 10-node tetrahedron, the Gmsh edge slot holding that node.
/// Gmsh's edges 01, 12, 20, 30, 32, 31 become VTK's 01, 12, 20, 03, 13, 23: the last two swap
/// (Gmsh reference manual, "Node ordering"; VTK, vtkQuadraticTetra class documentation).
constexpr std::array<int, 6> kGmshEdgeOfVtkEdge = {0, 1, 2, 3, 5, 4};

void check_fields(const std::filesystem::path& path, const std::vector<VtuField>& fields,
                  std::size_t n_entities, const char* kind) {
  std::set<std::string> names;
  for (const VtuField& f : fields) {
    PLISSE_CHECK(!f.name.empty(),
                 "VTU '" << path.string() << "': a " << kind << " field has no name");
    PLISSE_CHECK(std::none_of(f.name.begin(), f.name.end(),
                              [](char c) { return static_cast<unsigned char>(c) < 0x20; }),
                 "VTU '" << path.string() << "': " << kind << " field name '" << f.name
                         << "' contains a control character");
    PLISSE_CHECK(names.insert(f.name).second, "VTU '" << path.string() << "': two " << kind
                                                      << " fields are named '" << f.name << "'");
    PLISSE_CHECK(
        f.n_components == 1 || f.n_components == 3 || f.n_components == 6 || f.n_components == 9,
        "VTU '" << path.string() << "': " << kind << " field '" << f.name << "' has "
                << f.n_components << " components; must be 1, 3, 6 or 9");
    PLISSE_CHECK(f.values.size() == n_entities * static_cast<std::size_t>(f.n_components),
                 "VTU '" << path.string() << "': " << kind << " field '" << f.name << "' has "
                         << f.values.size() << " values; expected " << n_entities << " " << kind
                         << "s x " << f.n_components << " components = "
                         << n_entities * static_cast<std::size_t>(f.n_components));
  }
}

/// Byte layout of the appended block: offsets (from the byte after '_') of each array, in the
/// order the arrays are declared and written. `stored` is what the array takes there: the UInt64
/// byte count and the raw data, or the compressed header and blocks.
class AppendedLayout {
 public:
  std::uint64_t add(std::uint64_t stored) {
    const std::uint64_t offset = end_;
    end_ += stored;
    return offset;
  }

 private:
  std::uint64_t end_ = 0;
};

void write_block_header(AtomicFile& file, std::uint64_t n_bytes) {
  file.write(&n_bytes, sizeof n_bytes);
}

/// One array as VTK's zlib compressor stores it (vtkZLibDataCompressor; VTK file formats, "XML
/// File Formats", compressed appended data): a header of UInt64 values [number of blocks, block
/// size, size of the last block (0 when it is full), compressed size of each block], then the
/// blocks of `n_bytes` of `data`, each deflated on its own.
std::string zlib_encoded(const void* data, std::uint64_t n_bytes) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  const std::uint64_t n_blocks = (n_bytes + kZlibBlockBytes - 1) / kZlibBlockBytes;
  std::vector<std::uint64_t> header = {n_blocks, kZlibBlockBytes, n_bytes % kZlibBlockBytes};
  std::string blocks;
  const std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
      libdeflate_alloc_compressor(kZlibLevel), &libdeflate_free_compressor);
  if (!compressor) throw std::bad_alloc();
  std::vector<unsigned char> out(
      libdeflate_zlib_compress_bound(compressor.get(), static_cast<std::size_t>(kZlibBlockBytes)));
  for (std::uint64_t b = 0; b < n_blocks; ++b) {
    const std::uint64_t first = b * kZlibBlockBytes;
    const std::uint64_t size = std::min<std::uint64_t>(kZlibBlockBytes, n_bytes - first);
    const std::size_t out_size = libdeflate_zlib_compress(
        compressor.get(), bytes + first, static_cast<std::size_t>(size), out.data(), out.size());
    PLISSE_CHECK(out_size > 0, "VTU: compression failed (a block of " << size << " bytes)");
    header.push_back(out_size);
    blocks.append(reinterpret_cast<const char*>(out.data()), out_size);
  }
  std::string encoded(reinterpret_cast<const char*>(header.data()),
                      header.size() * sizeof(std::uint64_t));
  return encoded + blocks;
}

/// Writes one piece. `node(c, k)` gives node k (VTK order) of cell c; it is called twice per
/// node (check, then write), so the raw format never copies the connectivity whole.
template <class NodeOf>
void write_piece(const std::filesystem::path& path, std::span<const Vec3d> points, VtkCellType type,
                 std::size_t n_cells, const NodeOf& node, const std::vector<VtuField>& point_fields,
                 const std::vector<VtuField>& cell_fields, VtuCompression compression) {
  const std::size_t n_points = points.size();
  const int nodes_per_cell = n_cell_nodes(type);
  for (std::size_t c = 0; c < n_cells; ++c)
    for (int k = 0; k < nodes_per_cell; ++k) {
      const int n = node(c, k);
      PLISSE_CHECK(n >= 0 && static_cast<std::size_t>(n) < n_points,
                   "VTU '" << path.string() << "': cell " << c << " refers to node " << n
                           << ", outside [0, " << n_points << ")");
    }
  check_fields(path, point_fields, n_points, "point");
  check_fields(path, cell_fields, n_cells, "cell");

  const std::uint64_t n_connectivity = static_cast<std::uint64_t>(n_cells) * nodes_per_cell;
  const bool zlib = compression == VtuCompression::zlib;
  // Compressed, every array is encoded first (its stored size sets the offsets of the next).
  std::vector<std::string> encoded;
  if (zlib) {
    for (const auto* fields : {&point_fields, &cell_fields})
      for (const VtuField& f : *fields)
        encoded.push_back(zlib_encoded(f.values.data(), f.values.size() * sizeof(double)));
    encoded.push_back(zlib_encoded(points.data(), n_points * sizeof(Vec3d)));
    std::vector<std::int64_t> cells;
    cells.reserve(n_connectivity);
    for (std::size_t c = 0; c < n_cells; ++c)
      for (int k = 0; k < nodes_per_cell; ++k) cells.push_back(node(c, k));
    encoded.push_back(zlib_encoded(cells.data(), cells.size() * sizeof(std::int64_t)));
    for (std::size_t c = 0; c < n_cells; ++c)
      cells[c] = static_cast<std::int64_t>((c + 1) * static_cast<std::size_t>(nodes_per_cell));
    encoded.push_back(zlib_encoded(cells.data(), n_cells * sizeof(std::int64_t)));
    const std::string types(n_cells, static_cast<char>(type));
    encoded.push_back(zlib_encoded(types.data(), types.size()));
  }
  std::size_t next_array = 0;
  AppendedLayout layout;
  // The offset of the next array, whose raw data are n_bytes long.
  const auto place = [&](std::uint64_t n_bytes) {
    return layout.add(zlib ? encoded[next_array++].size() : sizeof(std::uint64_t) + n_bytes);
  };
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += kUnitsComment;
  xml +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\"";
  xml += zlib ? " compressor=\"vtkZLibDataCompressor\">\n" : ">\n";
  xml += "  <UnstructuredGrid>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(n_points) + "\" NumberOfCells=\"" +
         std::to_string(n_cells) + "\">\n";
  const auto declare_fields = [&](const char* tag, const std::vector<VtuField>& fields) {
    xml += std::string("      <") + tag + ">\n";
    for (const VtuField& f : fields) {
      const std::uint64_t offset = place(f.values.size() * sizeof(double));
      xml += "        <DataArray type=\"Float64\" Name=\"" + escape_xml(f.name) +
             "\" NumberOfComponents=\"" + std::to_string(f.n_components) +
             "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    }
    xml += std::string("      </") + tag + ">\n";
  };
  declare_fields("PointData", point_fields);
  declare_fields("CellData", cell_fields);
  const std::uint64_t points_offset = place(n_points * 3 * sizeof(double));
  xml +=
      "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" "
      "NumberOfComponents=\"3\" format=\"appended\" offset=\"" +
      std::to_string(points_offset) + "\"/>\n      </Points>\n";
  const std::uint64_t connectivity_offset = place(n_connectivity * sizeof(std::int64_t));
  const std::uint64_t offsets_offset = place(n_cells * sizeof(std::int64_t));
  const std::uint64_t types_offset = place(n_cells * sizeof(std::uint8_t));
  xml += "      <Cells>\n";
  xml += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" +
         std::to_string(connectivity_offset) + "\"/>\n";
  xml += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" +
         std::to_string(offsets_offset) + "\"/>\n";
  xml += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" +
         std::to_string(types_offset) + "\"/>\n";
  xml += "      </Cells>\n";
  xml += "    </Piece>\n";
  xml += "  </UnstructuredGrid>\n";
  // The block starts after '_' and ends with a newline before the closing tag.
  xml += "  <AppendedData encoding=\"raw\">\n   _";

  AtomicFile file(path);
  file.write(xml);
  if (zlib) {
    for (const std::string& array : encoded) file.write(array);
    file.write("\n  </AppendedData>\n</VTKFile>\n");
    file.commit();
    return;
  }
  const auto write_field = [&](const VtuField& f) {
    write_block_header(file, f.values.size() * sizeof(double));
    file.write(f.values.data(), f.values.size() * sizeof(double));
  };
  for (const VtuField& f : point_fields) write_field(f);
  for (const VtuField& f : cell_fields) write_field(f);
  write_block_header(file, n_points * 3 * sizeof(double));
  file.write(points.data(), n_points * sizeof(Vec3d));

  // Connectivity, offsets and types are generated in fixed-size chunks: no copy of the mesh.
  constexpr std::size_t kChunk = 4096;
  std::array<std::int64_t, kChunk> chunk;
  std::size_t filled = 0;
  const auto push = [&](std::int64_t value) {
    chunk[filled++] = value;
    if (filled == kChunk) {
      file.write(chunk.data(), filled * sizeof(std::int64_t));
      filled = 0;
    }
  };
  const auto drain = [&] {
    file.write(chunk.data(), filled * sizeof(std::int64_t));
    filled = 0;
  };
  write_block_header(file, n_connectivity * sizeof(std::int64_t));
  for (std::size_t c = 0; c < n_cells; ++c)
    for (int k = 0; k < nodes_per_cell; ++k) push(node(c, k));
  drain();
  // offsets[c] = index one past the last node of cell c in connectivity.
  write_block_header(file, n_cells * sizeof(std::int64_t));
  for (std::size_t c = 0; c < n_cells; ++c)
    push(static_cast<std::int64_t>((c + 1) * static_cast<std::size_t>(nodes_per_cell)));
  drain();
  write_block_header(file, n_cells * sizeof(std::uint8_t));
  const std::string types(n_cells, static_cast<char>(type));
  file.write(types);
  file.write("\n  </AppendedData>\n</VTKFile>\n");
  file.commit();
}

}  // namespace

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

VtuField make_scalar_field(std::string name, std::span<const double> values) {
  return {std::move(name), 1, std::vector<double>(values.begin(), values.end())};
}

VtuField make_vector_field(std::string name, std::span<const Vec3d> vectors) {
  VtuField field{std::move(name), 3, {}};
  field.values.reserve(3 * vectors.size());
  for (const Vec3d& v : vectors) field.values.insert(field.values.end(), {v(0), v(1), v(2)});
  return field;
}

VtuField make_symmetric_tensor_field(std::string name, std::span<const Mat3d> tensors) {
  VtuField field{std::move(name), 6, {}};
  field.values.reserve(6 * tensors.size());
  for (const Mat3d& T : tensors)
    field.values.insert(field.values.end(), {T(0, 0), T(1, 1), T(2, 2), T(0, 1), T(1, 2), T(0, 2)});
  return field;
}

std::vector<Mat3d> symmetric_tensors(const VtuField& field) {
  PLISSE_CHECK(field.n_components == 6, "VTU field '"
                                            << field.name << "' has " << field.n_components
                                            << " components, not the 6 of a symmetric tensor");
  std::vector<Mat3d> tensors(field.values.size() / 6);
  for (std::size_t k = 0; k < tensors.size(); ++k) {
    const double* c = &field.values[6 * k];
    tensors[k] << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
  }
  return tensors;
}

VtuField make_tensor_field(std::string name, std::span<const Mat3d> tensors) {
  VtuField field{std::move(name), 9, {}};
  field.values.reserve(9 * tensors.size());
  for (const Mat3d& T : tensors)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) field.values.push_back(T(i, j));
  return field;
}

int n_cell_nodes(VtkCellType type) {
  switch (type) {
    case VtkCellType::kTriangle:
      return 3;
    case VtkCellType::kTetra:
      return 4;
    case VtkCellType::kQuadraticTriangle:
      return 6;
    case VtkCellType::kQuadraticTetra:
      return 10;
  }
  throw Error("unknown VTK cell type " + std::to_string(static_cast<int>(type)));
}

int n_mesh_cells(const Mesh& mesh) {
  return mesh.is_shell() ? static_cast<int>(mesh.triangles.size()) : mesh.n_tets();
}

void write_vtu(const std::filesystem::path& path, std::span<const Vec3d> points, VtkCellType type,
               std::span<const int> connectivity, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, VtuCompression compression) {
  const auto nodes_per_cell = static_cast<std::size_t>(n_cell_nodes(type));
  PLISSE_CHECK(connectivity.size() % nodes_per_cell == 0,
               "VTU '" << path.string() << "': connectivity has " << connectivity.size()
                       << " entries, not a multiple of " << nodes_per_cell << " nodes per cell");
  write_piece(
      path, points, type, connectivity.size() / nodes_per_cell,
      [&](std::size_t c, int k) { return connectivity[c * nodes_per_cell + k]; }, point_fields,
      cell_fields, compression);
}

void write_vtu(const std::filesystem::path& path, std::span<const Vec3d> points,
               std::span<const std::array<int, 4>> tets, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, VtuCompression compression) {
  write_piece(
      path, points, VtkCellType::kTetra, tets.size(),
      [&](std::size_t c, int k) { return tets[c][k]; }, point_fields, cell_fields, compression);
}

void write_vtu(const std::filesystem::path& path, std::span<const Vec3d> points,
               std::span<const std::array<int, 3>> triangles,
               const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields,
               VtuCompression compression) {
  write_piece(
      path, points, VtkCellType::kTriangle, triangles.size(),
      [&](std::size_t c, int k) { return triangles[c][k]; }, point_fields, cell_fields,
      compression);
}

void write_vtu(const std::filesystem::path& path, const Mesh& mesh, std::span<const Vec3d> points,
               const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields,
               VtuCompression compression) {
  PLISSE_CHECK(points.size() == mesh.nodes.size(),
               "VTU '" << path.string() << "': " << points.size() << " points given for a mesh of "
                       << mesh.nodes.size() << " nodes");
  if (mesh.is_shell()) {
    write_vtu(path, points, std::span<const std::array<int, 3>>(mesh.triangles), point_fields,
              cell_fields, compression);
    return;
  }
  if (mesh.order() == 1) {
    write_vtu(path, points, std::span<const std::array<int, 4>>(mesh.tets), point_fields,
              cell_fields, compression);
    return;
  }
  PLISSE_CHECK(mesh.tet_edge_nodes.size() == mesh.tets.size(),
               "VTU '" << path.string() << "': mesh has " << mesh.tets.size() << " tetrahedra but "
                       << mesh.tet_edge_nodes.size() << " edge-node lists");
  write_piece(
      path, points, VtkCellType::kQuadraticTetra, mesh.tets.size(),
      [&](std::size_t c, int k) {
        return k < 4 ? mesh.tets[c][k] : mesh.tet_edge_nodes[c][kGmshEdgeOfVtkEdge[k - 4]];
      },
      point_fields, cell_fields, compression);
}

}  // namespace plisse
