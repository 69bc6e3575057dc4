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
};

/// The element of a case file without the key `element`, and the order `plisse mesh` writes by
/// default: Taylor-Hood, which reaches a given accuracy on bending walls far cheaper than MINI
/// (docs/performance.md, "Element families").
inline constexpr ElementFamily kDefaultElement = ElementFamily::taylor_hood;

/// "mini" | "taylor-hood".
inline std::string to_string(ElementFamily family) {
  return family == ElementFamily::mini ? "mini" : "taylor-hood";
}
/// The family named `name` ("mini", "taylor-hood"), or nullopt.
inline std::optional<ElementFamily> parse_element_family(std::string_view name) {
  if (name == "mini") return ElementFamily::mini;
  if (name == "taylor-hood") return ElementFamily::taylor_hood;
  return std::nullopt;
}
/// The mesh order a family needs: 1 (4-node tetrahedra) for MINI, 2 (10-node) for Taylor-Hood.
constexpr int mesh_order_of(ElementFamily family) { return family == ElementFamily::mini ? 1 : 2; }

}  // namespace plisse
