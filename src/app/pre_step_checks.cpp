#include "app/pre_step_checks.hpp"

#include <array>

#include "core/error.hpp"
#include "element/taylor_hood_geometry.hpp"

namespace plisse::app {
namespace {

void check_element_and_scheme(const Case& c, const Mesh& mesh, const ModelParts*) {
  if (const auto unsupported = unsupported_features(c, mesh); !unsupported.empty())
    throw unsupported.front();
}

/// A second-order tetrahedron whose edge nodes bend it inside out (a thin curved wall meshed by
/// Gmsh with -order 2 and no high-order optimisation) has det(dX/dξ) <= 0 somewhere: the element
/// kernels cannot integrate it.
void check_curved_elements(const Case& c, const Mesh& mesh, const ModelParts*) {
  if (c.element != ElementFamily::taylor_hood || mesh.order() != 2) return;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    std::array<Vec3d, taylor_hood::kNodes> X;
    for (int a = 0; a < taylor_hood::kCorners; ++a)
      X[static_cast<std::size_t>(a)] = mesh.nodes[static_cast<std::size_t>(mesh.tets[t][a])];
    for (int k = 0; k < 6; ++k)
      X[static_cast<std::size_t>(taylor_hood::kCorners + k)] =
          mesh.nodes[static_cast<std::size_t>(mesh.tet_edge_nodes[t][k])];
    try {
      taylor_hood::compute_geometry(X);
    } catch (const Error& e) {
      const InputPlace place =
          c.mesh.file ? InputPlace{*c.mesh.file, 0, 0, c.mesh.file_place.key} : c.mesh.place;
      throw InputError(
          place, "second-order tetrahedron " + std::to_string(t + 1) +
                     " (1-based, in the order of the mesh's tetrahedra) is turned inside out by "
                     "its edge nodes: " +
                     e.what() +
                     ". Curve the mesh with Gmsh's high-order optimisation (Mesh.HighOrderOptimize "
                     "= 2, or gmsh -3 -order 2 -optimize_ho), or use smaller elements across the "
                     "curved wall");
    }
  }
}

void check_pieces(const Case& c, const Mesh& mesh, const ModelParts* parts) {
  check_rigid_pieces(c, mesh, *parts);
}

}  // namespace

const std::vector<PreStepCheck>& pre_step_checks() {
  static const std::vector<PreStepCheck> table = {
      {"element and scheme", PreStepStage::mesh, check_element_and_scheme},
      {"curved elements", PreStepStage::mesh, check_curved_elements},
      {"rigid pieces", PreStepStage::parts, check_pieces},
  };
  return table;
}

void run_pre_step_checks(PreStepStage stage, const Case& c, const Mesh& mesh,
                         const ModelParts* parts) {
  PLISSE_CHECK(stage == PreStepStage::mesh || parts != nullptr,
               "the pre-step checks of the parts need the parts");
  for (const PreStepCheck& check : pre_step_checks())
    if (check.stage == stage) check.check(c, mesh, parts);
}

}  // namespace plisse::app
