// Requirement: a mesh that cannot be written whole (a full disk, a file size limit) is an error
// naming the file, and the earlier file of that name is left as it was. Gmsh reports neither: it
// printed "wrote ...", exited 0 and renamed a truncated file over a good mesh. The full disk is a
// 200 KiB tmpfs mounted in a user and mount namespace of its own (unshare -Urm; the test is
// skipped where the system does not allow one), the file size limit `ulimit -f`.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

const std::string kPlisse = std::string(PLISSE_BINARY_DIR) + "/bin/plisse";

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `script` under sh with a 4 GiB address-space limit (not under AddressSanitizer) and 60 s;
/// its output and status.
test::PlisseResult shell(const std::string& script, const fs::path& log) {
  const std::string command =
      test::limits(60) + "sh -c '" + script + "' > '" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text_of(log)};
}

TEST(FullDisk, AMeshTooLargeForTheDiskKeepsTheEarlierFile) {
  const fs::path dir = test::scratch_directory("full-disk");
  fs::create_directories(dir / "disk");
  if (std::system("unshare -Urm true > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "no user and mount namespace here (unshare -Urm)";
  const fs::path mesh = dir / "disk" / "cube.msh";
  // The small mesh (5 KB) fits, the large one (about 1.3 MB) does not. The mount and the files
  // on it go with the namespace, so the shell copies what is left to the test's directory.
  const std::string script = "mount -t tmpfs -o size=200k tmpfs " + (dir / "disk").string() +
                             " && " + kPlisse + " mesh cube --divisions 2 -o " + mesh.string() +
                             " && cp " + mesh.string() + " " + (dir / "small.msh").string() +
                             " && { " + kPlisse + " mesh cube --divisions 12 -o " + mesh.string() +
                             "; echo status=$?; ls -a " + (dir / "disk").string() + "; cp " +
                             mesh.string() + " " + (dir / "after.msh").string() + "; }";
  std::ofstream(dir / "full.sh") << script << '\n';
  const test::PlisseResult r =
      shell("unshare -Urm sh " + (dir / "full.sh").string(), dir / "log.txt");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("status=2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(mesh.string() + ": key '-o': cannot write the mesh file: it ends after"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("the earlier cube.msh is kept"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("wrote "), r.output.rfind("wrote ")) << r.output;  // the small one only
  EXPECT_EQ(r.output.find(".tmp."), std::string::npos) << r.output;          // no temporary left
  EXPECT_EQ(text_of(dir / "after.msh"), text_of(dir / "small.msh"));
}

TEST(FullDisk, AMeshPastTheFileSizeLimitKeepsTheEarlierFile) {
  const fs::path dir = test::scratch_directory("file-size-limit");
  fs::create_directories(dir);
  const fs::path mesh = dir / "cube.msh";
  // ulimit -f counts 1024-byte blocks: 50 KiB. Past it a write fails (EFBIG) instead of the
  // process ending by SIGXFSZ.
  const std::string script = "ulimit -f 50; " + kPlisse + " mesh cube --divisions 2 -o " +
                             mesh.string() + " && cp " + mesh.string() + " " +
                             (dir / "small.msh").string() + " && " + kPlisse +
                             " mesh cube --divisions 12 --binary -o " + mesh.string();
  const test::PlisseResult r = shell(script, dir / "log.txt");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(mesh.string() + ": key '-o': cannot write the mesh file: it ends after"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(text_of(mesh), text_of(dir / "small.msh"));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace plisse
