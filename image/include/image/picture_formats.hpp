// Which picture formats are read here, and which one a file's first bytes say it is in. Only
// formats whose headers the checks of declared_size.hpp, tiff_header.hpp and exr_header.hpp bound
// are opened: OpenImageIO, asked to open a file its name's reader cannot, tries every reader it
// has, and some of those trust any header (a 177-byte JPEG 2000 file named .tga had OpenJPEG
// take 1.1 GB; one declaring 1000000x1000000 pixels hung the process). Pure: bytes in, names out.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace l2::png_codec {

// OpenImageIO's names of the formats read here.
inline constexpr std::array<std::string_view, 16> kFormatsReadHere = {
    "bmp", "dds", "fits", "gif", "hdr", "ico",   "jpeg", "openexr",
    "png", "pnm", "psd",  "rla", "sgi", "targa", "tiff", "webp"};

bool read_here(std::string_view format);

// OpenImageIO's name of the format whose signature begins `head` (a file's first bytes, 132 of
// them to see a DICOM's), read here or not ("jpeg2000", "dpx"); empty for a format without one
// (Targa, RLA) or bytes no format begins with.
std::string format_by_signature(std::string_view head);

// A format's name as messages write it: OpenImageIO's in capitals ("JPEG2000").
std::string format_label(std::string_view format);

// The one-line refusal of a file of a format not read here: "cannot read: a JPEG2000 file, not a
// format read here (BMP, DDS, ...)".
std::string not_read_here(std::string_view format);

}  // namespace l2::png_codec
