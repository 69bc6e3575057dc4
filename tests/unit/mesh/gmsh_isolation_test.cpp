// The Gmsh reader runs in a forked child process (isolated_process.hpp): what the child may do
// (crash, loop, allocate, print, use the parent's descriptors) and what comes back; the reply's
// wire format refuses anything short or inconsistent; files on which the Gmsh SDK itself crashes
// or allocates without bound are InputErrors naming the file, the signal or the limit.
#include <fcntl.h>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/generate.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/gmsh_raw_model.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/isolated_process.hpp"
#include "mesh_test_util.hpp"
#include "support/sanitizer.hpp"

namespace plisse {
namespace {

ChildLimits small_limits() {
  ChildLimits limits;
  limits.memory_bytes = std::uint64_t{256} << 20;
  limits.cpu_seconds = 5;
  limits.wall_seconds = 20.0;
  return limits;
}

void send_text(ChildOutput& out, const std::string& text) { out.write(text.data(), text.size()); }

std::string text_of(const ChildResult& r) { return std::string(r.output.begin(), r.output.end()); }

/// No child of this process is left, reaped or not.
bool no_child_left() { return ::waitpid(-1, nullptr, WNOHANG) == -1 && errno == ECHILD; }

TEST(IsolatedProcess, ReturnsWhatTheChildWroteByteForByte) {
  std::string big(3'000'000, '\0');  // far more than a pipe buffer (64 KiB): no deadlock
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 7919 % 251);
  const ChildResult r =
      run_isolated([&](ChildOutput& out) { send_text(out, big); }, small_limits());
  EXPECT_EQ(r.end, ChildResult::End::exited);
  EXPECT_EQ(r.exit_status, 0);
  EXPECT_TRUE(text_of(r) == big) << r.output.size() << " bytes back";
  EXPECT_TRUE(no_child_left());
}

TEST(IsolatedProcess, ReportsTheSignalTheChildDiedOf) {
  const ChildResult r = run_isolated(
      [](ChildOutput& out) {
        send_text(out, "partial");
        out.flush();
        std::raise(SIGSEGV);
      },
      small_limits());
  EXPECT_EQ(r.end, ChildResult::End::killed_by_signal);
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_EQ(text_of(r), "partial");
  EXPECT_NE(describe_signal(r.signal).find("SIGSEGV"), std::string::npos);
  EXPECT_TRUE(no_child_left());
}

TEST(IsolatedProcess, ReportsTheExitStatusAndAThrowingWork) {
  const ChildResult r = run_isolated([](ChildOutput&) { ::_exit(7); }, small_limits());
  EXPECT_EQ(r.end, ChildResult::End::exited);
  EXPECT_EQ(r.exit_status, 7);
  const ChildResult t =
      run_isolated([](ChildOutput&) { throw std::runtime_error("x"); }, small_limits());
  EXPECT_EQ(t.exit_status, kChildWorkThrew);
}

TEST(IsolatedProcess, StopsAChildAtItsCpuTimeLimit) {
  ChildLimits limits = small_limits();
  limits.cpu_seconds = 1;
  const ChildResult r = run_isolated(
      [](ChildOutput&) {
        volatile unsigned long x = 0;
        while (true) x = x + 1;
      },
      limits);
  EXPECT_TRUE(r.cpu_limit_hit(limits))
      << describe_signal(r.signal) << ", " << r.cpu_seconds << " s";
  // SIGXCPU at 1 s of CPU, SIGKILL at 2 s at the latest (CPU time, whatever the machine's load).
  EXPECT_GE(r.cpu_seconds, 0.9);
  EXPECT_LE(r.cpu_seconds, 2.1);
}

TEST(IsolatedProcess, KillsAChildThatOutlivesTheWallTimeLimit) {
  ChildLimits limits = small_limits();
  limits.wall_seconds = 0.3;
  const auto start = std::chrono::steady_clock::now();
  const ChildResult r = run_isolated([](ChildOutput&) { ::sleep(60); }, limits);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.end, ChildResult::End::wall_time_exceeded);
  EXPECT_LT(wall, 3.0);
  EXPECT_TRUE(no_child_left());
}

