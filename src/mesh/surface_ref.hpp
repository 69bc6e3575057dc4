#pragma once
/// A reference to a tagged surface of the mesh, as a user wrote it.
#include <string>

#include "core/error.hpp"

namespace plisse {

/// The name of a surface tag and where it was named (so that a check against the mesh can report
/// the file, line, column and key of the reference).
struct SurfaceRef {
  std::string name;
  InputPlace place;
};

}  // namespace plisse
