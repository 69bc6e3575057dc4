#pragma once
/// A model with history (material/inelastic.hpp) bound to the quadrature points of one element:
/// what the element assembly hands the element kernels in place of an elastic model. The kernels
/// ask for the response at point q (evaluate_at_point in material/point_response.hpp); this reads
/// the point's history at the last converged step and writes the history of the response.
#include <span>
#include <variant>

#include "material/inelastic.hpp"
#include "material/registry.hpp"

namespace plisse {

struct InelasticPoints {
  const AnyMaterial* base = nullptr;  ///< the elastic model (equilibrium, virgin response)
  const InelasticLaw* law = nullptr;
  std::span<const double> converged;  ///< the element's history, law->history_size() per point
  std::span<double> now;              ///< receives the history at this evaluation; may be empty
  double dt = 0.0;                    ///< [s] since the converged step

  PointResponse evaluate_at(int q, const Mat3d& F) const {
    const std::size_t size = static_cast<std::size_t>(law->history_size());
    const PointResponse elastic =
        std::visit([&](const auto& model) { return model.evaluate(F); }, *base);
    return evaluate_inelastic(*law, elastic, F, converged.subspan(q * size, size),
                              now.empty() ? now : now.subspan(q * size, size), dt);
  }
};

}  // namespace plisse
