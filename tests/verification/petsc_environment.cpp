// One PETSc session per test process: PETSc can be initialised only once per process, so the
// session lives in a GoogleTest global environment (set up before the first test, finalised after
// the last) instead of in each test.
#include <gtest/gtest.h>

#include <memory>

#include "solver/petsc_session.hpp"

namespace plisse::test {
namespace {

class PetscEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { session_ = std::make_unique<PetscSession>(); }
  void TearDown() override { session_.reset(); }

 private:
  std::unique_ptr<PetscSession> session_;
};

// GoogleTest takes ownership of the environment.
[[maybe_unused]] ::testing::Environment* const kPetscEnvironment =
    ::testing::AddGlobalTestEnvironment(new PetscEnvironment);

}  // namespace
}  // namespace plisse::test
