#pragma once
/// The rigid motions that the assembled tangent itself does not resist: the run's own test of a
/// singular tangent, for what the check before the first step cannot judge (surface contacts that
/// do not yet press, a support that turned out weaker than its settings say).
#include <string>

#include "solver/mixed_model.hpp"

namespace plisse {

/// Assembles the tangent at the model's current state and, for each piece of the mesh, looks for
/// a combination of its six rigid motions (translations, turns about the axes through its centre)
/// that the tangent maps to nearly nothing: |K v| <= 1e-10 |K| |v| over the free unknowns, v the
/// motion's free part (a motion that moves a prescribed component leaves a free part that the
/// elements next to it resist). Returns "<piece> can still move as a rigid body by <motion>
/// (node N at [x, y, z] moves so)" for the first such piece, else empty. Collective; the model's
/// state is unchanged.
std::string unresisted_rigid_motion(MixedModel& model);

}  // namespace plisse
