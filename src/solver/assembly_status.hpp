#pragma once
/// The outcome of one assembly over the elements: whether every element could be evaluated, and
/// which one came closest to inverting.
namespace plisse {

/// What went wrong in an assembly, for the step controller and the diagnostics.
struct AssemblyStatus {
  bool ok = true;
  int worst_element = -1;  ///< element with the smallest J (or the failed bubble solve)
  double min_J = 1.0;
};

/// Adds the outcome of element `e` (`ok`, and `min_J`, its smallest det F) to `status`: keeps the
/// first failed element, else the one with the smallest J. Called in element order, so that the
/// result does not depend on how the elements were evaluated.
inline void track_element(AssemblyStatus& status, bool ok, double min_J, int e) {
  if (!status.ok) return;
  if (!ok || min_J < status.min_J) {
    status.ok = ok;
    status.min_J = min_J;
    status.worst_element = e;
  }
}

}  // namespace plisse
