#pragma once
/// Generated blocks of the markdown manuals: a block is the line `<!-- generated: NAME -->`, the
/// generated text, and the line `<!-- end generated -->`; the text around the blocks is written by
/// hand. docs/case-file.md (case-file keys) and docs/output.md (output reference) have them.
#include <functional>
#include <string>
#include <vector>

namespace plisse {

/// `doc` with the content of every block replaced by `markdown(NAME)`, the text around the blocks
/// kept as it is. Throws Error for a block without its end line or a start line without ' -->',
/// and whatever `markdown` throws for an unknown NAME.
std::string refresh_generated_blocks(
    const std::string& doc, const std::function<std::string(const std::string&)>& markdown);

/// The blocks of `names`, each `<!-- generated: NAME -->`, markdown(NAME) and the end line, with
/// an empty line between blocks: what `plisse case-keys` and `plisse outputs` print.
std::string generated_blocks(const std::vector<std::string>& names,
                             const std::function<std::string(const std::string&)>& markdown);

/// Refreshes the blocks of the markdown file `path` in place (atomically, only when they
/// changed) and returns whether they did. InputError (exit status 2) when the file has no block.
bool update_generated_blocks(const std::string& path,
                             const std::function<std::string(const std::string&)>& markdown);

}  // namespace plisse
