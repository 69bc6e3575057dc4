#include "case/test_data_reader.hpp"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plisse {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

/// A finite number filling the whole field, or nothing.
bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}

}  // namespace

std::vector<TestPoint> read_test_data(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = read_file(path, kMaxTestDataBytes);
  if (text.find('\0') != std::string::npos)
    throw InputError({file, 0, 0, ""}, "is binary (holds a NUL byte), not a CSV text file");
  // A spreadsheet's "CSV UTF-8" starts with a byte-order mark, which would glue itself to the
  // first column's name, unseen in the message: it is skipped.
  const std::string_view bom = "\xEF\xBB\xBF";
  std::istringstream in(text.compare(0, bom.size(), bom) == 0 ? text.substr(bom.size()) : text);
  std::string line;
  int number = 0;
  std::array<int, 3> column{-1, -1, -1};  // mode, stretch, stress
  const std::array<const char*, 3> names{"mode", "stretch", "stress"};
  std::size_t n_columns = 0;
  std::vector<TestPoint> points;
  while (std::getline(in, line)) {
    ++number;
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    const std::vector<std::string> fields = split(content);
    if (n_columns == 0) {  // the header
      for (std::size_t k = 0; k < fields.size(); ++k) {
        bool known = false;
        for (std::size_t c = 0; c < 3; ++c) {
          if (fields[k] != names[c]) continue;
          if (column[c] >= 0)
            throw InputError({file, number, 0, fields[k]}, "column named twice in the header");
          column[c] = static_cast<int>(k);
          known = true;
        }
        if (!known)
          throw InputError({file, number, 0, fields[k]},
                           "unknown column (the header is mode,stretch,stress, in any order)");
      }
      for (std::size_t c = 0; c < 3; ++c)
        if (column[c] < 0)
          throw InputError({file, number, 0, names[c]},
                           "missing from the header (the header is mode,stretch,stress, in any "
                           "order)");
      n_columns = fields.size();
      continue;
    }
    if (fields.size() != n_columns)
      throw InputError({file, number, 0, ""}, std::to_string(fields.size()) + " fields where the " +
                                                  "header has " + std::to_string(n_columns));
    TestPoint p;
    const std::string& mode = fields[static_cast<std::size_t>(column[0])];
    const auto parsed = parse_test_mode(mode);
    if (!parsed)
      throw InputError({file, number, 0, "mode"},
                       "unknown test mode '" + mode + "' (uniaxial, equibiaxial, planar)");
    p.mode = *parsed;
    if (!parse_number(fields[static_cast<std::size_t>(column[1])], p.stretch) || !(p.stretch > 0.0))
      throw InputError({file, number, 0, "stretch"},
                       "must be a finite number > 0 (got '" +
                           fields[static_cast<std::size_t>(column[1])] + "')");
    if (p.stretch == 1.0)
      throw InputError({file, number, 0, "stretch"},
                       "the undeformed state (stretch 1) carries no stress to fit: leave it out");
    if (!parse_number(fields[static_cast<std::size_t>(column[2])], p.stress) || p.stress == 0.0)
      throw InputError({file, number, 0, "stress"},
                       "must be a finite non-zero number in MPa (got '" +
                           fields[static_cast<std::size_t>(column[2])] +
                           "'): the fit weighs each point by its own stress");
    if ((p.stretch > 1.0) != (p.stress > 0.0))
      throw InputError({file, number, 0, "stress"},
                       std::string("a stretch ") + (p.stretch > 1.0 ? "above" : "below") +
                           " 1 needs a " + (p.stretch > 1.0 ? "positive (tensile)" : "negative") +
                           " nominal stress");
    points.push_back(p);
  }
  if (n_columns == 0)
    throw InputError({file, 0, 0, ""}, "holds no header line mode,stretch,stress");
  if (points.empty()) throw InputError({file, 0, 0, ""}, "holds no data line after its header");
  return points;
}

}  // namespace plisse
