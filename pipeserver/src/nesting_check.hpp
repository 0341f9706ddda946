// How deep an XML model (Collada, and the other XML formats Assimp reads) or a brace-nested text
// model (DirectX .x as text, ASCII FBX, ASE, MD5) nests, checked before Assimp reads it. Assimp
// walks such trees recursively: a Collada file of nodes nested 17,400 deep overflowed the stack
// (SIGSEGV) in the renderer. (glTF and its JSON: gltf_check.hpp.)
#pragma once

#include <filesystem>
#include <string_view>

namespace l2::detail {

// Elements or braces nested deeper than this are refused: real scenes (skeletons, assemblies,
// a Collada file's own structure around them) stay far below.
inline constexpr int kMaxModelNesting = 1000;

// The deepest nesting of `text` if it is XML (its first character, after a byte-order mark and
// white space, is '<'): elements open, comments, CDATA, declarations and processing instructions
// skipped, a quoted attribute value's '>' not ending its tag; with the line where it is first
// reached. Depth 0 for text that is not XML.
struct Nesting {
  int depth = 0;
  int line = 0;
};
Nesting xml_nesting(std::string_view text, int stop_above = kMaxModelNesting);
// The deepest '{' nesting outside double-quoted strings, for the brace-nested text formats.
Nesting brace_nesting(std::string_view text, int stop_above = kMaxModelNesting);

// Does nothing for a file of another format. Throws std::runtime_error naming the file and where
// the limit is passed: "deep.dae: XML nested deeper than 1000 levels (at line 1012)".
void check_nesting(const std::filesystem::path& path);

}  // namespace l2::detail
