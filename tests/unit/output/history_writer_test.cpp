#include "output/history_writer.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::contents;
using test::entries;
using test::from_hex;
using test::read_with_python;
using test::ScratchDir;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

const std::vector<std::string> kExtra = {"pressure:gas", "volume:cavity",   "force_y:punch",
                                         "ux:inner",     "negative_pivots", "stable"};

/// Rows with values that lose bits under any fixed-precision printing.
std::vector<std::vector<double>> tricky_rows() {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  return {
      {0, 0.0, 0.0, 0, 0.0, 1e-4, 1.0 / 3.0, -0.0, 0.1, 0, 1},
      {1, 0.1, 0.1 + 0.2, 4, 1.2345678901234567e-9, 2.0 / 3.0, tiny, -huge, 1e300, 12, 0},
      {2, 1e-17, 0.30000000000000004, 25, 5e-324, std::nextafter(1.0, 2.0), -1e-310,
       123456789012345678.0, -2.5, 0, 1},
  };
}

TEST(HistoryWriter, RowsReadBackBitForBit) {
  const ScratchDir dir;
  const auto path = dir / "history.csv";
  HistoryWriter history(path, kExtra);
  EXPECT_EQ(contents(path),
            "step,time,load_factor,newton_iterations,residual_norm,pressure:gas,volume:cavity,"
            "force_y:punch,ux:inner,negative_pivots,stable\n");
  for (const auto& row : tricky_rows()) history.add_row(row);
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"history.csv"});
  EXPECT_EQ(history.column_index("force_y:punch"), std::optional<std::size_t>(7));
  EXPECT_EQ(history.column_index("nothing"), std::nullopt);

  // Our reader.
  const HistoryTable table = read_history(path);
  EXPECT_EQ(table.columns, history.columns());
  ASSERT_EQ(table.rows.size(), 3u);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      EXPECT_EQ(bits(table.rows[r][c]), bits(tricky_rows()[r][c])) << "row " << r << " col " << c;

  // An independent reader: Python's csv module and float().
  const nlohmann::json read = read_with_python("csv", path);
  ASSERT_FALSE(read.is_null());
  EXPECT_EQ(read["header"].get<std::vector<std::string>>(), history.columns());
  ASSERT_EQ(read["rows"].size(), 3u);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      EXPECT_EQ(bits(from_hex(read["rows"][r][c])), bits(tricky_rows()[r][c]));

  // Integers and flags print as integers.
  EXPECT_NE(contents(path).find("\n1,0.1,0.30000000000000004,4,"), std::string::npos);
}

TEST(HistoryWriter, NonFiniteValuesRoundTrip) {
  const ScratchDir dir;
  const auto path = dir / "history.csv";
  HistoryWriter history(path, {});
  const double inf = std::numeric_limits<double>::infinity();
  history.add_row({3, inf, -inf, 25, std::nan("")});
  const HistoryTable table = read_history(path);
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0][1], inf);
  EXPECT_EQ(table.rows[0][2], -inf);
  EXPECT_TRUE(std::isnan(table.rows[0][4]));
}

TEST(HistoryWriter, RowOfWrongSizeIsRejectedAndFileUnchanged) {
  const ScratchDir dir;
  const auto path = dir / "history.csv";
  HistoryWriter history(path, {"stretch"});
  history.add_row({1, 0.5, 0.5, 3, 1e-10, 1.5});
  const std::string before = contents(path);
  EXPECT_THROW(history.add_row({2, 1.0, 1.0, 3, 1e-10}), Error);
  EXPECT_EQ(contents(path), before);
  EXPECT_EQ(history.rows().size(), 1u);
}

TEST(HistoryWriter, BadColumnNamesAreRejected) {
  const ScratchDir dir;
  EXPECT_THROW(HistoryWriter(dir / "h.csv", {"a,b"}), Error);
  EXPECT_THROW(HistoryWriter(dir / "h.csv", {""}), Error);
  EXPECT_THROW(HistoryWriter(dir / "h.csv", {"x", "x"}), Error);
  EXPECT_THROW(HistoryWriter(dir / "h.csv", {"time"}), Error);  // clashes with a standard one
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(HistoryWriter, ReopenContinuesAndCanDropLaterRows) {
  const ScratchDir dir;
  const auto path = dir / "history.csv";
  {
    HistoryWriter history(path, {"cauchy_zz"});
    history.add_row({1, 0.1, 0.1, 3, 1e-9, 0.01});
    history.add_row({2, 0.2, 0.2, 4, 1e-10, 0.02});
    history.add_row({3, 0.3, 0.3, 4, 1e-11, 0.03});
  }
  HistoryWriter history = HistoryWriter::reopen(path);
  EXPECT_EQ(history.columns().back(), "cauchy_zz");
  ASSERT_EQ(history.rows().size(), 3u);
  history.keep_first_rows(2);  // restart from step 2
  history.add_row({3, 0.25, 0.25, 5, 1e-12, 0.025});
  const HistoryTable table = read_history(path);
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.rows[1][5], 0.02);
  EXPECT_EQ(table.rows[2][1], 0.25);
}

