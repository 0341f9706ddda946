#include "pipeserver/model_texture.hpp"

#include <atomic>
#include <utility>

namespace l2 {

namespace {

// GL name 0 is no texture.
std::atomic<std::uint32_t> last_id{0};

}  // namespace

ModelTexture::ModelTexture(RgbImage pixels) : image(std::move(pixels)), id(++last_id) {}

}  // namespace l2
