#include "corpus_entry.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace plisse::test {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split(const std::string& text, const std::string& separator) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = text.find(separator, start);
    out.push_back(
        trim(text.substr(start, at == std::string::npos ? std::string::npos : at - start)));
    if (at == std::string::npos) return out;
    start = at + separator.size();
  }
}

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

}  // namespace

CorpusEntry read_corpus_entry(const std::filesystem::path& file) {
  const auto bad = [&](const std::string& why) {
    return std::runtime_error(file.string() + ": corpus header: " + why);
  };
  std::ifstream in(file);
  if (!in) throw bad("cannot open the file");
  CorpusEntry entry;
  entry.file = file;
  std::string line;
  if (!std::getline(in, line) || !starts_with(line, "# "))
    throw bad("the first line must be '# WHAT IS WRONG => FRAGMENT | ...'");
  const std::size_t arrow = line.find(" => ");
  if (arrow == std::string::npos) throw bad("the first line has no ' => '");
  entry.description = trim(line.substr(2, arrow - 2));
  entry.expect = split(line.substr(arrow + 4), " | ");
  if (entry.description.empty()) throw bad("empty description");
  for (const std::string& f : entry.expect)
    if (f.empty()) throw bad("empty expected fragment");

  // Options: the comment lines right after the first one that look like "# name: value".
  while (std::getline(in, line) && starts_with(line, "# ")) {
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos) break;
    const std::string name = line.substr(2, colon - 2), value = trim(line.substr(colon + 2));
    if (name == "args")
      entry.args = words(value);
    else if (name == "case")
      entry.case_path = value;
    else if (name == "commands")
      entry.commands = words(value);
    else if (name == "output")
      entry.output = value;
    else if (name == "known-bug")
      entry.known_bug = value;
    else if (name == "not-under-asan")
      entry.not_under_asan = value;
    else
      break;  // an ordinary comment
  }
  for (const std::string& c : entry.commands)
    if (c != "check" && c != "run") throw bad("unknown command '" + c + "'");
  return entry;
}

std::string expand(const std::string& text, const CorpusEntry& entry,
                   const std::filesystem::path& work) {
  std::string out = text;
  replace_all(out, "{dir}", entry.file.parent_path().string());
  replace_all(out, "{self}", entry.file.string());
  replace_all(out, "{work}", work.string());
  return out;
}

bool names_other_file(const CorpusEntry& entry) {
  for (const std::string& f : entry.expect)
    if (starts_with(f, "file ")) return true;
  return false;
}

std::string expected_text(const std::string& fragment, const CorpusEntry& entry,
                          const std::string& case_file, const std::filesystem::path& work) {
  const std::vector<std::string> w = words(fragment);
  if (w.size() == 2 && w[0] == "line") return case_file + ":" + w[1] + ":";
  if (w.size() == 4 && w[0] == "line" && w[2] == "col")
    return case_file + ":" + w[1] + ":" + w[3] + ":";
  if (starts_with(fragment, "file ")) {
    const std::string name = expand(trim(fragment.substr(5)), entry, work);
    if (name == "--set" || name == "command line" || std::filesystem::path(name).is_absolute())
      return name;
    return (entry.file.parent_path() / name).string();
  }
  return fragment;
}

}  // namespace plisse::test