TEST(HistoryWriter, MalformedFileGivesInputErrorWithPlace) {
  const ScratchDir dir;
  const auto path = dir / "history.csv";
  std::ofstream(path) << "step,time,load_factor,newton_iterations,residual_norm\n"
                      << "1,0.1,0.1,3,1e-9\n"
                      << "2,0.2,x,3,1e-9\n";
  try {
    read_history(path);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, path.string());
    EXPECT_EQ(e.place().line, 3);
    EXPECT_EQ(e.place().column, 7);  // "2,0.2,x": x is the 7th character
    EXPECT_EQ(e.place().key, "load_factor");
  }
  std::ofstream(path) << "a,b\n1,2\n";
  EXPECT_NO_THROW(read_history(path));
  EXPECT_THROW(HistoryWriter::reopen(path), InputError);  // not a plisse history
}

// The reader holds column names to the writer's rules, so a restart's rewrite of a history reads
// back as it was read: a name the writer could not write back unchanged is refused, with its
// place. (A header "...,x\r\r\n" once read as the column "x\r" and came back as "x".)
TEST(HistoryWriter, ColumnNamesTheWriterWouldRefuseAreInputErrors) {
  const ScratchDir dir;
  const auto path = dir / "history.csv";
  const std::string standard = "step,time,load_factor,newton_iterations,residual_norm";
  for (const std::string& extra :
       {std::string("x\r"), std::string("\"x\""), std::string("x,x"), std::string("")}) {
    std::ofstream(path, std::ios::binary) << standard << "," << extra << "\r\n";
    try {
      read_history(path);
      FAIL() << "accepted the extra column(s) '" << extra << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.place().line, 1);
      EXPECT_EQ(e.place().column, static_cast<int>(standard.size() + 2) +
                                      (extra == "x,x" ? 2 : 0));  // the second "x"
    }
  }
  std::ofstream(path, std::ios::binary) << standard << ",x\r\n1,2,3,4,5,6\r\n";
  const HistoryTable table = read_history(path);  // one CR before the LF is a Windows line end
  EXPECT_EQ(table.columns.back(), "x");
  EXPECT_EQ(table.rows.at(0).back(), 6.0);
}

TEST(HistoryWriter, RowsAreAppendedToTheSameFile) {
  const ScratchDir dir;
  HistoryWriter writer(dir / "history.csv", {"pressure:gas"});
  writer.add_row({1, 0.5, 0.5, 3, 1e-12, 0.1});
  struct stat first {};
  ASSERT_EQ(::stat((dir / "history.csv").c_str(), &first), 0);
  writer.add_row({2, 1.0, 1.0, 4, 2e-12, 0.2});
  struct stat second {};
  ASSERT_EQ(::stat((dir / "history.csv").c_str(), &second), 0);
  // Appended in place, not replaced by a rename: the inode of the file a reader opened stays.
  EXPECT_EQ(first.st_ino, second.st_ino);
  EXPECT_EQ(contents(dir / "history.csv"),
            "step,time,load_factor,newton_iterations,residual_norm,pressure:gas\n"
            "1,0.5,0.5,3,1e-12,0.1\n2,1,1,4,2e-12,0.2\n");
}

TEST(HistoryWriter, ReopenDropsARowAKilledRunLeftUnterminated) {
  const ScratchDir dir;
  write_file_atomically(dir / "history.csv",
                        "step,time,load_factor,newton_iterations,residual_norm\n"
                        "1,0.5,0.5,3,1e-12\n2,1,1,4,2e-1");
  HistoryWriter writer = HistoryWriter::reopen(dir / "history.csv");
  ASSERT_EQ(writer.rows().size(), 1u);
  writer.add_row({2, 1.0, 1.0, 5, 3e-12});
  EXPECT_EQ(contents(dir / "history.csv"),
            "step,time,load_factor,newton_iterations,residual_norm\n"
            "1,0.5,0.5,3,1e-12\n2,1,1,5,3e-12\n");
  // read_history itself keeps its rule: a last line without its line break is still a row.
  write_file_atomically(dir / "h2.csv",
                        "step,time,load_factor,newton_iterations,residual_norm\n1,0,0,0,0");
  EXPECT_EQ(read_history(dir / "h2.csv").rows.size(), 1u);
}

}  // namespace
}  // namespace plisse
