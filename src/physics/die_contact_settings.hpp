#pragma once
/// The contact law of a rigid die (physics/die_contact.hpp applies it).
#include <string>

namespace plisse {

enum class ContactKind { frictionless, sticking, coulomb };

/// Contact law and augmented-Lagrangian parameters of one die (docs/theory/contact.md).
struct DieContactSettings {
  std::string name;  ///< history columns force_x:<name> ...
  ContactKind contact = ContactKind::frictionless;
  double penalty = 0.0;  ///< epsilon [MPa/mm = N/mm^3], > 0: contact pressure per unit gap
  /// Largest penetration (glued: distance to the anchor; Coulomb, sticking: tangential slip in
  /// the step) [mm], > 0.
  double tolerance = 1e-3;
  double friction = 0.0;  ///< Coulomb friction coefficient, >= 0 (contact coulomb only)
  /// A node with gap g <= touch_slack [mm] touches (round-off allowance, contact.md D13).
  double touch_slack = 0.0;
};

}  // namespace plisse
