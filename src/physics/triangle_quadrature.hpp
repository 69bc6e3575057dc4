#pragma once
/// The symmetric quadrature rule on the triangle that integrates the surface terms of a 6-node
/// (quadratic) face exactly (docs/theory/loads.md, L9).
#include <array>

namespace plisse {

/// One point of a triangle rule: barycentric coordinates (L0, L1, L2) and a weight that is a
/// fraction of the triangle's area (the weights sum to 1).
struct TrianglePoint {
  std::array<double, 3> L;
  double weight;
};

/// Degree 4, 6 points, positive weights: two orbits {(a, b, b) and permutations},
/// b = (1 - a) / 2 [Dunavant, Int. J. Numer. Meth. Engng 21 (1985) 1129, rule 4]. The values were
/// recomputed here to 25 digits (mpmath) from the four moment conditions for 1, e2, e3 and e2^2
/// (e2 = L0 L1 + L1 L2 + L2 L0, e3 = L0 L1 L2), which with the symmetry of the orbits make every
/// polynomial of degree <= 4 exact; tests/unit/physics/quadratic_face_test.cpp checks all
/// monomials of degree <= 4.
inline constexpr std::array<TrianglePoint, 6> kTriangleRuleDegree4 = {{
    {{0.1081030181680702273633415, 0.4459484909159648863183293, 0.4459484909159648863183293},
     0.2233815896780114656950070},
    {{0.4459484909159648863183293, 0.1081030181680702273633415, 0.4459484909159648863183293},
     0.2233815896780114656950070},
    {{0.4459484909159648863183293, 0.4459484909159648863183293, 0.1081030181680702273633415},
     0.2233815896780114656950070},
    {{0.8168475729804585130808571, 0.09157621350977074345957146, 0.09157621350977074345957146},
     0.1099517436553218676383263},
    {{0.09157621350977074345957146, 0.8168475729804585130808571, 0.09157621350977074345957146},
     0.1099517436553218676383263},
    {{0.09157621350977074345957146, 0.09157621350977074345957146, 0.8168475729804585130808571},
     0.1099517436553218676383263},
}};

}  // namespace plisse
