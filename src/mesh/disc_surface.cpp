#include "mesh/disc_surface.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/gmsh_session.hpp"

namespace plisse {
double estimate_disc_triangles(double radius, double h, Symmetry symmetry,
                               const PoleRefinement& rim) {
  constexpr int kSteps = 20000;
  const double dr = radius / kSteps;
  double n = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double r = (i + 0.5) * dr;
    const double s = rim.size_at(radius - r, h);
    n += 2.0 * std::numbers::pi * kept_fraction(symmetry) * r * dr / (std::sqrt(3.0) / 4.0 * s * s);
  }
  return n;
}

SurfaceTriangulation mesh_disc_surface(double radius, double h, Symmetry symmetry,
                                       const PoleRefinement& rim) {
  PLISSE_CHECK(radius > 0.0 && h > 0.0, "mesh_disc_surface: sizes must be positive");
  PLISSE_CHECK(symmetry != Symmetry::octant, "mesh_disc_surface: a flat panel has no octant");
  const double tolerance = 1e-9 * radius;  // cut-plane and rim nodes are within round-off
  GmshSession session;
  SurfaceTriangulation surface;
  try {
    gmsh::model::add("disc");
    // The sector in the x-y plane (angle from +x towards +y), turned a quarter about +x so that
    // +y goes to +z: the kept part x >= 0, z >= 0 of a quarter, z >= 0 of a half.
    const double sweep = 2.0 * std::numbers::pi * kept_fraction(symmetry);
    int surface_tag = 0;
    if (symmetry == Symmetry::full) {
      surface_tag = gmsh::model::occ::addDisk(0.0, 0.0, 0.0, radius, radius);
    } else {
      const int centre = gmsh::model::occ::addPoint(0.0, 0.0, 0.0);
      const int start = gmsh::model::occ::addPoint(radius, 0.0, 0.0);
      const int end =
          gmsh::model::occ::addPoint(radius * std::cos(sweep), radius * std::sin(sweep), 0.0);
      const int arc = gmsh::model::occ::addCircleArc(start, centre, end);
      const int first = gmsh::model::occ::addLine(centre, start);
      const int last = gmsh::model::occ::addLine(end, centre);
      const int loop = gmsh::model::occ::addCurveLoop({first, arc, last});
      surface_tag = gmsh::model::occ::addPlaneSurface({loop});
    }
    gmsh::model::occ::rotate({{2, surface_tag}}, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                             0.5 * std::numbers::pi);
    gmsh::model::occ::synchronize();
    session.check_internal("disc geometry");
    // The rim: the boundary curves whose middle lies on the circle (OpenCASCADE may renumber
    // the curves it builds the surface from).
    std::vector<double> arcs;
    gmsh::vectorpair boundary;
    gmsh::model::getBoundary({{2, surface_tag}}, boundary, false, false, false);
    for (const auto& [dim, tag] : boundary) {
      std::vector<double> low, high, point;
      gmsh::model::getParametrizationBounds(1, std::abs(tag), low, high);
      gmsh::model::getValue(1, std::abs(tag), {0.5 * (low[0] + high[0])}, point);
      if (std::abs(std::hypot(point[0], point[2]) - radius) < 1e-6 * radius)
        arcs.push_back(std::abs(tag));
    }
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
    if (rim.active()) {
      PLISSE_CHECK(!arcs.empty(), "disc surface: no rim curve");
      const int distance = gmsh::model::mesh::field::add("Distance");
      gmsh::model::mesh::field::setNumbers(distance, "CurvesList", arcs);
      gmsh::model::mesh::field::setNumber(distance, "NumPointsPerCurve", 400);
      const int threshold = gmsh::model::mesh::field::add("Threshold");
      gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
      gmsh::model::mesh::field::setNumber(threshold, "SizeMin", rim.size);
      gmsh::model::mesh::field::setNumber(threshold, "SizeMax", h);
      gmsh::model::mesh::field::setNumber(threshold, "DistMin", rim.radius);
      gmsh::model::mesh::field::setNumber(threshold, "DistMax", rim.outer_radius(h));
      gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
    }
    gmsh::model::mesh::generate(2);
    session.check_internal("disc meshing");

    std::unordered_map<std::size_t, int> index;
    append_gmsh_triangles(surface_tag, surface, index);
    session.check_internal("disc mesh");
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("disc surface: ") + e.what());
  } catch (const std::string& message) {
    throw Error("disc surface: Gmsh: " + message);
  }
  PLISSE_CHECK(!surface.triangles.empty(), "disc surface: Gmsh produced no triangles");
  const auto planes = cut_planes(symmetry);
  for (Vec3d& p : surface.nodes) {
    p.y() = 0.0;
    for (int axis : {0, 2}) {
      if (!planes[static_cast<std::size_t>(axis)]) continue;
      if (std::abs(p[axis]) < tolerance) p[axis] = 0.0;
      PLISSE_CHECK(p[axis] >= 0.0, "disc surface: node outside the kept part (coordinate "
                                       << axis << " = " << p[axis] << ")");
    }
    const double r = std::hypot(p.x(), p.z());
    if (std::abs(r - radius) < 1e-6 * radius) p *= radius / r;  // Gmsh's rim nodes, on the circle
    PLISSE_CHECK(r <= radius * (1.0 + 1e-6),
                 "disc surface: node outside the disc (r = " << r << ")");
  }
  for (auto& t : surface.triangles) {
    const Vec3d n = (surface.nodes[static_cast<std::size_t>(t[1])] -
                     surface.nodes[static_cast<std::size_t>(t[0])])
                        .cross(surface.nodes[static_cast<std::size_t>(t[2])] -
                               surface.nodes[static_cast<std::size_t>(t[0])]);
    if (n.y() < 0.0) std::swap(t[1], t[2]);
  }
  return surface;
}

}  // namespace plisse
