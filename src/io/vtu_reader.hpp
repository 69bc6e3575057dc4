#pragma once
/// Reader for the VTU files plisse writes (io/vtu_writer.hpp), e.g. to seed a "mode"
/// imperfection from the `mode_1` point field of an earlier run.
///
/// Accepted format, exactly what write_vtu produces: VTKFile type="UnstructuredGrid",
/// byte_order="LittleEndian", header_type="UInt64"; one Piece; every DataArray format="appended"
/// in one <AppendedData encoding="raw"> block, each array a UInt64 byte count then the data;
/// point and cell fields Float64. Anything else (ASCII or base64 data, compressed data, other
/// header types, several pieces) is refused with plisse::Error naming the file and what is wrong.
///
/// Robustness (the reader is fuzzed): every size and offset read from the file is checked
/// against the file size before it is used, so a truncated or corrupt file gives plisse::Error,
/// never a crash, a huge allocation or a read past the end. Every array block must lie inside the
/// appended block, and the file must end with the closing tags (a truncated file is reported as
/// such).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/vtu_writer.hpp"

namespace plisse {

/// Name and component count of one field in a VTU file.
struct VtuArrayInfo {
  std::string name;  ///< XML entities decoded
  int n_components = 1;
};

/// What a plisse VTU file holds, after every block was checked to fit the file.
struct VtuSummary {
  std::uint64_t n_points = 0;
  std::uint64_t n_cells = 0;
  std::vector<VtuArrayInfo> point_fields;  ///< in file order
  std::vector<VtuArrayInfo> cell_fields;
};

/// Reads and checks the header of `path` and the byte counts of all its arrays.
/// Throws plisse::Error ("VTU 'path': ...") when the file cannot be read, is not in the accepted
/// format, or is truncated or inconsistent.
VtuSummary read_vtu_summary(const std::filesystem::path& path);

/// The number of points of `path` (read_vtu_summary(path).n_points).
std::uint64_t read_vtu_point_count(const std::filesystem::path& path);

/// The point field `name` of `path`: n_components values per point, point-major, as written
/// (VtuField's conventions). Throws plisse::Error as read_vtu_summary, and when there is no point
/// field of that name (the message lists the point fields there are).
VtuField read_vtu_point_field(const std::filesystem::path& path, const std::string& name);

}  // namespace plisse
