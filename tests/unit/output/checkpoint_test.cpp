// checkpoint.bin: every field reads back bit for bit; damage, truncation and out-of-range values
// are refused as bad input at --resume, naming what is wrong; the fingerprint says what changed.
#include "output/checkpoint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "core/fnv1a.hpp"
#include "output/atomic_file.hpp"
#include "output_test_support.hpp"

namespace plisse {
namespace {

using test::ScratchDir;

Checkpoint sample() {
  Checkpoint c;
  c.fingerprint = {
      0x0123456789abcdefull, {"loads[0].value=5", "mesh.layers=3"}, "/m/shell.msh", 42, 7};
  c.element = ElementFamily::taylor_hood;
  c.steps = 17;
  c.time = 0.625;
  c.dt = 0.0625;
  c.previous_dt = 0.03125;
  c.previous_state = {0.0, -1.5, 2.25e-300};
  c.state = {1.0, -2.5, 3.0e-17};
  c.bubbles = {};
  c.term_states = {{1.0, 2.0}, {}, {-0.5}};
  c.negative_pivots = 4;
  return c;
}

/// What reading `bytes` as a checkpoint throws (empty when it is accepted).
std::string refusal(const ScratchDir& dir, const std::string& bytes) {
  write_file_atomically(dir / "checkpoint.bin", bytes);
  try {
    read_checkpoint(dir / "checkpoint.bin");
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().key, "--resume");
    EXPECT_EQ(e.place().file, (dir / "checkpoint.bin").string());
    return e.rule();
  }
  return {};
}

TEST(Checkpoint, EveryFieldReadsBackBitForBit) {
  const ScratchDir dir;
  const Checkpoint c = sample();
  write_checkpoint(dir / "checkpoint.bin", c);
  const Checkpoint r = read_checkpoint(dir / "checkpoint.bin");
  EXPECT_EQ(r.fingerprint, c.fingerprint);
  EXPECT_EQ(r.element, c.element);
  EXPECT_EQ(r.steps, c.steps);
  EXPECT_EQ(r.time, c.time);
  EXPECT_EQ(r.dt, c.dt);
  EXPECT_EQ(r.previous_dt, c.previous_dt);
  EXPECT_EQ(r.previous_state, c.previous_state);
  EXPECT_EQ(r.state, c.state);
  EXPECT_EQ(r.bubbles, c.bubbles);
  EXPECT_EQ(r.term_states, c.term_states);
  EXPECT_EQ(r.negative_pivots, c.negative_pivots);
}

TEST(Checkpoint, EveryFlippedByteAndEveryTruncationIsRefused) {
  const ScratchDir dir;
  write_checkpoint(dir / "good.bin", sample());
  const std::string good = test::contents(dir / "good.bin");
  ASSERT_TRUE(refusal(dir, good).empty());
  for (std::size_t i = 0; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = static_cast<char>(bad[i] ^ 0x10);
    EXPECT_FALSE(refusal(dir, bad).empty()) << "byte " << i << " of " << good.size();
  }
  for (std::size_t n = 0; n < good.size(); ++n)
    EXPECT_FALSE(refusal(dir, good.substr(0, n)).empty()) << "first " << n << " bytes";
  EXPECT_NE(refusal(dir, good.substr(0, good.size() - 1)).find("truncated"), std::string::npos);
  std::string flipped = good;
  flipped[good.size() / 2] ^= 1;
  EXPECT_NE(refusal(dir, flipped).find("damaged: its checksum does not match its content"),
            std::string::npos);
  EXPECT_NE(refusal(dir, good + "x").find("truncated"), std::string::npos);
}

TEST(Checkpoint, ValuesOutOfTheirRangeAreRefusedByName) {
  // Written with a valid checksum: the field checks alone must catch them.
  const ScratchDir dir;
  const auto refused = [&](auto change, const std::string& expected) {
    Checkpoint c = sample();
    change(c);
    write_checkpoint(dir / "w.bin", c);
    const std::string why = refusal(dir, test::contents(dir / "w.bin"));
    EXPECT_NE(why.find(expected), std::string::npos)
        << "'" << why << "' lacks '" << expected << "'";
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  refused([](Checkpoint& c) { c.steps = -3; }, "step count -3 out of range");
  refused([&](Checkpoint& c) { c.time = nan; }, "time is not finite and >= 0");
  refused([](Checkpoint& c) { c.time = -1.0; }, "time is not finite and >= 0");
  refused([](Checkpoint& c) { c.dt = 0.0; }, "next step size is not finite and > 0");
  refused([&](Checkpoint& c) { c.dt = inf; }, "next step size is not finite and > 0");
  refused([](Checkpoint& c) { c.previous_dt = -0.5; }, "last step size");
  refused([&](Checkpoint& c) { c.state[2] = nan; }, "state: value 2 is not finite");
  refused([&](Checkpoint& c) { c.previous_state[0] = -inf; }, "previous state: value 0");
  refused([&](Checkpoint& c) { c.term_states[2][0] = nan; }, "term state: value 0 is not finite");
  refused([](Checkpoint& c) { c.state.clear(); }, "the state is empty");
  refused([](Checkpoint& c) { c.previous_state.push_back(1.0); },
          "the previous state has 4 values for a state of 3");
  refused([](Checkpoint& c) { c.negative_pivots = -2; }, "negative pivot count out of range");
  const std::string old_version("PLISSECK\x03\0\0\0rest-of-an-old-file", 31);
  EXPECT_NE(refusal(dir, old_version).find("another version"), std::string::npos);
  EXPECT_NE(refusal(dir, "not a checkpoint at all").find("wrong file type"), std::string::npos);
}

/// Where the element family's code lies in a checkpoint of `c`: after the magic, the version and
/// the fingerprint (case text, --set values, mesh file, mesh bytes, geometry).
std::size_t element_code_offset(const Checkpoint& c) {
  std::size_t offset = 8 + 4 + 8 + 8;  // magic, version, case text, count of --set values
  for (const std::string& o : c.fingerprint.overrides) offset += 8 + o.size();
  return offset + 8 + c.fingerprint.mesh_file.size() + 8 + 8;
}

TEST(Checkpoint, ElementFamilyCodesReadBackAndOldCodesReadTheSame) {
  // The codes 0 (MINI) and 1 (Taylor-Hood) are those of every earlier file of this version, so
  // an old checkpoint reads the same; the shell triangle has a code of its own, 2, not 1.
  const ScratchDir dir;
  const std::pair<ElementFamily, std::uint32_t> codes[] = {
      {ElementFamily::mini, 0}, {ElementFamily::taylor_hood, 1}, {ElementFamily::shell, 2}};
  for (const auto& [family, code] : codes) {
    Checkpoint c = sample();
    c.element = family;
    write_checkpoint(dir / "checkpoint.bin", c);
    const std::string bytes = test::contents(dir / "checkpoint.bin");
    std::uint32_t written = 0;
    std::memcpy(&written, bytes.data() + element_code_offset(c), sizeof written);
    EXPECT_EQ(written, code) << to_string(family);
    EXPECT_EQ(read_checkpoint(dir / "checkpoint.bin").element, family) << to_string(family);
  }
  // A code past the known ones, with the checksum made to match: refused by name.
  write_checkpoint(dir / "good.bin", sample());
  std::string bad = test::contents(dir / "good.bin");
  const std::uint32_t unknown = 3;
  std::memcpy(bad.data() + element_code_offset(sample()), &unknown, sizeof unknown);
  const std::size_t content = bad.size() - 8 - 8;  // before the checksum and the trailer
  Fnv1a checksum;
  checksum.add(bad.data(), content);
  const std::uint64_t sum = checksum.value();
  std::memcpy(bad.data() + content, &sum, sizeof sum);
  EXPECT_NE(refusal(dir, bad).find("unknown element family"), std::string::npos);
}

TEST(Checkpoint, MissingOrNotARegularFileIsRefused) {
  const ScratchDir dir;
  EXPECT_THROW(read_checkpoint(dir / "checkpoint.bin"), InputError);
  std::filesystem::create_directory(dir / "checkpoint.bin");
  EXPECT_THROW(read_checkpoint(dir / "checkpoint.bin"), InputError);
}

TEST(Checkpoint, FingerprintSaysWhatChanged) {
  const ScratchDir dir;
  write_file_atomically(dir / "case.yaml", "title: a\n");
  write_file_atomically(dir / "m.msh", "mesh one");
  Mesh tet;  // the mesh the run solves on
  tet.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tet.tets = {{0, 1, 2, 3}};
  const auto now = [&](const std::vector<std::string>& sets, const std::string& mesh) {
    return run_fingerprint(dir / "case.yaml", sets, mesh, tet);
  };
  const RunFingerprint saved = now({"a=1"}, (dir / "m.msh").string());
  EXPECT_EQ(fingerprint_changes(saved, now({"a=1"}, (dir / "m.msh").string())), "");
  EXPECT_EQ(fingerprint_changes(saved, now({"a=2", "b=1"}, (dir / "m.msh").string())),
            "the --set values differ (checkpoint: a=1; now: a=2, b=1)");
  EXPECT_EQ(fingerprint_changes(saved, now({}, "")),
            "the --set values differ (checkpoint: a=1; now: none); the mesh differs (checkpoint: " +
                (dir / "m.msh").string() + "; now: generated)");
  write_file_atomically(dir / "m.msh", "mesh two");
  write_file_atomically(dir / "case.yaml", "title: b\n");
  EXPECT_EQ(fingerprint_changes(saved, now({"a=1"}, (dir / "m.msh").string())),
            "the case file changed since the checkpoint was written; the mesh file " +
                (dir / "m.msh").string() + " changed since the checkpoint was written");
  EXPECT_THROW(now({}, (dir / "missing.msh").string()), InputError);
  // The same file named otherwise (relative, through `..`) is the same mesh; another file with
  // other content is not, whatever its name.
  const RunFingerprint by_path = now({"a=1"}, (dir / "m.msh").string());
  EXPECT_EQ(
      fingerprint_changes(
          by_path, now({"a=1"}, (dir.path() / ".." / dir.path().filename() / "m.msh").string())),
      "");
  write_file_atomically(dir / "n.msh", "mesh three");
  EXPECT_EQ(fingerprint_changes(by_path, now({"a=1"}, (dir / "n.msh").string())),
            "the mesh file's content differs from the checkpoint's (checkpoint: " +
                (dir / "m.msh").string() + "; now: " + (dir / "n.msh").string() + ")");
  // The same files, but a node moved (a changed imperfection or its mode file): seen too.
  const RunFingerprint before = now({"a=1"}, (dir / "m.msh").string());
  tet.nodes[3].z() += 1e-12;
  EXPECT_EQ(fingerprint_changes(before, now({"a=1"}, (dir / "m.msh").string())),
            "the mesh's nodes or tetrahedra differ from the checkpoint's (a changed imperfection, "
            "its mode file, or the mesh generator)");
}

}  // namespace
}  // namespace plisse
