#include "output/json_file.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

namespace plisse {

void write_json_file(const std::filesystem::path& path, const nlohmann::json& value) {
  std::string text;
  try {
    text = value.dump(2);  // NaN and infinities serialise as null (nlohmann::json dump())
  } catch (const nlohmann::json::type_error& e) {  // invalid UTF-8 in a string
    throw Error("cannot write JSON '" + path.string() + "': " + e.what());
  }
  text += '\n';
  write_file_atomically(path, text);
}

nlohmann::json read_json_file(const std::filesystem::path& path) {
  // Parsed, JSON takes ten to twenty times its text: plisse's own files (a summary, wrinkles.json)
  // are kilobytes to a few megabytes, and a larger one is refused unread.
  const std::string text = read_file(path, kMaxJsonBytes);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is the 1-based offset of the error; turn it into line and column for the message.
    int line = 1, column = 1;
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw InputError({path.string(), line, column, ""}, std::string("invalid JSON: ") + e.what());
  }
}

}  // namespace plisse
