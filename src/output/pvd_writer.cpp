#include "output/pvd_writer.hpp"

#include <charconv>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "output/atomic_file.hpp"
#include "output/vtu_writer.hpp"

namespace plisse {
namespace {

/// Shortest text that reads back to the same double (std::to_chars round-trip guarantee).
std::string shortest(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

void check_entry(const std::filesystem::path& pvd, double time, const std::string& file) {
  PLISSE_CHECK(std::isfinite(time),
               "collection '" << pvd.string() << "': time of '" << file << "' is not finite");
  PLISSE_CHECK(!file.empty(), "collection '" << pvd.string() << "': empty file name");
  PLISSE_CHECK(std::filesystem::path(file).is_relative(),
               "collection '" << pvd.string() << "': file '" << file
                              << "' must be relative to the collection's directory");
}

/// Value of attribute `name` inside one start tag `tag` (our own writer's layout: name="...").
std::string attribute(const std::string& tag, const std::string& name,
                      const std::filesystem::path& pvd) {
  const std::string key = " " + name + "=\"";
  const std::size_t begin = tag.find(key);
  const std::size_t end = begin == std::string::npos ? begin : tag.find('"', begin + key.size());
  if (end == std::string::npos)
    throw InputError({pvd.string(), 0, 0, ""}, "DataSet without attribute '" + name + "'");
  std::string value = tag.substr(begin + key.size(), end - begin - key.size());
  static const std::pair<const char*, char> kEntities[] = {
      {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}, {"&amp;", '&'}};
  for (const auto& [entity, character] : kEntities)
    for (std::size_t at = value.find(entity); at != std::string::npos;
         at = value.find(entity, at + 1))
      value.replace(at, std::char_traits<char>::length(entity), 1, character);
  return value;
}

}  // namespace

PvdWriter::PvdWriter(std::filesystem::path path, std::vector<PvdEntry> entries)
    : path_(std::move(path)), entries_(std::move(entries)) {
  for (const PvdEntry& e : entries_) check_entry(path_, e.time, e.file);
  write();
}

void PvdWriter::add(double time, const std::string& file) {
  check_entry(path_, time, file);
  entries_.push_back({time, file});
  write();
}

void PvdWriter::write() const {
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += kUnitsComment;
  xml +=
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n";
  xml += "  <Collection>\n";
  for (const PvdEntry& e : entries_)
    xml += "    <DataSet timestep=\"" + shortest(e.time) + "\" group=\"\" part=\"0\" file=\"" +
           escape_xml(e.file) + "\"/>\n";
  xml += "  </Collection>\n";
  xml += "</VTKFile>\n";
  write_file_atomically(path_, xml);
}

std::vector<PvdEntry> read_pvd(const std::filesystem::path& path) {
  const std::string text = read_file(path);
  if (text.find("type=\"Collection\"") == std::string::npos)
    throw InputError({path.string(), 0, 0, ""}, "not a VTK collection (.pvd) file");
  std::vector<PvdEntry> entries;
  for (std::size_t at = text.find("<DataSet"); at != std::string::npos;
       at = text.find("<DataSet", at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos)
      throw InputError({path.string(), 0, 0, ""}, "unterminated DataSet tag");
    const std::string tag = text.substr(at, end - at);
    const std::string time_text = attribute(tag, "timestep", path);
    PvdEntry entry;
    const auto parsed =
        std::from_chars(time_text.data(), time_text.data() + time_text.size(), entry.time);
    if (parsed.ec != std::errc() || parsed.ptr != time_text.data() + time_text.size())
      throw InputError({path.string(), 0, 0, ""}, "timestep '" + time_text + "' is not a number");
    entry.file = attribute(tag, "file", path);
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace plisse
