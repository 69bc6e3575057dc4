// The clamped strip's critical buckling strain with either element family, one configuration per
// process so that the peak memory is that configuration's: the measure of docs/performance.md,
// "Element families" (the same strip and search as tests/verification/buckling/).
//
// Usage: plisse-strip-buckling mini|taylor-hood LAYERS [IN_PLANE_SIZE [LENGTH]]
//   LAYERS: cells through the thickness t = 1 mm; IN_PLANE_SIZE [mm]: in-plane cell size
//   (default t / LAYERS, cubic cells; 0 for the default); LENGTH [mm]: the strip's length L
//   (default 20, L/t = 20). PLANE_STRAIN=1 in the environment: the strip in plane strain
//   (u_y = 0, one cell across). Prints one line: element, layers, size, free dofs,
//   eps_cr / beam theory, wall time [s], peak resident memory [MiB].
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "element/element_family.hpp"
#include "solver/petsc_session.hpp"
#include "verification/buckling/fixtures/clamped_strip.hpp"

int main(int argc, char** argv) {
  using namespace plisse;
  if (argc < 3 || !parse_element_family(argv[1])) {
    std::fprintf(stderr,
                 "usage: plisse-strip-buckling mini|taylor-hood LAYERS [IN_PLANE_SIZE [LENGTH]]\n");
    return 2;
  }
  test::ClampedStrip strip;
  strip.element = *parse_element_family(argv[1]);
  strip.layers = std::atoi(argv[2]);
  if (argc > 3) strip.in_plane_size = std::atof(argv[3]);
  if (argc > 4) strip.length = std::atof(argv[4]);
  if (const char* plane = std::getenv("PLANE_STRAIN"))
    strip.plane_strain = std::string(plane) == "1";
  if (strip.layers < 1 || strip.in_plane_size < 0 || !(strip.length > 0)) {
    std::fprintf(stderr, "plisse-strip-buckling: LAYERS >= 1, IN_PLANE_SIZE >= 0, LENGTH > 0\n");
    return 2;
  }
  PetscSession petsc({"-no_signal_handler"});
  const auto start = std::chrono::steady_clock::now();
  const test::BucklingResult r = test::find_critical_strain(strip);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double size = strip.in_plane_size > 0 ? strip.in_plane_size : 1.0 / strip.layers;
  std::printf("%-12s %3d %7.4f %9d %10.6f %9.2f %8.1f\n", argv[1], strip.layers, size, r.n_free,
              r.strain_critical / r.strain_analytic, seconds, usage.ru_maxrss / 1024.0);
  return r.strain_critical > 0 ? 0 : 1;
}
