#pragma once
/// A rigid die as the case file gives it, and the contact law of a die (physics/die_contact.hpp
/// applies it).
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/die_geometry.hpp"
#include "physics/ramp.hpp"

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

/// A `dies:` entry: a rigid analytic die with prescribed motion, as the case file gives it
/// (terms/die.cpp turns it into a DieGeometry and DieContactSettings).
struct DieSettings {
  std::string name;  ///< history columns `force_x:<name>` ...
  DieShape shape = DieShape::plane;
  Vec3d point = Vec3d::Zero();    ///< plane: a point; sphere/cylinder: centre / a point on the axis
  Vec3d normal = Vec3d::UnitY();  ///< plane: unit normal pointing towards the body (normalised)
  Vec3d axis = Vec3d::UnitZ();    ///< cylinder: axis direction (normalised)
  double radius = 0.0;            ///< sphere, cylinder [mm], > 0
  ContactKind contact = ContactKind::frictionless;
  std::optional<SurfaceRef> region;    ///< sticking: glued from the start on this tag
  std::optional<SurfaceRef> surface;   ///< candidate contact surface (default: whole boundary)
  Vec3d displacement = Vec3d::Zero();  ///< `move.displacement` [mm] at the end of the ramp
  Ramp ramp;                           ///< `move.ramp`
  double penalty = 0.0;                ///< [MPa/mm]; 0: chosen from the material and mesh
  double tolerance = 1e-3;             ///< allowed penetration [mm], > 0
  double friction = 0.0;               ///< coulomb: friction coefficient, >= 0
  InputPlace place;
};

}  // namespace plisse
