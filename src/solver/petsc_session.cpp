#include "solver/petsc_session.hpp"

#include <petscsys.h>
#include <slepcsys.h>

#include <sstream>

#include "solver/petsc_call.hpp"

namespace plisse {

namespace detail {
void throw_petsc_error(PetscErrorCode code, const char* call, const char* file, int line) {
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::ostringstream out;
  out << "PETSc error " << code << " (" << (text ? text : "unknown") << ") in " << call << " at "
      << file << ':' << line;
  throw Error(out.str());
}
}  // namespace detail

PetscSession::PetscSession(const std::vector<std::string>& options) {
  // SlepcInitialize initialises PETSc too when nobody has (and SlepcFinalize then finalises it),
  // and registers SLEPc's classes and options (EPS for solver/eigenmodes).
  PetscBool initialized = PETSC_FALSE;
  PLISSE_PETSC(SlepcInitialized(&initialized));
  if (!initialized) {
    // -skip_petscrc: PETSc would otherwise read options from ~/.petscrc and from .petscrc and
    // petscrc in the working directory, past the checks of the case's and command line's options
    // (a file-writing viewer in a directory someone sent you).
    static char program[] = "plisse";
    static char skip[] = "-skip_petscrc";
    static char* words[] = {program, skip, nullptr};
    int argc = 2;
    char** argv = words;
    PLISSE_PETSC(SlepcInitialize(&argc, &argv, nullptr, nullptr));
    // PETSc's own error printing would duplicate our messages; errors come back as codes.
    PLISSE_PETSC(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
    owns_ = true;
  }
  for (const auto& o : options) insert_options(o);
}

PetscSession::~PetscSession() {
  if (owns_) SlepcFinalize();
}

void PetscSession::insert_options(const std::string& options) {
  if (options.empty()) return;
  PLISSE_PETSC(PetscOptionsInsertString(nullptr, options.c_str()));
}

int PetscSession::rank() {
  PetscMPIInt r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}

int PetscSession::size() {
  PetscMPIInt s = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &s);
  return s;
}

}  // namespace plisse
