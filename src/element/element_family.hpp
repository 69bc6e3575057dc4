#pragma once
/// The element families plisse offers (case key `element`; docs/theory/taylor_hood.md compares
/// them).
#include <optional>
#include <string>
#include <string_view>

namespace plisse {

enum class ElementFamily {
  mini,         ///< MINI (P1+/P1): linear tetrahedra with a condensed bubble, linear pressure
  taylor_hood,  ///< Taylor-Hood (P2/P1): 10-node tetrahedra, linear pressure on the corners
  shell,        ///< rotation-free Kirchhoff-Love triangle (EBST, docs/theory/shell.md) on the
                ///< mid-surface (mesh/shell_surface.hpp): displacements only, exactly
                ///< incompressible plane stress
};

/// The element of a case file without the key `element`, and the order `plisse mesh` writes by
/// default: Taylor-Hood, which reaches a given accuracy on bending walls far cheaper than MINI
/// (docs/performance.md, "Element families").
inline constexpr ElementFamily kDefaultElement = ElementFamily::taylor_hood;

/// "mini" | "taylor-hood" | "shell".
inline std::string to_string(ElementFamily family) {
  switch (family) {
    case ElementFamily::mini:
      return "mini";
    case ElementFamily::taylor_hood:
      return "taylor-hood";
    case ElementFamily::shell:
      return "shell";
  }
  return "taylor-hood";
}
/// The family named `name` ("mini", "taylor-hood", "shell"), or nullopt.
inline std::optional<ElementFamily> parse_element_family(std::string_view name) {
  if (name == "mini") return ElementFamily::mini;
  if (name == "taylor-hood") return ElementFamily::taylor_hood;
  if (name == "shell") return ElementFamily::shell;
  return std::nullopt;
}
/// The mesh order a family needs: 1 (4-node tetrahedra) for MINI, 2 (10-node) for Taylor-Hood,
/// 1 for the shell (Mesh::order of a mesh without tetrahedra).
constexpr int mesh_order_of(ElementFamily family) {
  return family == ElementFamily::taylor_hood ? 2 : 1;
}

}  // namespace plisse
