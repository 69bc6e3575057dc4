// VTU reader (output/vtu_reader.hpp): bit-exact round trip with write_vtu, raw or zlib-compressed,
// and a plisse::Error (never a crash, a huge allocation or a read past the end) for missing fields,
// foreign formats, truncated and corrupted files: every truncation length and every single-byte
// corruption are tried, in both formats.
#include "output/vtu_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::contents;
using test::ScratchDir;

/// A 2-tetrahedron piece with a scalar, a vector (the mode shape) and a tensor point field, and a
/// cell field. Values are not exact in decimal: a lossy path would show.
struct Sample {
  std::vector<Vec3d> points = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1),
                               Vec3d(1, 1, 1)};
  std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  std::vector<VtuField> point_fields;
  std::vector<VtuField> cell_fields;
  Sample() {
    std::vector<double> p;
    std::vector<Vec3d> mode;
    std::vector<Mat3d> stress;
    for (int i = 0; i < 5; ++i) {
      p.push_back((i + 1) / 3.0);
      mode.emplace_back(0.1 * i + 1.0 / 7.0, -i / 11.0, 1e-300 * i);
      stress.push_back(Mat3d::Constant(i / 13.0) + Mat3d::Identity());
    }
    point_fields = {make_scalar_field("pressure", p), make_vector_field("mode_1", mode),
                    make_symmetric_tensor_field("cauchy_stress", stress),
                    make_vector_field("a<b & \"c\"", mode)};
    cell_fields = {make_scalar_field("J", std::vector<double>{1.0 / 3.0, 2.0 / 3.0})};
  }
  void write(const std::filesystem::path& path,
             VtuCompression compression = VtuCompression::none) const {
    write_vtu(path, points, tets, point_fields, cell_fields, compression);
  }
};

constexpr std::array<VtuCompression, 2> kCompressions = {VtuCompression::none,
                                                         VtuCompression::zlib};
std::string name(VtuCompression c) { return c == VtuCompression::zlib ? "zlib" : "raw"; }

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string error_of(const std::filesystem::path& path, const std::string& field = "mode_1") {
  try {
    read_vtu_point_field(path, field);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(VtuReader, RoundTripIsBitExactForThePointsAndEveryPointFieldRawOrCompressed) {
  for (const VtuCompression compression : kCompressions) {
    SCOPED_TRACE(name(compression));
    ScratchDir dir;
    const Sample s;
    s.write(dir / "a.vtu", compression);
    const VtuSummary summary = read_vtu_summary(dir / "a.vtu");
    EXPECT_EQ(summary.n_points, 5u);
    EXPECT_EQ(summary.n_cells, 2u);
    EXPECT_EQ(read_vtu_point_count(dir / "a.vtu"), 5u);
    const VtuField points = read_vtu_points(dir / "a.vtu");
    EXPECT_EQ(points.n_components, 3);
    ASSERT_EQ(points.values.size(), 15u);
    for (std::size_t i = 0; i < 5; ++i)
      EXPECT_EQ(Vec3d(points.values[3 * i], points.values[3 * i + 1], points.values[3 * i + 2]),
                s.points[i]);
    ASSERT_EQ(summary.point_fields.size(), s.point_fields.size());
    ASSERT_EQ(summary.cell_fields.size(), 1u);
    EXPECT_EQ(summary.cell_fields[0].name, "J");
    for (std::size_t k = 0; k < s.point_fields.size(); ++k) {
      const VtuField& written = s.point_fields[k];
      EXPECT_EQ(summary.point_fields[k].name, written.name);  // entities decoded
      EXPECT_EQ(summary.point_fields[k].n_components, written.n_components);
      const VtuField read = read_vtu_point_field(dir / "a.vtu", written.name);
      EXPECT_EQ(read.name, written.name);
      EXPECT_EQ(read.n_components, written.n_components);
      EXPECT_EQ(read.values, written.values);  // bit-exact: raw Float64 both ways
    }
  }
}

TEST(VtuReader, ACompressedArrayOfSeveralBlocksReadsBackBitExact) {
  // 60 000 points: the vector field is 1.44 MB, two zlib blocks (the last one partial), the
  // scalar field one; values that do not repeat, so the blocks do not deflate to nothing.
  ScratchDir dir;
  const int n = 60000;
  std::vector<Vec3d> points, u;
  std::vector<double> p;
  for (int i = 0; i < n; ++i) {
    points.emplace_back(i / 7.0, std::sin(i), std::cos(0.5 * i));
    u.emplace_back(std::sqrt(i + 0.5), -i / 11.0, std::exp(-1e-4 * i));
    p.push_back(std::log1p(i));
  }
  const std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}, {n - 4, n - 3, n - 2, n - 1}};
  const std::vector<VtuField> fields = {make_vector_field("u", u), make_scalar_field("p", p)};
  write_vtu(dir / "big.vtu", points, tets, fields, {}, VtuCompression::zlib);
  write_vtu(dir / "raw.vtu", points, tets, fields, {}, VtuCompression::none);
  EXPECT_NE(contents(dir / "big.vtu").find("compressor=\"vtkZLibDataCompressor\""),
            std::string::npos);
  EXPECT_LT(std::filesystem::file_size(dir / "big.vtu"),
            std::filesystem::file_size(dir / "raw.vtu"));
  EXPECT_EQ(read_vtu_point_field(dir / "big.vtu", "u").values, fields[0].values);
  EXPECT_EQ(read_vtu_point_field(dir / "big.vtu", "p").values, fields[1].values);
}