TEST(IsolatedProcess, LimitsTheMemoryTheChildCanMap) {
  // 4 GiB against a 256 MiB limit. Without AddressSanitizer the allocation throws in the child;
  // ASan's allocator instead reports and ends the process: both leave the parent untouched.
  const ChildResult r = run_isolated(
      [](ChildOutput& out) {
        try {
          std::vector<char> big(std::size_t{4} << 30, 1);
          send_text(out, "allocated " + std::to_string(big.size()));
        } catch (const std::bad_alloc&) {
          send_text(out, "bad_alloc");
        }
      },
      small_limits());
#if PLISSE_TEST_ASAN
  EXPECT_TRUE(r.end != ChildResult::End::exited || r.exit_status != 0 || text_of(r) == "bad_alloc");
#else
  EXPECT_EQ(text_of(r), "bad_alloc");
  EXPECT_LT(r.max_rss_kib, 300 * 1024);
#endif
}

TEST(IsolatedProcess, ChildSeesNoDescriptorOfTheParentAndWritesToDevNull) {
  const auto dir = test::scratch_dir("descriptors");
  // Not close-on-exec, and above the child's pipe (3), which could otherwise reuse its number.
  const int opened = ::open((dir / "open.txt").c_str(), O_CREAT | O_WRONLY, 0600);
  ASSERT_GE(opened, 0);
  const int fd = ::fcntl(opened, F_DUPFD, 40);
  ::close(opened);
  ASSERT_GE(fd, 40);
  struct stat null_stat {};
  ASSERT_EQ(::stat("/dev/null", &null_stat), 0);
  const ChildResult r = run_isolated(
      [&](ChildOutput& out) {
        const bool closed = ::fcntl(fd, F_GETFD) == -1 && errno == EBADF;
        struct stat s {};
        const bool null_out = ::fstat(1, &s) == 0 && s.st_rdev == null_stat.st_rdev &&
                              ::fstat(2, &s) == 0 && s.st_rdev == null_stat.st_rdev;
        std::printf("Gmsh prints here\n");  // must not reach the test's output
        std::fflush(stdout);
        send_text(out, std::string(closed ? "closed" : "open") + (null_out ? " null" : " tty"));
      },
      small_limits());
  ::close(fd);
  EXPECT_EQ(text_of(r), "closed null");
}

TEST(GmshReply, RoundTripsAndRefusesEveryTruncationAndTrailingByte) {
  RawGmshModel m;
  m.types = {{4, 3, "Tetrahedron 4"}, {2, 2, "Triangle 3"}};
  m.node_tags = {1, 2, 3, 4};
  m.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.blocks = {{4, {10}, {1, 2, 3, 4}}, {2, {11}, {1, 3, 2}}};
  m.groups = {{2, 5, "bottom", {{2, {11}}}}};
  const ChildResult r = run_isolated([&](ChildOutput& out) { send_model(m, out); }, small_limits());
  GmshReaderReply reply;
  ASSERT_TRUE(decode_reply(r.output, reply));
  ASSERT_EQ(reply.kind, GmshReaderReply::Kind::model);
  EXPECT_EQ(reply.model.coordinates, m.coordinates);
  EXPECT_EQ(reply.model.blocks[1].node_tags, m.blocks[1].node_tags);
  EXPECT_EQ(reply.model.types[0].name, "Tetrahedron 4");
  EXPECT_EQ(reply.model.groups[0].name, "bottom");
  EXPECT_EQ(reply.model.groups[0].elements[0].element_tags, std::vector<std::size_t>{11});
  for (std::size_t n = 0; n < r.output.size(); ++n)
    EXPECT_FALSE(decode_reply(std::span<const char>(r.output.data(), n), reply)) << n;
  std::vector<char> longer = r.output;
  longer.push_back('x');
  EXPECT_FALSE(decode_reply(longer, reply));
  // A count of 2^60 nodes is refused before anything is allocated.
  std::vector<char> huge = r.output;
  const std::size_t count_at = 4 + 4 + 1 + 8 + 2 * (4 + 4 + 8) + 13 + 10;  // node_tags count
  const std::uint64_t n = std::uint64_t{1} << 60;
  std::memcpy(huge.data() + count_at, &n, sizeof n);
  EXPECT_FALSE(decode_reply(huge, reply));
}

