#pragma once
/// The one way plisse calls PETSc: PLISSE_PETSC(call) turns a nonzero PetscErrorCode into a
/// plisse::Error naming the call site and PETSc's message (docs/architecture.md, "Coding
/// conventions").
#include <petscsys.h>

#include <string>

#include "core/error.hpp"

namespace plisse::detail {
[[noreturn]] void throw_petsc_error(PetscErrorCode code, const char* call, const char* file,
                                    int line);
}  // namespace plisse::detail

#define PLISSE_PETSC(...)                                                                        \
  do {                                                                                           \
    const PetscErrorCode plisse_petsc_code_ = (__VA_ARGS__);                                     \
    if (plisse_petsc_code_ != 0)                                                                 \
      ::plisse::detail::throw_petsc_error(plisse_petsc_code_, #__VA_ARGS__, __FILE__, __LINE__); \
  } while (false)