TEST(VtuReader, CellFieldRoundTripIsBitExactAndAPointFieldIsNoCellField) {
  ScratchDir dir;
  const Sample s;
  s.write(dir / "a.vtu");
  const VtuField read = read_vtu_cell_field(dir / "a.vtu", "J");
  EXPECT_EQ(read.n_components, 1);
  EXPECT_EQ(read.values, s.cell_fields[0].values);
  try {
    read_vtu_cell_field(dir / "a.vtu", "pressure");
    ADD_FAILURE() << "a point field was read as a cell field";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no cell field 'pressure' (cell fields: J)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read_vtu_cell_field(dir / "a.pvtu", "J"), Error);
}

TEST(VtuReader, EmptyPieceAndNoFields) {
  ScratchDir dir;
  write_vtu(dir / "empty.vtu", std::vector<Vec3d>{}, std::vector<std::array<int, 4>>{},
            {make_scalar_field("s", std::vector<double>{})}, {});
  EXPECT_EQ(read_vtu_point_count(dir / "empty.vtu"), 0u);
  EXPECT_TRUE(read_vtu_point_field(dir / "empty.vtu", "s").values.empty());
  EXPECT_NE(error_of(dir / "empty.vtu", "mode_1").find("point fields: s"), std::string::npos);
}

TEST(VtuReader, MissingFieldNamesTheFieldsThereAre) {
  ScratchDir dir;
  Sample().write(dir / "a.vtu");
  const std::string message = error_of(dir / "a.vtu", "mode_2");
  EXPECT_NE(message.find("no point field 'mode_2'"), std::string::npos) << message;
  EXPECT_NE(message.find("mode_1"), std::string::npos) << message;
  EXPECT_NE(message.find("a.vtu"), std::string::npos) << message;
  // A cell field is not a point field.
  EXPECT_NE(error_of(dir / "a.vtu", "J").find("no point field 'J'"), std::string::npos);
}

TEST(VtuReader, UnreadableFilesAreErrors) {
  ScratchDir dir;
  EXPECT_NE(error_of(dir / "missing.vtu").find("no such file"), std::string::npos);
  EXPECT_NE(error_of(dir.path()).find("not a regular file"), std::string::npos);
  write_bytes(dir / "empty.vtu", "");
  EXPECT_NE(error_of(dir / "empty.vtu").find("no <AppendedData>"), std::string::npos);
}

