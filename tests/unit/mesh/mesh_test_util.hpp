#pragma once
/// Helpers shared by the mesh tests.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "mesh/generate.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"

namespace plisse {

/// Prints a Symmetry by name (gtest finds it by ADL: parameterised test names and messages).
inline void PrintTo(Symmetry s, std::ostream* out) { *out << to_string(s); }

}  // namespace plisse

namespace plisse::test {

/// Sum of the signed tetrahedron volumes [mm^3].
inline double mesh_volume(const Mesh& mesh) {
  double v = 0.0;
  for (int t = 0; t < mesh.n_tets(); ++t) v += tet_signed_volume(mesh, t);
  return v;
}

/// Smallest signed tetrahedron volume [mm^3].
inline double min_tet_volume(const Mesh& mesh) {
  double v = 1e300;
  for (int t = 0; t < mesh.n_tets(); ++t) v = std::min(v, tet_signed_volume(mesh, t));
  return v;
}

/// The distinct nodes of the triangles of tag `name`.
inline std::vector<int> tag_nodes(const Mesh& mesh, const std::string& name) {
  std::vector<int> nodes;
  for (int tri : mesh.surface_tags.at(name))
    for (int n : mesh.triangles[static_cast<std::size_t>(tri)]) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

/// This process's directory for test files, removed at exit (see ScratchCleanup).
inline std::filesystem::path scratch_root() {
  return std::filesystem::temp_directory_path() /
         ("plisse_mesh_test_" + std::to_string(::getpid()));
}

/// A fresh directory for this test's files (removed and recreated on each call).
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir = scratch_root() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Removes scratch_root() when the test program ends.
struct ScratchCleanup {
  ~ScratchCleanup() {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_root(), ignored);
  }
};
inline ScratchCleanup scratch_cleanup;

inline std::string data_file(const std::string& name) {
  return std::string(PLISSE_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

}  // namespace plisse::test
