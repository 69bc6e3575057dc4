// Checks of the raw case-file text that yaml-cpp does not make, or makes without saying where or
// why: non-text bytes, unclosed quotes, second documents, tab indentation, oversized files.
#include "case/yaml_text.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/input_file.hpp"

namespace plisse::case_detail {
namespace {

/// Length of the well-formed UTF-8 sequence of 2 to 4 bytes at text[i] (RFC 3629, section 4), or 0.
std::size_t utf8_sequence_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  std::size_t n = 0;
  if (byte(i) >= 0xc2 && byte(i) <= 0xdf) n = 2;
  if (byte(i) >= 0xe0 && byte(i) <= 0xef) n = 3;
  if (byte(i) >= 0xf0 && byte(i) <= 0xf4) n = 4;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  return n;
}

/// Offset of the first byte YAML does not allow in a UTF-8 stream (YAML 1.2, section 5.1,
/// c-printable): a control character other than tab, line feed and carriage return, DEL, or a
/// byte that does not begin a well-formed UTF-8 sequence; npos when there is none. yaml-cpp
/// passes such bytes into messages and values, so a binary file gave errors full of raw bytes.
/// Streams with a UTF-16 or UTF-32 byte order mark are left to yaml-cpp.
std::size_t first_non_text_byte(const std::string& text) {
  using namespace std::string_view_literals;
  for (const std::string_view bom : {"\xFE\xFF"sv, "\xFF\xFE"sv, "\0\0\xFE\xFF"sv})
    if (std::string_view(text).substr(0, bom.size()) == bom) return std::string::npos;
  for (std::size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0; i < text.size();) {
    const auto ch = static_cast<unsigned char>(text[i]);
    if (ch >= 0x80) {
      const std::size_t n = utf8_sequence_length(text, i);
      if (n == 0) return i;
      i += n;
      continue;
    }
    if ((ch < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') || ch == 0x7f) return i;
    ++i;
  }
  return std::string::npos;
}

/// Offset of the start of 0-based line `line` of `text` (npos past the end).
std::size_t line_start(const std::string& text, int line) {
  std::size_t start = 0;
  for (int l = 0; l < line && start != std::string::npos; ++l) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  return start;
}

/// Whether 0-based line `line` of `text` has a tab in its indentation.
bool indented_with_tab(const std::string& text, int line) {
  const std::size_t start = line_start(text, line);
  for (std::size_t i = start; i != std::string::npos && i < text.size(); ++i) {
    if (text[i] == '\t') return true;
    if (text[i] != ' ') return false;
  }
  return false;
}

/// Finds a quoted scalar that is never closed. yaml-cpp ends such a scalar at the end of the input
/// instead of reporting it, so `title: "abc` swallows the rest of the file into one text value and
/// the sections after it silently vanish. The parser's events give each scalar's mark (a byte
/// offset, at the scalar's tag or anchor if it has one); the quote found there must be closed.
class UnclosedQuoteFinder : public YAML::EventHandler {
 public:
  explicit UnclosedQuoteFinder(const std::string& text) : text_(text) {
    if (text_.rfind("\xEF\xBB\xBF", 0) == 0) bom_ = 3;  // yaml-cpp's offsets skip a UTF-8 BOM
  }
  /// The mark of the first unclosed quoted scalar, if any.
  const std::optional<YAML::Mark>& found() const { return found_; }
  /// Documents seen so far, and where the second one starts (its first node, else its start).
  int documents() const { return documents_; }
  std::optional<YAML::Mark> second_document() const {
    return second_node_ ? second_node_ : second_document_;
  }

  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                const std::string&) override {
    note(mark);
    if (tag == "?" || found_) return;  // plain scalars have no quotes
    std::size_t i = static_cast<std::size_t>(mark.pos) + bom_;
    // Skip the node's properties: "!tag" and "&anchor", each followed by blanks.
    while (i < text_.size() && (text_[i] == '!' || text_[i] == '&')) {
      while (i < text_.size() && !std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
      while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t')) ++i;
    }
    if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) return;  // block scalar
    if (!closed(i)) found_ = mark;
  }
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ == 2) second_document_ = mark;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { note(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { note(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    note(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    note(mark);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& mark) {
    if (documents_ == 2 && !second_node_) second_node_ = mark;
  }
  /// Whether the quote at `open` has its closing quote: `\"` escapes inside double quotes
  /// (YAML 1.2, section 7.3.1), `''` inside single quotes (section 7.3.2).
  bool closed(std::size_t open) const {
    const char quote = text_[open];
    for (std::size_t i = open + 1; i < text_.size(); ++i) {
      if (quote == '"' && text_[i] == '\\') {
        ++i;
      } else if (text_[i] == quote) {
        if (quote == '\'' && i + 1 < text_.size() && text_[i + 1] == '\'') {
          ++i;
          continue;
        }
        return true;
      }
    }
    return false;
  }

  const std::string& text_;
  std::size_t bom_ = 0;
  std::optional<YAML::Mark> found_;
  int documents_ = 0;
  std::optional<YAML::Mark> second_document_, second_node_;
};

}  // namespace

std::string scalar_text_problem(const std::string& text) {
  char code[16];
  for (std::size_t i = 0; i < text.size();) {
    const auto ch = static_cast<unsigned char>(text[i]);
    if (ch >= 0x80) {
      const std::size_t n = utf8_sequence_length(text, i);
      if (n == 0) {
        std::snprintf(code, sizeof code, "0x%02X", ch);
        return std::string("is not UTF-8 text (byte ") + code + ")";
      }
      // U+0080-U+009F, the C1 controls, are the two-byte sequences C2 80 to C2 9F.
      const auto next = static_cast<unsigned char>(text[i + 1]);
      if (ch == 0xc2 && next <= 0x9f) {
        std::snprintf(code, sizeof code, "U+%04X", next);
        return std::string("holds the control character ") + code;
      }
      i += n;
      continue;
    }
    if ((ch < 0x20 && ch != '\t' && ch != '\n') || ch == 0x7f) {
      std::snprintf(code, sizeof code, "U+%04X", ch);
      return std::string("holds the control character ") + code;
    }
    ++i;
  }
  return {};
}

YAML::Node load_case_document(const std::string& text, const std::string& name) {
  if (const std::size_t at = first_non_text_byte(text); at != std::string::npos) {
    const auto before = text.begin() + static_cast<std::ptrdiff_t>(at);
    const int line = 1 + static_cast<int>(std::count(text.begin(), before, '\n'));
    const std::size_t newline = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
    const int column = static_cast<int>(newline == std::string::npos ? at + 1 : at - newline);
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text[at]));
    throw InputError({name, line, column, ""},
                     std::string("the case file is not YAML text: byte ") + byte +
                         " is not a printable UTF-8 character (is it a binary file?)");
  }
  // One pass over the events first, stopping at a second document: yaml-cpp 0.7 returns empty
  // documents forever on some malformed text (a lone ','; yaml-cpp issue #1040), so LoadAll may
  // only see text with at most one document.
  UnclosedQuoteFinder finder(text);
  {
    std::istringstream in(text);
    YAML::Parser parser(in);
    try {
      while (finder.documents() < 2 && parser.HandleNextDocument(finder)) {
      }
    } catch (const YAML::Exception&) {  // LoadAll below reports it with its place
    }
  }
  if (const auto& m = finder.second_document()) {
    // A second document starts at a '---' line, or where yaml-cpp gave up on the first one (a
    // stray ',' or ']' at the top level): say which.
    bool marker = false;  // a '---' line at the mark or before it, past blank and comment lines
    for (int l = m->is_null() ? -1 : m->line; l >= 0 && !marker; --l) {
      const std::size_t start = line_start(text, l);
      if (start == std::string::npos) continue;
      const std::string line = text.substr(start, text.find('\n', start) - start);
      marker = line.compare(0, 3, "---") == 0;
      const std::size_t first = line.find_first_not_of(" \t\r");
      if (l < m->line && first != std::string::npos && line[first] != '#') break;
    }
    throw InputError({name, m->is_null() ? 0 : m->line + 1, m->is_null() ? 0 : m->column + 1, ""},
                     marker ? "a case file holds one YAML document, this is a second one (remove "
                              "the '---' line before it or split the file)"
                            : "YAML syntax error: the case's top-level map cannot continue here "
                              "(a stray ',', ']' or '}'?)");
  }
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp stops at 2000 levels with the message "bad file", which names no cause.
    const bool marked = !e.mark.is_null();
    throw InputError({name, marked ? e.mark.line + 1 : 0, marked ? e.mark.column + 1 : 0, ""},
                     "YAML syntax error: lists or maps nested more than " +
                         std::to_string(e.depth()) +
                         " levels deep here, the parser's limit (a case file needs a few)");
  } catch (const YAML::Exception& e) {
    const bool marked = !e.mark.is_null();
    std::string rule = "YAML syntax error: " + e.msg;
    // yaml-cpp's messages for a tab in the indentation ("illegal map value", ...) do not say so.
    if (marked && (indented_with_tab(text, e.mark.line) ||
                   (e.mark.line > 0 && indented_with_tab(text, e.mark.line - 1))))
      rule += " (this line or the one before is indented with a tab: YAML indents with spaces)";
    throw InputError({name, marked ? e.mark.line + 1 : 0, marked ? e.mark.column + 1 : 0, ""},
                     rule);
  }
  if (const auto& m = finder.found())
    throw InputError({name, m->line + 1, m->column + 1, ""},
                     "YAML syntax error: this quoted value is never closed (its closing quote "
                     "is missing, so it would run to the end of the file)");
  return documents.empty() ? YAML::Node() : documents.front();
}

std::string read_case_text(const std::string& path) {
  // A regular file of at most kMaxCaseFileBytes: a FIFO would block the reader, a device such as
  // /dev/zero (or a huge file given by mistake) fill the memory before the parser sees a byte.
  check_input_file(path, kMaxCaseFileBytes, "case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0, ""}, "the case file cannot be opened for reading");
  // Read at most kMaxCaseFileBytes + 1: the file may have grown since it was checked.
  std::string text(kMaxCaseFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxCaseFileBytes)
    throw InputError({path, 0, 0, ""}, "the case file is larger than " +
                                           std::to_string(kMaxCaseFileBytes >> 20) +
                                           " MiB; a case file is a short YAML text");
  return text;
}

}  // namespace plisse::case_detail