TEST(VtuReader, AFileLargerThanHalfTheMemoryIsRefusedBeforeAnyBlockIsRead) {
  // A sparse file: 100 GiB claimed, no blocks on disk; its blocks would be allocated whole.
  ScratchDir dir;
  write_bytes(dir / "huge.vtu", "<VTKFile type=\"UnstructuredGrid\">");
  ASSERT_EQ(truncate((dir / "huge.vtu").c_str(), std::int64_t{100} << 30), 0);
  EXPECT_NE(error_of(dir / "huge.vtu").find("more than half of this machine's memory"),
            std::string::npos)
      << error_of(dir / "huge.vtu");
}

TEST(VtuReader, ForeignFormatsAreRefusedByName) {
  ScratchDir dir;
  Sample().write(dir / "a.vtu");
  const std::string good = contents(dir / "a.vtu");
  const auto variant = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    write_bytes(dir / "b.vtu", text);
    return error_of(dir / "b.vtu");
  };
  EXPECT_NE(variant("UInt64", "UInt32").find("header_type"), std::string::npos);
  EXPECT_NE(variant("LittleEndian", "BigEndian").find("LittleEndian"), std::string::npos);
  EXPECT_NE(variant("\"UnstructuredGrid\"", "\"PolyData\"").find("UnstructuredGrid"),
            std::string::npos);
  EXPECT_NE(variant("encoding=\"raw\"", "encoding=\"base64\"").find("raw"), std::string::npos);
  EXPECT_NE(variant("format=\"appended\"", "format=\"ascii\"").find("appended"), std::string::npos);
  EXPECT_NE(variant("type=\"Float64\" Name=\"mode_1\"", "type=\"Float32\" Name=\"mode_1\"")
                .find("Float32"),
            std::string::npos);
  EXPECT_NE(variant("NumberOfPoints=\"5\"", "NumberOfPoints=\"6\"").find("expected"),
            std::string::npos);
  EXPECT_NE(variant("NumberOfPoints=\"5\"", "NumberOfPoints=\"x5\"").find("unsigned integer"),
            std::string::npos);
  EXPECT_NE(variant("NumberOfPoints=\"5\"", "NumberOfPoints=\"99999999999999999999999\"")
                .find("unsigned integer"),
            std::string::npos);
  EXPECT_NE(variant("header_type=\"UInt64\"",
                    "header_type=\"UInt64\" compressor=\"vtkLZ4DataCompressor\"")
                .find("compressor 'vtkLZ4DataCompressor'"),
            std::string::npos);
}

std::size_t data_start(const std::string& vtu) {
  return vtu.find('_', vtu.find("<AppendedData")) + 1;
}

TEST(VtuReader, TruncationsAreErrors) {
  for (const VtuCompression compression : kCompressions) {
    SCOPED_TRACE(name(compression));
    ScratchDir dir;
    Sample().write(dir / "a.vtu", compression);
    const std::string good = contents(dir / "a.vtu");
    // Longest first: each truncation is one resize of the same file (cheap on a loaded machine).
    for (std::size_t n = good.size() - 1; n-- > 0;) {
      // (n = size - 1, only the final newline after </VTKFile> gone, is complete and skipped.)
      std::filesystem::resize_file(dir / "a.vtu", n);
      EXPECT_NE(error_of(dir / "a.vtu"), "") << "truncated to " << n << " of " << good.size();
    }
  }
}

