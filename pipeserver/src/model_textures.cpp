#include "model_textures.hpp"

#include <assimp/material.h>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <span>
#include <stdexcept>
#include <utility>

#include "image/png_io.hpp"

namespace l2::detail {

namespace {

// A texture over kMaxTextureSide: refused, where a texture that cannot be read is left out.
struct TooLarge : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where a material's base-colour texture is, as the model writes it ("*0": embedded, the first
// of the file's; else a file path), and which texture coordinates it is mapped with. Empty: none.
// glTF's base colour is BASE_COLOR (Assimp also copies it to DIFFUSE); OBJ's map_Kd and the
// other formats' diffuse map are DIFFUSE.
std::pair<std::string, unsigned> texture_of(const aiMaterial& material) {
  for (const aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
    aiString path;
    unsigned channel = 0;
    if (material.GetTextureCount(type) > 0 &&
        material.GetTexture(type, 0, &path, nullptr, &channel) == AI_SUCCESS && path.length > 0)
      return {path.C_Str(), channel};
  }
  return {};
}

// The texture's picture file: Windows separators (".\wood.jpg", as many OBJ exporters write)
// read as '/', a relative path taken from the model's folder.
std::filesystem::path file_of(const std::filesystem::path& model, std::string written) {
  std::replace(written.begin(), written.end(), '\\', '/');
  return model.parent_path() / written;
}

// How a texture is named in the model's lines: "embedded texture 0" or "texture 'wood.jpg'".
std::string name_of(const std::string& written, int embedded) {
  if (embedded >= 0) return fmt::format("embedded texture {}", embedded);
  return fmt::format("texture '{}'", written);
}

SizeCheck bounded(const std::filesystem::path& model, const std::string& name) {
  return [&model, name](int width, int height) {
    if (width <= kMaxTextureSide && height <= kMaxTextureSide) return;
    throw TooLarge(
        fmt::format("{}: {} is {}x{} pixels, larger than a texture may be (sides up to {})",
                    model.string(), name, width, height, kMaxTextureSide));
  };
}

// Raw texels (an uncompressed embedded texture): B, G, R, A each, rows top to bottom.
RgbImage from_texels(const aiTexture& t, const SizeCheck& accept) {
  accept(static_cast<int>(std::min(t.mWidth, 1u << 30)),
         static_cast<int>(std::min(t.mHeight, 1u << 30)));
  RgbImage image(static_cast<int>(t.mWidth), static_cast<int>(t.mHeight));
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const aiTexel& c =
          t.pcData[static_cast<std::size_t>(y) * t.mWidth + static_cast<unsigned>(x)];
      image.set(x, y, {c.r, c.g, c.b});
    }
  }
  return image;
}

// The picture of a texture the model embeds or names. Throws TooLarge, or std::runtime_error
// with the reason it cannot be read after "LABEL: ".
RgbImage picture_of(const std::filesystem::path& model, const std::string& written,
                    const aiTexture* embedded, const std::string& label, const SizeCheck& accept) {
  if (embedded == nullptr) return read_png(file_of(model, written), nullptr, accept);
  if (embedded->mHeight > 0) return from_texels(*embedded, accept);
  // mHeight 0: mWidth bytes of a picture file, its format in the hint ("png", "jpg").
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(embedded->pcData),
                                            embedded->mWidth);
  return read_picture_bytes(bytes, label, embedded->achFormatHint, accept);
}

// The reason in a reader's "LABEL: reason".
std::string reason(const std::runtime_error& e, const std::string& label) {
  const std::string what = e.what();
  if (what.rfind(label + ": ", 0) == 0) return what.substr(label.size() + 2);
  return what;
}

class Reader {
 public:
  Reader(const std::filesystem::path& model, const aiScene& scene) : model_(model), scene_(scene) {}

  ModelTextures read() {
    for (unsigned i = 0; i < scene_.mNumMeshes; ++i) {
      const aiMesh& mesh = *scene_.mMeshes[i];
      const auto [written, channel] = texture_of(*scene_.mMaterials[mesh.mMaterialIndex]);
      MeshTexture t;
      t.channel = channel;
      if (!written.empty()) t.texture = texture(written, mesh.HasTextureCoords(channel));
      out_.of_mesh.push_back(t);
    }
    return std::move(out_);
  }

 private:
  // The index of the texture `written`, read on its first use; -1 when it is left out.
  std::int32_t texture(const std::string& written, bool mapped) {
    const auto [embedded, index] = scene_.GetEmbeddedTextureAndIndex(written.c_str());
    const std::string name = name_of(written, index);
    if (!mapped) {
      leave_out(name, "its mesh has no texture coordinates");
      return -1;
    }
    const auto known = read_.find(written);
    if (known != read_.end()) return known->second;
    std::int32_t& slot = read_[written];
    slot = -1;
    if (written[0] == '*' && embedded == nullptr) {
      leave_out(name, "the file embeds no such texture");
      return slot;
    }
    const std::string label = model_.string() + ": " + name;
    try {
      RgbImage image = picture_of(model_, written, embedded, label, bounded(model_, name));
      slot = static_cast<std::int32_t>(out_.textures.size());
      out_.textures.push_back(std::make_shared<const ModelTexture>(std::move(image)));
    } catch (const TooLarge&) {
      throw;
    } catch (const std::runtime_error& e) {
      // The readers' errors begin with what they read: the picture file, or the label.
      leave_out(name, reason(e, embedded ? label : file_of(model_, written).string()));
    }
    return slot;
  }

  // Said once per texture and reason, however many meshes it is left out of.
  void leave_out(const std::string& name, const std::string& why) {
    std::string line = fmt::format("{}: {} left out ({}), drawn in its material's colour",
                                   model_.string(), name, why);
    if (std::find(out_.left_out.begin(), out_.left_out.end(), line) == out_.left_out.end())
      out_.left_out.push_back(std::move(line));
  }

  const std::filesystem::path& model_;
  const aiScene& scene_;
  std::map<std::string, std::int32_t> read_;  // by the path as written
  ModelTextures out_;
};

}  // namespace

ModelTextures read_textures(const std::filesystem::path& model, const aiScene& scene) {
  return Reader(model, scene).read();
}

}  // namespace l2::detail