/// InputError message of reading `path` ("" if it was read).
std::string read_error(const std::string& path) {
  try {
    read_gmsh(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.place().file, path);
    return e.what();
  }
  return "";
}

std::string regression_file(const std::string& name) {
  return std::string(PLISSE_SOURCE_DIR) + "/fuzz/regressions/gmsh/" + name;
}

TEST(GmshIsolation, FileOnWhichGmshCrashesIsAMalformedMeshNamingTheSignal) {
  // Gmsh 4.11 dereferences a null entity in GModel::setPhysicalName on this file.
  const std::string path = regression_file("gmsh-setphysicalname-segfault.msh");
  const std::string message = read_error(path);
  EXPECT_NE(message.find("the mesh file is malformed"), std::string::npos) << message;
  EXPECT_NE(message.find("SIGSEGV"), std::string::npos) << message;
  // Gmsh in plisse's own process is untouched and reads the next file.
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.divisions = 1;
  const std::string good = (test::scratch_dir("after_crash") / "cube.msh").string();
  write_gmsh(generate_mesh(spec), good);
  EXPECT_EQ(read_gmsh(good).n_tets(), generate_mesh(spec).n_tets());
  EXPECT_TRUE(no_child_left());
}

TEST(GmshIsolation, HugeAnnouncedNodeCountIsAMalformedMeshNotAnAllocation) {
  const std::string path = regression_file("huge-node-count-aborts-under-asan.msh");
  const auto start = std::chrono::steady_clock::now();
  const std::string message = read_error(path);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(message.find("the mesh file is malformed"), std::string::npos) << message;
#if !PLISSE_TEST_ASAN
  EXPECT_NE(message.find("memory limit of 1024 MiB for a file of 93 bytes"), std::string::npos)
      << message;
#endif
  EXPECT_LT(wall, 5.0);
}

TEST(GmshIsolation, OnlyMshFilesAreGivenToGmsh) {
  // Gmsh reads any other name, or a .msh file that does not begin like one, as a .geo script,
  // which can run shell commands (SystemCall).
  const auto dir = test::scratch_dir("extension");
  const std::string script = (dir / "mesh.geo").string();
  std::ofstream(script) << "SystemCall \"touch " << (dir / "ran").string() << "\";\n";
  const std::string message = read_error(script);
  EXPECT_NE(message.find("must end in .msh"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(dir / "ran"));
  // Named .msh, Gmsh still runs it as a script unless it begins like an MSH file.
  const std::string disguised = (dir / "mesh.msh").string();
  std::filesystem::copy_file(script, disguised);
  const std::string disguised_message = read_error(disguised);
  EXPECT_NE(disguised_message.find("not a Gmsh mesh file"), std::string::npos) << disguised_message;
  EXPECT_FALSE(std::filesystem::exists(dir / "ran"));
  MeshGenerationSpec spec;
  spec.kind = "cube";
  spec.divisions = 1;
  const std::string upper = (dir / "CUBE.MSH").string();
  write_gmsh(generate_mesh(spec), (dir / "cube.msh").string());
  std::filesystem::copy_file(dir / "cube.msh", upper);
  EXPECT_EQ(read_gmsh(upper).n_tets(), generate_mesh(spec).n_tets());
}

TEST(GmshIsolation, LimitsGrowWithTheFileFromAGenerousFloor) {
  const ChildLimits small = gmsh_reader_limits(100);
  EXPECT_EQ(small.memory_bytes, (std::uint64_t{1} << 30) + 6400);
  EXPECT_EQ(small.cpu_seconds, 10u);
  EXPECT_DOUBLE_EQ(small.wall_seconds, 30.0);
  const ChildLimits big = gmsh_reader_limits(std::uintmax_t{100} << 20);  // 100 MiB
  EXPECT_EQ(big.memory_bytes, (std::uint64_t{1} << 30) + (std::uint64_t{6400} << 20));
  EXPECT_EQ(big.cpu_seconds, 410u);
}

}  // namespace
}  // namespace plisse
