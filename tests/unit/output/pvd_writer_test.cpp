#include "output/pvd_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::entries;
using test::from_hex;
using test::read_with_python;
using test::ScratchDir;

TEST(PvdWriter, CollectionIsValidXmlAfterEveryStep) {
  const ScratchDir dir;
  const auto path = dir / "solution.pvd";
  PvdWriter pvd(path);
  nlohmann::json read = read_with_python("pvd", path);  // valid even before the first step
  ASSERT_FALSE(read.is_null());
  EXPECT_EQ(read["tag"], "VTKFile");
  EXPECT_EQ(read["type"], "Collection");
  EXPECT_TRUE(read["datasets"].empty());

  const std::vector<PvdEntry> steps = {
      {0.0, "step_0000.vtu"}, {0.1, "step_0001.vtu"}, {1.0 / 3.0, "step_0002.vtu"}};
  for (std::size_t i = 0; i < steps.size(); ++i) {
    pvd.add(steps[i].time, steps[i].file);
    read = read_with_python("pvd", path);
    ASSERT_FALSE(read.is_null());
    ASSERT_EQ(read["datasets"].size(), i + 1);
    for (std::size_t k = 0; k <= i; ++k) {
      EXPECT_EQ(from_hex(read["datasets"][k]["timestep"]), steps[k].time);  // exact
      EXPECT_EQ(read["datasets"][k]["file"], steps[k].file);
    }
  }
  EXPECT_EQ(entries(dir.path()), std::set<std::string>{"solution.pvd"});
}

TEST(PvdWriter, ReopenedCollectionContinues) {
  const ScratchDir dir;
  const auto path = dir / "solution.pvd";
  {
    PvdWriter pvd(path);
    pvd.add(0.25, "step_0001.vtu");
    pvd.add(0.5, "a&b \"c\".vtu");
  }
  const std::vector<PvdEntry> read = read_pvd(path);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].time, 0.25);
  EXPECT_EQ(read[1].file, "a&b \"c\".vtu");
  PvdWriter pvd(path, read);
  pvd.add(0.75, "step_0003.vtu");
  const nlohmann::json xml = read_with_python("pvd", path);
  ASSERT_FALSE(xml.is_null());
  ASSERT_EQ(xml["datasets"].size(), 3u);
  EXPECT_EQ(xml["datasets"][1]["file"], "a&b \"c\".vtu");
  EXPECT_EQ(from_hex(xml["datasets"][2]["timestep"]), 0.75);
}

TEST(PvdWriter, RejectsAbsoluteFileAndNonFiniteTime) {
  const ScratchDir dir;
  PvdWriter pvd(dir / "solution.pvd");
  EXPECT_THROW(pvd.add(1.0, "/tmp/step_0001.vtu"), Error);
  EXPECT_THROW(pvd.add(std::nan(""), "step_0001.vtu"), Error);
  EXPECT_THROW(pvd.add(1.0, ""), Error);
  EXPECT_TRUE(pvd.entries().empty());
  EXPECT_THROW(read_pvd(dir / "missing.pvd"), InputError);
}

}  // namespace
}  // namespace plisse
