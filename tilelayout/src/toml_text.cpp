#include "tilelayout/toml_text.hpp"

#include <toml++/toml.h>
#include <sstream>

namespace l2 {

std::string toml_quoted(std::string_view text) {
  // toml++'s own writer, without its multi-line form: one field stays on one line.
  const toml::value<std::string> value{std::string(text)};
  std::ostringstream out;
  out << toml::toml_formatter{value, toml::format_flags::allow_unicode_strings};
  return out.str();
}

}  // namespace l2