TEST(VtuReader, CorruptByteCountsAndOffsetsAreErrors) {
  ScratchDir dir;
  Sample().write(dir / "a.vtu");
  const std::string good = contents(dir / "a.vtu");
  const std::size_t data = data_start(good);
  // The first block's UInt64 byte count set to huge values: no allocation, an error.
  for (const std::uint64_t bad :
       {std::uint64_t{8}, std::uint64_t{1} << 40, ~std::uint64_t{0}, ~std::uint64_t{0} - 7}) {
    std::string text = good;
    std::memcpy(text.data() + data, &bad, sizeof bad);
    write_bytes(dir / "c.vtu", text);
    const std::string message = error_of(dir / "c.vtu", "pressure");
    EXPECT_NE(message, "") << bad;
  }
  // Offsets beyond the file.
  std::string text = good;
  const std::size_t at = text.find("offset=\"0\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 10, "offset=\"18446744073709551615\"");
  write_bytes(dir / "d.vtu", text);
  EXPECT_NE(error_of(dir / "d.vtu", "pressure").find("outside the appended data"),
            std::string::npos);
}

TEST(VtuReader, CorruptCompressionHeadersAreErrorsWithoutHugeAllocations) {
  // The first array's header [blocks, block size, last block, compressed sizes...]: each word set
  // to values a corrupt file could hold. Every one is refused (the inflation bound stops a small
  // block from claiming gigabytes), or, where the change is harmless, read at the right size.
  ScratchDir dir;
  Sample().write(dir / "a.vtu", VtuCompression::zlib);
  const std::string good = contents(dir / "a.vtu");
  const std::size_t data = data_start(good);
  for (std::size_t word = 0; word < 4; ++word)
    for (const std::uint64_t bad : {std::uint64_t{0}, std::uint64_t{2}, std::uint64_t{1} << 20,
                                    std::uint64_t{1} << 40, ~std::uint64_t{0}}) {
      std::string text = good;
      std::memcpy(text.data() + data + 8 * word, &bad, sizeof bad);
      write_bytes(dir / "c.vtu", text);
      try {
        EXPECT_EQ(read_vtu_point_field(dir / "c.vtu", "pressure").values.size(), 5u);
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("c.vtu"), std::string::npos) << e.what();
      }
    }
  // A block size that claims far more than the block can inflate to: refused by the bound.
  std::string text = good;
  const std::uint64_t huge_block = std::uint64_t{1} << 36, full = 0;
  std::memcpy(text.data() + data + 8, &huge_block, sizeof huge_block);
  std::memcpy(text.data() + data + 16, &full, sizeof full);
  write_bytes(dir / "d.vtu", text);
  EXPECT_NE(error_of(dir / "d.vtu", "pressure").find("can hold"), std::string::npos)
      << error_of(dir / "d.vtu", "pressure");
}

TEST(VtuReader, SingleByteCorruptionIsReadOrRefusedNeverACrash) {
  // Each byte in turn replaced by 0xff, then by '<' (in place, then restored): the reader
  // either reads a field of the declared size or throws plisse::Error (anything else fails or
  // crashes the test).
  for (const VtuCompression compression : kCompressions) {
    SCOPED_TRACE(name(compression));
    ScratchDir dir;
    Sample().write(dir / "a.vtu", compression);
    const std::string good = contents(dir / "a.vtu");
    std::fstream file(dir / "a.vtu", std::ios::in | std::ios::out | std::ios::binary);
    const auto put = [&](std::size_t at, char c) {
      file.seekp(static_cast<std::streamoff>(at));
      file.put(c);
      file.flush();
    };
    int refused = 0;
    for (const char replacement : {'\xff', '<'}) {
      for (std::size_t i = 0; i < good.size(); ++i) {
        if (good[i] == replacement) continue;
        put(i, replacement);
        try {
          const VtuField f = read_vtu_point_field(dir / "a.vtu", "mode_1");
          EXPECT_EQ(f.values.size(), 15u) << "byte " << i;
        } catch (const Error&) {
          ++refused;
        }
        put(i, good[i]);
      }
    }
    ASSERT_TRUE(file.good());
    EXPECT_GT(refused, 500);
    EXPECT_EQ(contents(dir / "a.vtu"), good);  // every byte restored
  }
}

}  // namespace
}  // namespace plisse
