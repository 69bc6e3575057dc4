#include "output/xml_tags.hpp"

#include <array>
#include <charconv>
#include <utility>

namespace plisse::vtu_detail {

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

std::optional<std::uint64_t> parse_unsigned(std::string_view text) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<std::string> decode_entities(std::string_view text) {
  static constexpr std::array<std::pair<std::string_view, char>, 5> kEntities = {
      {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}}};
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] != '&') {
      out += text[i++];
      continue;
    }
    bool known = false;
    for (const auto& [entity, c] : kEntities)
      if (text.substr(i, entity.size()) == entity) {
        out += c;
        i += entity.size();
        known = true;
        break;
      }
    if (!known) return std::nullopt;
  }
  return out;
}

Tag parse_tag(const VtuFile& file, std::string_view text) {
  Tag tag;
  std::size_t i = 0;
  if (!text.empty() && text[0] == '/') {
    tag.closing = true;
    ++i;
  }
  const std::size_t name_start = i;
  while (i < text.size() && !is_space(text[i]) && text[i] != '/') ++i;
  tag.name = std::string(text.substr(name_start, i - name_start));
  if (tag.name.empty()) file.fail("malformed XML header: a tag without a name");
  while (true) {
    while (i < text.size() && is_space(text[i])) ++i;
    if (i == text.size()) break;
    if (text[i] == '/' && i + 1 == text.size()) break;  // self-closing
    const std::size_t key_start = i;
    while (i < text.size() && text[i] != '=' && !is_space(text[i])) ++i;
    const std::string key(text.substr(key_start, i - key_start));
    while (i < text.size() && is_space(text[i])) ++i;
    if (key.empty() || i == text.size() || text[i] != '=')
      file.fail("malformed XML header: attribute '" + key + "' of <" + tag.name + "> has no value");
    ++i;
    while (i < text.size() && is_space(text[i])) ++i;
    if (i == text.size() || (text[i] != '"' && text[i] != '\''))
      file.fail("malformed XML header: attribute '" + key + "' of <" + tag.name +
                "> is not quoted");
    const char quote = text[i++];
    const std::size_t close = text.find(quote, i);
    if (close == std::string_view::npos)
      file.fail("malformed XML header: unterminated value of '" + key + "' in <" + tag.name + ">");
    const auto value = decode_entities(text.substr(i, close - i));
    if (!value)
      file.fail("malformed XML header: unknown entity in '" + key + "' of <" + tag.name + ">");
    if (!tag.attributes.emplace(key, *value).second)
      file.fail("malformed XML header: attribute '" + key + "' repeated in <" + tag.name + ">");
    i = close + 1;
  }
  return tag;
}

const std::string* attribute(const Tag& tag, const std::string& key) {
  const auto it = tag.attributes.find(key);
  return it == tag.attributes.end() ? nullptr : &it->second;
}

std::string require_attribute(const VtuFile& file, const Tag& tag, const std::string& key) {
  const std::string* value = attribute(tag, key);
  if (value == nullptr) file.fail("<" + tag.name + "> has no " + key + " attribute");
  return *value;
}

std::uint64_t require_unsigned(const VtuFile& file, const Tag& tag, const std::string& key) {
  const std::string text = require_attribute(file, tag, key);
  const auto value = parse_unsigned(text);
  if (!value)
    file.fail("<" + tag.name + "> " + key + "=\"" + text + "\" is not an unsigned integer");
  return *value;
}

}  // namespace plisse::vtu_detail
