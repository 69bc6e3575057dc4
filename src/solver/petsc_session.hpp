#pragma once
/// PETSc, SLEPc (and MPI) initialisation for the lifetime of one object.
#include <string>
#include <vector>

namespace plisse {

class PetscSession {
 public:
  /// Initialises PETSc and SLEPc once per process (the first session owns them and finalises
  /// them in its destructor). `options` are PETSc command-line style options
  /// ("-snes_monitor -ksp_view") inserted into the global options database; later options win.
  explicit PetscSession(const std::vector<std::string>& options = {});
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

  /// Adds options (whitespace-separated string) to the global database.
  static void insert_options(const std::string& options);
  /// MPI rank and size of PETSC_COMM_WORLD.
  static int rank();
  static int size();

 private:
  bool owns_ = false;
};

}  // namespace plisse
