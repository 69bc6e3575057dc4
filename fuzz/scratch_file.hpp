#pragma once
/// A temporary file that fuzz targets rewrite for every input (the readers under test take paths).
///
/// Each process gets its own directory under the system temporary directory
/// (plisse-fuzz-<pid>), so parallel fuzzing jobs do not share files; it is removed when the
/// process exits normally.
#include <filesystem>
#include <string>

#include "targets.hpp"

namespace plisse::fuzz {

/// Writes `data` to the file `name` in this process's scratch directory (replacing it) and returns
/// its path.
std::filesystem::path write_scratch_file(const std::string& name, Bytes data);

}  // namespace plisse::fuzz
