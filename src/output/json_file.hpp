#pragma once
/// JSON files of a run directory (summary.json: dofs, elements, wall time per phase, peak memory,
/// final metrics, wrinkle table), written pretty-printed and atomically, and read back (e.g. by
/// `plisse wrinkles DIR`).
///
/// Non-finite numbers: JSON has no NaN or infinity. nlohmann::json serialises them as `null`, so
/// the file stays valid JSON for every reader; a reader therefore gets null where the run had a
/// NaN or an infinite value and must treat null as "not a finite number".
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace plisse {

/// Writes `value` to `path`, indented by 2 spaces, ending with a newline, atomically
/// (output/atomic_file.hpp). NaN and +-infinity become null (see file comment). Strings must be
/// valid UTF-8 (plisse::Error otherwise). Throws plisse::Error naming the path on a write failure.
void write_json_file(const std::filesystem::path& path, const nlohmann::json& value);

/// Largest JSON file read_json_file reads [bytes]: a summary.json of a long run with many rings,
/// probes and instabilities is a few megabytes.
inline constexpr std::uintmax_t kMaxJsonBytes = std::uintmax_t{64} << 20;

/// Parses the JSON file at `path`. Throws plisse::InputError (file = path, with the line and
/// column of a syntax error) if it cannot be read, is larger than kMaxJsonBytes (refused unread)
/// or is not valid JSON.
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace plisse
