// `alpha`, `beta` and `alpha_gamma` of a [[display]] entry (docs/wall-file.md, "Alpha and beta
// maps"): grey PNG files the display's size, relative to the wall file as a warp's is, read once
// when the wall is read into the display's one map of gains and offsets.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "image/png_io.hpp"
#include "tilelayout/tile_layout.hpp"
#include "wall_sections.hpp"

namespace l2 {
namespace {

// The grey bytes of the map `key` names, checked against the display before its pixels are
// read: a grey PNG (8 bits, or 16 taken to 8 as read_png rounds them) the display's size.
std::vector<std::uint8_t> read_grey_map(const TomlFields& f, std::string_view key,
                                        const std::string& name, const Display& d) {
  if (name.empty()) f.fail(key, "must name a grey PNG file, got \"\"");
  const std::filesystem::path path = std::filesystem::path(f.source().file).parent_path() / name;
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error))
    f.fail(key, fmt::format("{}: not a regular file: a map is a PNG file", path.string()));
  PictureSource source;
  RgbImage picture;
  try {
    picture = read_png(path, &source, [&](int width, int height) {
      if (width != d.width || height != d.height) {
        throw LayoutError(fmt::format("{}: {}x{}, but the display is {}x{}", path.string(), width,
                                      height, d.width, d.height));
      }
    });
  } catch (const std::exception& e) {
    f.fail(key, e.what());
  }
  if (source.format != "png" || source.colour_channels != 1) {
    f.fail(key, fmt::format("{}: must be a grey PNG, got {}{}", path.string(),
                            source.colour_channels == 1 ? "grey " : "colour ", source.format));
  }
  std::vector<std::uint8_t> grey(static_cast<std::size_t>(d.width) * d.height);
  const std::uint8_t* rgb = picture.data();
  for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = rgb[3 * i];
  return grey;
}

}  // namespace

void read_levels(const TomlFields& f, Display& d) {
  if (!f.has("alpha") && !f.has("beta")) {
    if (f.has("alpha_gamma")) f.fail("alpha_gamma", "needs an alpha map (alpha = \"...\")");
    return;
  }
  std::vector<std::uint8_t> alpha, beta;
  if (f.has("alpha")) {
    d.alpha = *f.string("alpha");
    alpha = read_grey_map(f, "alpha", d.alpha, d);
    if (f.has("alpha_gamma")) {
      const toml::node& g = *f.node("alpha_gamma");
      const auto v = g.value<double>();  // an integer too
      if (!v || !(*v >= 1 && *v <= kMaxBlendGamma)) {
        f.fail("alpha_gamma", fmt::format("must be a number 1..{}, got {}", kMaxBlendGamma,
                                          v ? fmt::format("{}", *v) : type_name(g)));
      }
      d.alpha_gamma = *v;
    }
  } else if (f.has("alpha_gamma")) {
    f.fail("alpha_gamma", "needs an alpha map (alpha = \"...\")");
  }
  if (f.has("beta")) {
    d.beta = *f.string("beta");
    beta = read_grey_map(f, "beta", d.beta, d);
  }
  LevelMap map = level_map(d.width, d.height, alpha, d.alpha_gamma, beta);
  if (!is_identity(map)) d.level_map = std::make_shared<const LevelMap>(std::move(map));
}

}  // namespace l2
