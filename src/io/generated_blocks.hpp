#pragma once
/// Generated blocks of the markdown manuals: a block is the line `<!-- generated: NAME -->`, the
/// generated text, and the line `<!-- end generated -->`; the text around the blocks is written by
/// hand. docs/case-file.md (case-file keys) and docs/output.md (output reference) have them.
#include <functional>
#include <string>

namespace plisse {

/// `doc` with the content of every block replaced by `markdown(NAME)`, the text around the blocks
/// kept as it is. Throws Error for a block without its end line or a start line without ' -->',
/// and whatever `markdown` throws for an unknown NAME.
std::string refresh_generated_blocks(
    const std::string& doc, const std::function<std::string(const std::string&)>& markdown);

}  // namespace plisse
