// A glTF file's structure checked before Assimp reads it. Assimp walks the node tree, and parses
// the JSON, recursively: a chain of a few thousand nested nodes, or of a million nested arrays,
// overflowed the stack (SIGSEGV); a node listed as the child of two (a tree the spec forbids) is
// copied once per path to it, so forty such nodes asked for 2^40 copies; a binary glTF whose
// JSON chunk declares 4 GB was given 4 GB before anything was read.
#pragma once

#include <filesystem>

namespace l2::detail {

// Nodes nested deeper than this are refused: real scenes (skeletons, CAD assemblies) stay far
// below, and Assimp's recursion stays far from the end of a thread's stack.
inline constexpr int kMaxNodeDepth = 1000;
// JSON nested deeper than this is refused: glTF's own structure is a few levels deep.
inline constexpr int kMaxJsonDepth = 256;

// Does nothing for a file that is neither a binary glTF ("glTF" first) nor JSON ('{' or '['
// first: Assimp's glTF 1.0 reader tries any file of an extension no reader claims), nor for
// JSON that does not parse (Assimp's error names it). Throws std::runtime_error naming the file
// and what is wrong: "model.gltf: nodes nested 20000 deep (node 19999), more than the 1000
// levels read here", "... node 1 is a child of node 0 twice (a glTF node has one parent)",
// "... JSON nested deeper than 256 levels", "model.glb: its JSON chunk declares 4294967280
// bytes, more than the file's 32".
void check_gltf(const std::filesystem::path& path);

}  // namespace l2::detail
