// The page's files (page/), built into the program (embed_files.cmake) so the page needs
// nothing but this program: no files beside it, no network.
#pragma once

#include <span>
#include <string_view>

namespace l2 {

struct PageAsset {
  std::string_view path;  // "/", "/app.js", ...
  std::string_view type;  // its Content-Type
  std::string_view body;
};

std::span<const PageAsset> page_assets();

}  // namespace l2
