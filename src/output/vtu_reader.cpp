#include "output/vtu_reader.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "output/xml_tags.hpp"

namespace plisse {
namespace {

using vtu_detail::attribute;
using vtu_detail::is_space;
using vtu_detail::parse_tag;
using vtu_detail::parse_unsigned;
using vtu_detail::require_attribute;
using vtu_detail::require_unsigned;
using vtu_detail::Tag;
using vtu_detail::VtuFile;

// Byte counts and values are read as the host's bytes, as the writer writes them.
static_assert(std::endian::native == std::endian::little,
              "VTU reader assumes a little-endian host");

/// The XML header is read in chunks until "<AppendedData" appears; a plisse header is a few kB.
constexpr std::size_t kHeaderChunk = 1 << 16;
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t{16} << 20;
/// Largest accepted NumberOfComponents (plisse writes 1, 3, 6 or 9).
constexpr int kMaxComponents = 1 << 16;

enum class Section { none, point_data, cell_data, points, cells };

struct ArrayDecl {
  Section section = Section::none;
  std::string name;
  std::string type;
  int n_components = 1;
  std::uint64_t offset = 0;   ///< from the first byte after '_'
  std::uint64_t n_bytes = 0;  ///< the array's byte count, uncompressed (filled after the header)
  /// Compressed files: the block size, and each block's compressed size (the data follow the
  /// header of 3 + blocks UInt64 values).
  std::uint64_t block_bytes = 0;
  std::vector<std::uint64_t> compressed;
};

const char* section_name(Section s) {
  switch (s) {
    case Section::point_data:
      return "PointData";
    case Section::cell_data:
      return "CellData";
    case Section::points:
      return "Points";
    case Section::cells:
      return "Cells";
    case Section::none:
      break;
  }
  return "";
}

/// Everything the header says, plus where the raw data lie.
struct ParsedVtu {
  VtuSummary summary;
  std::vector<ArrayDecl> arrays;
  std::uint64_t data_start = 0;  ///< first byte after '_'
  std::uint64_t data_end = 0;    ///< position of the closing </AppendedData>
  bool zlib = false;             ///< compressor="vtkZLibDataCompressor"
};

/// Deflate expands at most 1032 times (zlib's technical notes); a compressed array claiming
/// more is corrupt, and is refused before anything of its size is allocated.
constexpr std::uint64_t kMaxInflation = 1032;
/// What a few bytes of deflate can hold beyond that ratio (a stream's fixed overhead).
constexpr std::uint64_t kInflationSlack = 1 << 16;

/// The header of compressed array `a` (output/vtu_writer.hpp: [blocks, block size, last block size
/// or 0, compressed sizes]): fills a.n_bytes, a.block_bytes and a.compressed after checking that
/// the header and the blocks lie in the appended data.
void read_compressed_header(VtuFile& file, const ParsedVtu& out, ArrayDecl& a) {
  const std::uint64_t available = out.data_end - out.data_start - a.offset;
  const auto corrupt = [&](const std::string& what) {
    file.fail("array '" + a.name + "': " + what + " (truncated or corrupt file)");
  };
  constexpr std::uint64_t kWord = sizeof(std::uint64_t);
  if (available < 3 * kWord) corrupt("its compression header lies outside the appended data");
  std::array<std::uint64_t, 3> head{};
  file.read_at(out.data_start + a.offset, head.data(), sizeof head);
  const auto [n_blocks, block_bytes, last_bytes] = head;
  if (n_blocks > available / kWord - 3)
    corrupt(std::to_string(n_blocks) + " compressed blocks declared, more than the file holds");
  if (n_blocks > 0 && (block_bytes == 0 || last_bytes >= block_bytes))
    corrupt("block size " + std::to_string(block_bytes) + " and last block " +
            std::to_string(last_bytes) + " are inconsistent");
  a.compressed.resize(static_cast<std::size_t>(n_blocks));
  file.read_at(out.data_start + a.offset + 3 * kWord, a.compressed.data(), n_blocks * kWord);
  std::uint64_t stored = 0;
  for (const std::uint64_t size : a.compressed) {
    if (size == 0 || size > available - (3 + n_blocks) * kWord - stored)
      corrupt("the compressed blocks reach past the appended data");
    stored += size;
  }
  // n_bytes = (n_blocks - 1) block_bytes + (last_bytes or block_bytes), without overflow, and
  // at most what deflate can expand `stored` bytes to.
  const std::uint64_t last = last_bytes ? last_bytes : block_bytes;
  const std::uint64_t limit = stored * kMaxInflation + kInflationSlack;
  if (n_blocks > 0 && (last > limit || n_blocks - 1 > (limit - last) / block_bytes))
    corrupt("more data declared than " + std::to_string(stored) + " compressed bytes can hold");
  a.block_bytes = block_bytes;
  a.n_bytes = n_blocks == 0 ? 0 : (n_blocks - 1) * block_bytes + last;
  if (a.n_bytes > physical_memory_bytes() / 2)
    file.fail("array '" + a.name + "' inflates to " + std::to_string(a.n_bytes >> 20) +
              " MiB, more than half of this machine's memory: too large to read");
}

ParsedVtu parse(VtuFile& file) {
  // 1. The header: everything before "<AppendedData".
  static constexpr std::string_view kAppended = "<AppendedData";
  std::string buffer;
  std::size_t appended = std::string::npos;
  while (appended == std::string::npos) {
    if (buffer.size() >= file.size())
      file.fail("not a plisse VTU file: no <AppendedData> block (ASCII, base64 or truncated?)");
    if (buffer.size() >= kMaxHeaderBytes)
      file.fail("not a plisse VTU file: no <AppendedData> within the first 16 MiB");
    const std::uint64_t n = std::min<std::uint64_t>(kHeaderChunk, file.size() - buffer.size());
    const std::size_t search_from =
        buffer.size() >= kAppended.size() ? buffer.size() - kAppended.size() : 0;
    buffer += file.read_string(buffer.size(), n);
    appended = buffer.find(kAppended, search_from);
  }
  // The AppendedData tag itself and the '_' that starts the data: read a little past it.
  if (buffer.size() < appended + 256 && buffer.size() < file.size())
    buffer +=
        file.read_string(buffer.size(), std::min<std::uint64_t>(256, file.size() - buffer.size()));
  const std::size_t appended_close = buffer.find('>', appended);
  if (appended_close == std::string::npos) file.fail("truncated in the <AppendedData> tag");
  const Tag appended_tag =
      parse_tag(file, std::string_view(buffer).substr(appended + 1, appended_close - appended - 1));
  const std::string* encoding = attribute(appended_tag, "encoding");
  if (encoding == nullptr || *encoding != "raw")
    file.fail("AppendedData encoding is '" + (encoding ? *encoding : std::string()) +
              "'; only raw is read (plisse's format)");
  std::size_t underscore = appended_close + 1;
  while (underscore < buffer.size() && is_space(buffer[underscore])) ++underscore;
  if (underscore >= buffer.size() || buffer[underscore] != '_')
    file.fail("no '_' marker at the start of the appended data");

  ParsedVtu out;
  out.data_start = underscore + 1;

  // 2. Tags of the header.
  const std::string_view header = std::string_view(buffer).substr(0, appended);
  int n_vtk_files = 0, n_grids = 0, n_pieces = 0;
  Section section = Section::none;
  for (std::size_t pos = header.find('<'); pos != std::string_view::npos;
       pos = header.find('<', pos)) {
    const std::size_t close = header.find('>', pos);
    if (close == std::string_view::npos) file.fail("malformed XML header: unclosed tag");
    std::string_view inside = header.substr(pos + 1, close - pos - 1);
    pos = close + 1;
    if (!inside.empty() && (inside[0] == '?' || inside[0] == '!')) continue;  // declaration
    const Tag tag = parse_tag(file, inside);
    if (tag.name == "PointData" || tag.name == "CellData" || tag.name == "Points" ||
        tag.name == "Cells") {
      const Section s = tag.name == "PointData"  ? Section::point_data
                        : tag.name == "CellData" ? Section::cell_data
                        : tag.name == "Points"   ? Section::points
                                                 : Section::cells;
      if (tag.closing) {
        if (section != s) file.fail("malformed XML header: unexpected </" + tag.name + ">");
        section = Section::none;
      } else {
        if (section != Section::none)
          file.fail("malformed XML header: <" + tag.name + "> inside <" + section_name(section) +
                    ">");
        if (n_pieces != 1) file.fail("<" + tag.name + "> outside a <Piece>");
        if (inside.back() != '/') section = s;  // <PointData/> is empty
      }
      continue;
    }
    if (tag.closing) continue;
    if (tag.name == "VTKFile") {
      ++n_vtk_files;
      if (require_attribute(file, tag, "type") != "UnstructuredGrid")
        file.fail("not an UnstructuredGrid file");
      if (require_attribute(file, tag, "byte_order") != "LittleEndian")
        file.fail("byte order is not LittleEndian");
      if (require_attribute(file, tag, "header_type") != "UInt64")
        file.fail("header_type is not UInt64 (not written by plisse)");
      if (const std::string* compressor = attribute(tag, "compressor")) {
        if (*compressor != "vtkZLibDataCompressor")
          file.fail("compressor '" + *compressor +
                    "' is not read (plisse writes vtkZLibDataCompressor, or none)");
        out.zlib = true;
      }
    } else if (tag.name == "UnstructuredGrid") {
      ++n_grids;
    } else if (tag.name == "Piece") {
      if (++n_pieces > 1) file.fail("several <Piece>s (not written by plisse)");
      out.summary.n_points = require_unsigned(file, tag, "NumberOfPoints");
      out.summary.n_cells = require_unsigned(file, tag, "NumberOfCells");
    } else if (tag.name == "DataArray") {
      if (section == Section::none)
        file.fail("<DataArray> outside PointData, CellData, Points or Cells");
      ArrayDecl a;
      a.section = section;
      a.name = require_attribute(file, tag, "Name");
      a.type = require_attribute(file, tag, "type");
      if (require_attribute(file, tag, "format") != "appended")
        file.fail("DataArray '" + a.name +
                  "' is not in the appended block (format is not "
                  "'appended')");
      a.offset = require_unsigned(file, tag, "offset");
      if (attribute(tag, "NumberOfComponents") != nullptr) {
        const std::uint64_t nc = require_unsigned(file, tag, "NumberOfComponents");
        if (nc < 1 || nc > static_cast<std::uint64_t>(kMaxComponents))
          file.fail("DataArray '" + a.name + "' has " + std::to_string(nc) + " components");
        a.n_components = static_cast<int>(nc);
      }
      out.arrays.push_back(std::move(a));
    }
  }
  if (n_vtk_files != 1 || n_grids != 1 || n_pieces != 1)
    file.fail("not a plisse VTU file: expected one <VTKFile>, <UnstructuredGrid> and <Piece>");
  if (section != Section::none)
    file.fail(std::string("malformed XML header: <") + section_name(section) + "> not closed");

  // 3. The closing tags: a truncated file ends without them.
  const std::uint64_t tail_size = std::min<std::uint64_t>(64, file.size() - out.data_start);
  const std::string tail = file.read_string(file.size() - tail_size, tail_size);
  const std::size_t closing = tail.rfind("</AppendedData>");
  if (closing == std::string::npos || tail.find("</VTKFile>", closing) == std::string::npos)
    file.fail("truncated: the file does not end with </AppendedData></VTKFile>");
  out.data_end = file.size() - tail_size + closing;

  // 4. Every block inside [data_start, data_end), with the size its declaration implies.
  bool has_points = false, has_connectivity = false, has_offsets = false, has_types = false;
  for (ArrayDecl& a : out.arrays) {
    const std::uint64_t available = out.data_end - out.data_start;
    if (available < sizeof(std::uint64_t) || a.offset > available - sizeof(std::uint64_t))
      file.fail("array '" + a.name + "': offset " + std::to_string(a.offset) +
                " lies outside the appended data (truncated or corrupt file)");
    if (out.zlib)
      read_compressed_header(file, out, a);
    else {
      file.read_at(out.data_start + a.offset, &a.n_bytes, sizeof a.n_bytes);
      if (a.n_bytes > available - sizeof(std::uint64_t) - a.offset)
        file.fail("array '" + a.name + "': " + std::to_string(a.n_bytes) +
                  " bytes declared, more than the file holds (truncated or corrupt file)");
    }
    const auto expect = [&](const char* type, std::uint64_t n_entities, std::uint64_t bytes_each) {
      if (a.type != type)
        file.fail("array '" + a.name + "' has type " + a.type + "; plisse writes " + type);
      // n_bytes == n_entities * bytes_each without overflow
      if (a.n_bytes % bytes_each != 0 || a.n_bytes / bytes_each != n_entities)
        file.fail("array '" + a.name + "' holds " + std::to_string(a.n_bytes) + " bytes; " +
                  std::to_string(n_entities) + " entries of " + std::to_string(bytes_each) +
                  " bytes expected (corrupt file)");
    };
    const auto nc = static_cast<std::uint64_t>(a.n_components);
    switch (a.section) {
      case Section::point_data:
        expect("Float64", out.summary.n_points, 8 * nc);
        out.summary.point_fields.push_back({a.name, a.n_components});
        break;
      case Section::cell_data:
        expect("Float64", out.summary.n_cells, 8 * nc);
        out.summary.cell_fields.push_back({a.name, a.n_components});
        break;
      case Section::points:
        if (has_points || nc != 3) file.fail("<Points> must hold one array of 3 components");
        expect("Float64", out.summary.n_points, 24);
        has_points = true;
        break;
      case Section::cells:
        if (a.name == "connectivity") {
          if (a.type != "Int64" || a.n_bytes % 8 != 0)
            file.fail("connectivity is not an Int64 array");
          has_connectivity = true;
        } else if (a.name == "offsets") {
          expect("Int64", out.summary.n_cells, 8);
          has_offsets = true;
        } else if (a.name == "types") {
          expect("UInt8", out.summary.n_cells, 1);
          has_types = true;
        }
        break;
      case Section::none:
        break;
    }
  }
  if (!has_points || !has_connectivity || !has_offsets || !has_types)
    file.fail("not a plisse VTU file: Points or Cells (connectivity, offsets, types) missing");
  return out;
}

const ArrayDecl* find_array(const ParsedVtu& parsed, Section section, std::string_view name) {
  const auto it = std::find_if(parsed.arrays.begin(), parsed.arrays.end(), [&](const ArrayDecl& a) {
    return a.section == section && a.name == name;
  });
  return it == parsed.arrays.end() ? nullptr : &*it;
}

/// The values of one array of T (Float64: double, UInt8: std::uint8_t) whose block parse() checked
/// to fit the file: the allocation is bounded by the file size.
template <class T = double>
std::vector<T> read_values(VtuFile& file, const ParsedVtu& parsed, const ArrayDecl& a) {
  std::vector<T> values(static_cast<std::size_t>(a.n_bytes / sizeof(T)));
  if (!parsed.zlib) {
    file.read_at(parsed.data_start + a.offset + sizeof(std::uint64_t), values.data(),
                 values.size() * sizeof(T));
    return values;
  }
  // Each block inflates to block_bytes (the last to what is left), exactly.
  auto* bytes = reinterpret_cast<unsigned char*>(values.data());
  std::uint64_t position =
      parsed.data_start + a.offset + (3 + a.compressed.size()) * sizeof(std::uint64_t);
  std::vector<unsigned char> block;
  for (std::size_t b = 0; b < a.compressed.size(); ++b) {
    block.resize(static_cast<std::size_t>(a.compressed[b]));
    file.read_at(position, block.data(), block.size());
    position += block.size();
    const std::uint64_t first = b * a.block_bytes;
    const std::uint64_t expected = std::min(a.block_bytes, a.n_bytes - first);
    uLongf produced = static_cast<uLongf>(expected);
    const int status =
        uncompress(bytes + first, &produced, block.data(), static_cast<uLong>(block.size()));
    if (status != Z_OK || produced != expected)
      file.fail("array '" + a.name + "': block " + std::to_string(b) +
                " does not inflate to its declared size (corrupt file)");
  }
  return values;
}

std::string list_names(const std::vector<VtuArrayInfo>& fields) {
  std::string known;
  for (const VtuArrayInfo& f : fields) known += (known.empty() ? "" : ", ") + f.name;
  return known.empty() ? "none" : known;
}

/// The point (Section::point_data) or cell (Section::cell_data) field `name`; fails naming the
/// fields of that kind the file has.
VtuField read_field(VtuFile& file, const ParsedVtu& parsed, Section section,
                    const std::string& name) {
  const bool point = section == Section::point_data;
  const ArrayDecl* a = find_array(parsed, section, name);
  if (a == nullptr)
    file.fail(std::string(point ? "no point field '" : "no cell field '") + name +
              (point ? "' (point fields: " : "' (cell fields: ") +
              list_names(point ? parsed.summary.point_fields : parsed.summary.cell_fields) + ")");
  return {name, a->n_components, read_values(file, parsed, *a)};
}

/// Deepest element nesting accepted in a .pvtu (plisse writes 4 levels); bounds the tag stack.
constexpr std::size_t kMaxPvtuDepth = 32;

bool is_pvtu(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".pvtu";
}

/// What a .pvtu declares.
struct ParsedPvtu {
  std::vector<VtuArrayInfo> point_fields;  ///< PPointData, in file order
  std::vector<VtuArrayInfo> cell_fields;   ///< PCellData
  std::vector<std::string> sources;        ///< Piece Source, in file order, each once
};

/// Parses the whole .pvtu (at most kMaxHeaderBytes): well-nested elements, only whitespace between
/// tags, the structure of output/pvtu_writer.hpp. Unknown elements inside <VTKFile> are skipped.
ParsedPvtu parse_pvtu(VtuFile& file) {
  if (file.size() > kMaxHeaderBytes) file.fail("larger than 16 MiB: not a .pvtu written by plisse");
  const std::string text = file.read_string(0, file.size());
  ParsedPvtu out;
  std::vector<std::string> open;  // names of the elements enclosing the current position
  bool finished = false;          // </VTKFile> seen
  int n_vtk_files = 0, n_grids = 0, n_points_arrays = 0;
  std::set<std::string> sections_seen;
  std::set<std::string> point_names, cell_names, sources;
  for (std::size_t pos = 0;;) {
    const std::size_t lt = text.find('<', pos);
    const std::string_view between =
        std::string_view(text).substr(pos, lt == std::string::npos ? std::string::npos : lt - pos);
    if (!std::all_of(between.begin(), between.end(), is_space))
      file.fail(finished ? "content after </VTKFile>" : "malformed XML: text between tags");
    if (lt == std::string::npos) break;
    if (finished) file.fail("content after </VTKFile>");
    if (text.compare(lt, 4, "<!--") == 0) {
      const std::size_t end = text.find("-->", lt + 4);
      if (end == std::string::npos) file.fail("truncated: unterminated comment");
      pos = end + 3;
      continue;
    }
    if (text.compare(lt, 2, "<?") == 0) {
      const std::size_t end = text.find("?>", lt + 2);
      if (end == std::string::npos) file.fail("truncated: unterminated XML declaration");
      pos = end + 2;
      continue;
    }
    const std::size_t gt = text.find('>', lt);
    if (gt == std::string::npos) file.fail("truncated: unclosed tag at the end of the file");
    const std::string_view inside = std::string_view(text).substr(lt + 1, gt - lt - 1);
    pos = gt + 1;
    if (!inside.empty() && inside[0] == '!')
      file.fail("malformed XML: DOCTYPE or CDATA sections are not read");
    if (inside.find('<') != std::string_view::npos)  // not allowed in names nor attribute values
      file.fail("malformed XML: '<' inside a tag");
    const Tag tag = parse_tag(file, inside);
    if (tag.closing) {
      if (open.empty() || open.back() != tag.name)
        file.fail("malformed XML: unexpected </" + tag.name + ">");
      open.pop_back();
      finished = open.empty();
      continue;
    }
    const bool self_closing = inside.back() == '/';
    const std::string parent = open.empty() ? std::string() : open.back();
    const auto require_parent = [&](const char* expected) {
      if (parent != expected) file.fail("<" + tag.name + "> outside <" + expected + ">");
    };
    if (tag.name == "VTKFile") {
      if (!open.empty() || ++n_vtk_files > 1) file.fail("several <VTKFile> elements");
      if (require_attribute(file, tag, "type") != "PUnstructuredGrid")
        file.fail("not a PUnstructuredGrid file");
      if (require_attribute(file, tag, "byte_order") != "LittleEndian")
        file.fail("byte order is not LittleEndian");
      if (require_attribute(file, tag, "header_type") != "UInt64")
        file.fail("header_type is not UInt64 (not written by plisse)");
    } else if (open.empty()) {
      file.fail("<" + tag.name + "> outside <VTKFile>");
    } else if (tag.name == "PUnstructuredGrid") {
      require_parent("VTKFile");
      if (++n_grids > 1) file.fail("several <PUnstructuredGrid> elements");
      const std::string* ghost = attribute(tag, "GhostLevel");
      if (ghost != nullptr && *ghost != "0")
        file.fail("GhostLevel=\"" + *ghost + "\"; plisse pieces have no ghost cells (0)");
    } else if (tag.name == "PPointData" || tag.name == "PCellData" || tag.name == "PPoints") {
      require_parent("PUnstructuredGrid");
      if (!sections_seen.insert(tag.name).second) file.fail("several <" + tag.name + "> elements");
    } else if (tag.name == "PDataArray") {
      if (parent != "PPointData" && parent != "PCellData" && parent != "PPoints")
        file.fail("<PDataArray> outside PPointData, PCellData or PPoints");
      VtuArrayInfo info{require_attribute(file, tag, "Name"), 1};
      const std::string type = require_attribute(file, tag, "type");
      if (type != "Float64")
        file.fail("PDataArray '" + info.name + "' has type " + type + "; plisse writes Float64");
      if (attribute(tag, "NumberOfComponents") != nullptr) {
        const std::uint64_t nc = require_unsigned(file, tag, "NumberOfComponents");
        if (nc < 1 || nc > static_cast<std::uint64_t>(kMaxComponents))
          file.fail("PDataArray '" + info.name + "' has " + std::to_string(nc) + " components");
        info.n_components = static_cast<int>(nc);
      }
      if (parent == "PPoints") {
        if (++n_points_arrays > 1 || info.n_components != 3)
          file.fail("<PPoints> must hold one array of 3 components");
      } else {
        const bool point = parent == "PPointData";
        if (!(point ? point_names : cell_names).insert(info.name).second)
          file.fail(std::string("two ") + (point ? "point" : "cell") + " fields are named '" +
                    info.name + "'");
        (point ? out.point_fields : out.cell_fields).push_back(std::move(info));
      }
    } else if (tag.name == "Piece") {
      require_parent("PUnstructuredGrid");
      std::string source = require_attribute(file, tag, "Source");
      const std::string problem = pvtu_piece_source_problem(source);
      if (!problem.empty()) file.fail("piece '" + source + "': " + problem);
      // Listed once, after normalisation ("a.vtu" = "./a.vtu"): each piece is read into memory,
      // so aliases of one file must not multiply what a small .pvtu makes the reader hold.
      if (!sources.insert(std::filesystem::path(source).lexically_normal().generic_string()).second)
        file.fail("piece '" + source + "' is listed twice");
      out.sources.push_back(std::move(source));
    }
    if (!self_closing) {
      if (open.size() >= kMaxPvtuDepth) file.fail("malformed XML: elements nested too deeply");
      open.push_back(tag.name);
    }
  }
  if (!finished) file.fail("truncated: the file does not end with </VTKFile>");
  if (n_grids != 1) file.fail("not a plisse PVTU file: no <PUnstructuredGrid>");
  if (n_points_arrays != 1) file.fail("not a plisse PVTU file: no <PPoints> array");
  if (out.sources.empty()) file.fail("lists no <Piece>");
  return out;
}

/// One piece as read for a merge: its counts, the global index of each point and, if asked
/// for, one point field. Errors are the piece's own ("VTU 'piece path': ...").
struct PieceValues {
  std::uint64_t n_points = 0;
  std::uint64_t n_cells = 0;
  std::vector<std::uint64_t> global_node;
  VtuField field;
};

/// Reads the piece at `path`, checks that it holds every field `declared` declares (same
/// component count) and a valid global_node field, and reads the point field `field_name` unless
/// it is empty.
PieceValues read_piece(const std::filesystem::path& path, const ParsedPvtu& declared,
                       const std::string& field_name) {
  VtuFile file(path);
  const ParsedVtu parsed = parse(file);
  const auto check_declared = [&](const std::vector<VtuArrayInfo>& fields, Section section) {
    const char* kind = section == Section::point_data ? "point" : "cell";
    for (const VtuArrayInfo& f : fields) {
      const ArrayDecl* a = find_array(parsed, section, f.name);
      if (a == nullptr)
        file.fail(std::string("no ") + kind + " field '" + f.name + "', which the .pvtu declares");
      if (a->n_components != f.n_components)
        file.fail(std::string(kind) + " field '" + f.name + "' has " +
                  std::to_string(a->n_components) + " components; the .pvtu declares " +
                  std::to_string(f.n_components));
    }
  };
  check_declared(declared.point_fields, Section::point_data);
  check_declared(declared.cell_fields, Section::cell_data);

  PieceValues out;
  out.n_points = parsed.summary.n_points;
  out.n_cells = parsed.summary.n_cells;
  const std::string global_name(kGlobalNodeField);
  const ArrayDecl* global = find_array(parsed, Section::point_data, global_name);
  if (global == nullptr)
    file.fail("no point field '" + global_name +
              "' (the global node index every piece of a .pvtu must hold)");
  if (global->n_components != 1)
    file.fail("point field '" + global_name + "' has " + std::to_string(global->n_components) +
              " components; 1 expected");
  const std::vector<double> indices = read_values(file, parsed, *global);
  out.global_node.reserve(indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const double g = indices[i];
    // Whole numbers below 2^53 are exact in Float64; anything else is not an index.
    if (!(g >= 0.0 && g < 9007199254740992.0 && g == std::floor(g)))
      file.fail("point " + std::to_string(i) + ": " + global_name + " = " + std::to_string(g) +
                " is not a node index (a whole number >= 0)");
    out.global_node.push_back(static_cast<std::uint64_t>(g));
  }
  if (!field_name.empty()) out.field = read_field(file, parsed, Section::point_data, field_name);
  return out;
}

/// Reads every piece of the .pvtu `file` and merges them (output/pvtu_writer.hpp): the summary and,
/// if `field_name` is not empty, that point field in global node order.
std::pair<VtuSummary, VtuField> read_pvtu(const std::filesystem::path& path,
                                          const std::string& field_name) {
  VtuFile file(path, "PVTU");
  const ParsedPvtu declared = parse_pvtu(file);
  if (!field_name.empty() &&
      std::none_of(declared.point_fields.begin(), declared.point_fields.end(),
                   [&](const VtuArrayInfo& f) { return f.name == field_name; }))
    file.fail("no point field '" + field_name +
              "' (point fields: " + list_names(declared.point_fields) + ")");

  std::vector<PieceValues> pieces;
  pieces.reserve(declared.sources.size());
  VtuSummary summary;
  summary.point_fields = declared.point_fields;
  summary.cell_fields = declared.cell_fields;
  std::uint64_t total_points = 0, max_global = 0;
  for (const std::string& source : declared.sources) {
    try {
      pieces.push_back(read_piece(path.parent_path() / source, declared, field_name));
    } catch (const Error& e) {
      file.fail("piece '" + source + "': " + e.what());
    }
    const PieceValues& piece = pieces.back();
    total_points += piece.n_points;  // each term is bounded by its file's size: no overflow
    summary.n_cells += piece.n_cells;
    for (const std::uint64_t g : piece.global_node) max_global = std::max(max_global, g);
  }
  // Every node 0..N-1 appears in some piece, so N <= total_points: checked before allocating.
  const std::uint64_t n_nodes = total_points == 0 ? 0 : max_global + 1;
  if (n_nodes > total_points)
    file.fail(std::string(kGlobalNodeField) + " reaches " + std::to_string(max_global) +
              " but the pieces hold " + std::to_string(total_points) +
              " points in all: some nodes are in no piece");
  summary.n_points = n_nodes;

  VtuField merged;
  std::vector<char> seen(static_cast<std::size_t>(n_nodes), 0);
  if (!field_name.empty()) {
    merged.name = field_name;
    merged.n_components = pieces.front().field.n_components;
    merged.values.resize(static_cast<std::size_t>(n_nodes) *
                         static_cast<std::size_t>(merged.n_components));
  }
  const auto nc = static_cast<std::size_t>(merged.n_components);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const PieceValues& piece = pieces[k];
    for (std::size_t i = 0; i < piece.global_node.size(); ++i) {
      const auto g = static_cast<std::size_t>(piece.global_node[i]);
      if (field_name.empty()) {
        seen[g] = 1;
        continue;
      }
      const double* from = piece.field.values.data() + i * nc;
      double* to = merged.values.data() + g * nc;
      if (!seen[g]) {
        std::copy(from, from + nc, to);
        seen[g] = 1;
      } else if (std::memcmp(from, to, nc * sizeof(double)) != 0) {
        file.fail("piece '" + declared.sources[k] + "': node " + std::to_string(g) + " has " +
                  field_name + " values that differ from another piece's (bit for bit)");
      }
    }
  }
  const auto missing = std::find(seen.begin(), seen.end(), 0);
  if (missing != seen.end())
    file.fail("node " + std::to_string(missing - seen.begin()) + " of " + std::to_string(n_nodes) +
              " is in no piece");
  return {std::move(summary), std::move(merged)};
}

}  // namespace

