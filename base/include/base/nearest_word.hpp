// The word a user probably meant: for an unknown key in a file, the valid key closest to what was
// typed (a transposition, a letter missing, added or wrong), so an error can say "did you mean".
//
// Example:
//   nearest_word("tile_hieght", {"kind", "tile_width", "tile_height"})  // "tile_height"
//   nearest_word("colour", {"kind", "width"})                            // nullopt: too far
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace l2 {

// The choice within a third of the word's length of edits (at least one) of `word`, the closest;
// nullopt when none is that close.
std::optional<std::string_view> nearest_word(std::string_view word,
                                             std::initializer_list<std::string_view> choices);

// "kind, tile_width, tile_height": the choices as a list for a message.
std::string word_list(std::initializer_list<std::string_view> choices);

}  // namespace l2
