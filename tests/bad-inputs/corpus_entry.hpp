#pragma once
/// One file of the bad-input corpus (tests/bad-inputs/README.md) and what its header expects.
///
/// Header: the first line is `# WHAT IS WRONG => FRAGMENT | FRAGMENT | ...`; the next comment
/// lines may set options as `# NAME: VALUE` (args, case, commands, output, known-bug,
/// not-under-asan). Fragments:
///   `line N`          the message holds "<case file>:N:" (the error is placed at line N);
///   `line N col C`    the message holds "<case file>:N:C:";
///   `file F`          the message names F (relative to the corpus folder unless absolute,
///                     "--set" or "command line"); without a `file` fragment the message must
///                     name the case file;
///   anything else     must appear verbatim (e.g. `key 'material.c1'`, `must be > 0`).
/// Placeholders in options and `file`: {dir} the corpus folder, {self} this file, {work} the
/// fresh working directory of the run (the default output is {work}/out).
#include <filesystem>
#include <string>
#include <vector>

namespace plisse::test {

struct CorpusEntry {
  std::filesystem::path file;        ///< the corpus file
  std::string description;           ///< what is wrong, in words
  std::vector<std::string> expect;   ///< fragments after "=>", in order of the header
  std::vector<std::string> args;     ///< `# args:` extra arguments for both commands
  std::string case_path = "{self}";  ///< `# case:` the case file given to plisse
  std::vector<std::string> commands{"check", "run"};  ///< `# commands:` which subcommands
  std::string output = "{work}/out";  ///< `# output:` the -o argument of `plisse run`
  std::string known_bug;              ///< `# known-bug:` why the entry is skipped (empty: it runs)
  std::string not_under_asan;         ///< `# not-under-asan:` why AddressSanitizer builds skip it
};

/// Reads the header of `file`. Throws std::runtime_error naming the file when the header is
/// malformed (no " => ", an empty description or fragment, an unknown command).
CorpusEntry read_corpus_entry(const std::filesystem::path& file);

/// `text` with {dir}, {self} and {work} replaced.
std::string expand(const std::string& text, const CorpusEntry& entry,
                   const std::filesystem::path& work);

/// One expected fragment turned into the exact text to look for in the output: `line N [col C]`
/// becomes "<case_file>:N:[C:]", `file F` becomes F expanded (relative to the corpus folder unless
/// absolute, "--set" or "command line"), anything else stays as it is.
std::string expected_text(const std::string& fragment, const CorpusEntry& entry,
                          const std::string& case_file, const std::filesystem::path& work);

/// True when a `file F` fragment replaces the default requirement that the case file is named.
bool names_other_file(const CorpusEntry& entry);

}  // namespace plisse::test
