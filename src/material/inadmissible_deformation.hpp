#pragma once
/// The exception a material throws when asked to evaluate a deformation outside its domain.
#include "core/error.hpp"

namespace plisse {

/// A trial deformation at which the energy is not defined: det F <= 0 (inverted or degenerate
/// element, any model) or a limiting-chain-extensibility model past its locking limit (Gent).
/// Derives from SolverError because it is a property of a Newton iterate, not of the input: the
/// solver catches it, rejects the iterate and cuts the step (or reports exit status 1).
class InadmissibleDeformation : public SolverError {
 public:
  using SolverError::SolverError;
};

}  // namespace plisse
