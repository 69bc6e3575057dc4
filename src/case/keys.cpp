// Refreshing the generated key tables of docs/case-file.md from the case-file schema.
#include "case/keys.hpp"

#include "output/generated_blocks.hpp"

namespace plisse {

std::string refresh_case_key_blocks(const std::string& doc) {
  return refresh_generated_blocks(doc, case_keys_markdown);
}

}  // namespace plisse
