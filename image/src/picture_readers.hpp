// The OpenImageIO reader a picture is opened with, by every path of the module (a whole read,
// the image cache, the tiled copy): the reader of the format the file's first bytes name, else
// the one its name's extension (or a picture in memory's hint) names, and only a reader of a
// format read here (image/picture_formats.hpp). OpenImageIO's trial of every reader it has, when
// the name's reader cannot open a file, is turned off for the process: it reached readers no
// check bounds.
#pragma once

#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <string_view>

#include "base/result.hpp"

namespace l2::png_codec {

// The format a picture is read as (OpenImageIO's name), and whether its first bytes named it.
struct ReaderChoice {
  std::string format;
  bool by_signature = false;
};
// `head`: the picture's first bytes; `name`: its path, or an extension ("tga"), or empty.
// Failure in one line: a format not read here, or none known.
Result<ReaderChoice> choose_reader(std::string_view head, const std::string& name);

// The header of a format known by its name alone, checked once its reader is chosen: an RLA
// file's (image/rla_header.hpp). Formats with a signature are checked before, by their bytes
// (picture_checks.hpp). `head`: the first kRlaHeaderBytes bytes where the file has them.
Status check_chosen(const ReaderChoice& choice, std::string_view head);

// A reader of `format`, one read here, not yet opened.
std::unique_ptr<OIIO_NAMESPACE::ImageInput> make_reader(std::string_view format);

// The file at `path` opened by the reader choose_reader picks, with `config` (may be null).
// Failure in one line, in the words of the reader that knows the content ("cannot read: a GIF
// file: ...").
Result<std::unique_ptr<OIIO_NAMESPACE::ImageInput>> open_reader(
    const char* path, const OIIO_NAMESPACE::ImageSpec* config = nullptr);

// What the image cache makes its readers of `format` (one read here) with (add_file), so that
// it too opens a file by its content.
OIIO_NAMESPACE::ImageInput::Creator reader_creator(std::string_view format);

}  // namespace l2::png_codec