VtuSummary read_vtu_summary(const std::filesystem::path& path) {
  if (is_pvtu(path)) return read_pvtu(path, "").first;
  VtuFile file(path);
  return parse(file).summary;
}

std::uint64_t read_vtu_point_count(const std::filesystem::path& path) {
  return read_vtu_summary(path).n_points;
}

VtuField read_vtu_point_field(const std::filesystem::path& path, const std::string& name) {
  if (is_pvtu(path)) {
    if (name.empty()) throw Error("PVTU '" + path.string() + "': no point field '' (empty name)");
    return read_pvtu(path, name).second;
  }
  VtuFile file(path);
  const ParsedVtu parsed = parse(file);
  return read_field(file, parsed, Section::point_data, name);
}

VtuField read_vtu_points(const std::filesystem::path& path) {
  if (is_pvtu(path))
    throw Error("PVTU '" + path.string() +
                "': points are read from one piece (.vtu), not from a .pvtu");
  VtuFile file(path);
  const ParsedVtu parsed = parse(file);
  // parse() found exactly one array in <Points> and checked it: Float64, 3 components.
  const auto it = std::find_if(parsed.arrays.begin(), parsed.arrays.end(),
                               [](const ArrayDecl& a) { return a.section == Section::points; });
  return {"Points", 3, read_values(file, parsed, *it)};
}

VtuField read_vtu_cell_field(const std::filesystem::path& path, const std::string& name) {
  if (is_pvtu(path))
    throw Error("PVTU '" + path.string() +
                "': cell fields are read from one piece (.vtu), not from a .pvtu");
  VtuFile file(path);
  const ParsedVtu parsed = parse(file);
  return read_field(file, parsed, Section::cell_data, name);
}

std::vector<std::uint8_t> read_vtu_cell_types(const std::filesystem::path& path) {
  if (is_pvtu(path))
    throw Error("PVTU '" + path.string() +
                "': cell types are read from one piece (.vtu), not from a .pvtu");
  VtuFile file(path);
  const ParsedVtu parsed = parse(file);
  // parse() found the array and checked it: UInt8, one byte per cell.
  return read_values<std::uint8_t>(file, parsed, *find_array(parsed, Section::cells, "types"));
}

}  // namespace plisse
