#include "image/picture_formats.hpp"

#include <algorithm>
#include <cctype>

namespace l2::png_codec {

namespace {

bool starts(std::string_view head, std::string_view magic, std::size_t at = 0) {
  return head.size() >= at + magic.size() && head.substr(at, magic.size()) == magic;
}

}  // namespace

bool read_here(std::string_view format) {
  return std::find(kFormatsReadHere.begin(), kFormatsReadHere.end(), format) !=
         kFormatsReadHere.end();
}

std::string format_by_signature(std::string_view h) {
  using namespace std::string_view_literals;
  // Read here.
  if (starts(h, "\x89PNG"sv)) return "png";
  if (starts(h, "GIF"sv)) return "gif";
  if (starts(h, "BM"sv)) return "bmp";
  if (h.size() >= 2 && h[0] == 'P' && h[1] >= '1' && h[1] <= '6') return "pnm";
  if (starts(h, "PF\n"sv) || starts(h, "Pf\n"sv)) return "pnm";  // PFM, which the PNM reader reads
  if (starts(h, "II*\0"sv) || starts(h, "MM\0*"sv)) return "tiff";
  if (starts(h, "\xff\xd8\xff"sv)) return "jpeg";
  if (starts(h, "DDS "sv)) return "dds";
  if (starts(h, "8BPS"sv)) return "psd";
  if (starts(h, "\x76\x2f\x31\x01"sv)) return "openexr";
  if (starts(h, "RIFF"sv) && starts(h, "WEBP"sv, 8)) return "webp";
  if (starts(h, "#?RADIANCE"sv) || starts(h, "#?RGBE"sv)) return "hdr";
  if (starts(h, "SIMPLE  ="sv)) return "fits";
  if (starts(h, "\x01\xda"sv)) return "sgi";
  // An icon directory: reserved 0, type 1, and at least one image.
  if (starts(h, "\0\0\1\0"sv) && h.size() >= 6 && (h[4] != 0 || h[5] != 0)) return "ico";
  // Not read here: named, so that the refusal says what the file is.
  if (starts(h, "\0\0\0\x0cjP  \r\n\x87\n"sv) || starts(h, "\xff\x4f\xff\x51"sv)) return "jpeg2000";
  if (starts(h, "SDPX"sv) || starts(h, "XPDS"sv)) return "dpx";
  if (starts(h, "\x80\x2a\x5f\xd7"sv) || starts(h, "\xd7\x5f\x2a\x80"sv)) return "cineon";
  if (starts(h, "FORM"sv)) return "iff";
  if (starts(h, "ftyp"sv, 4)) return "heif";
  if (starts(h, "DICM"sv, 128)) return "dicom";
  if (starts(h, "\x53\x80\xf6\x34"sv)) return "softimage";
  return {};
}

std::string format_label(std::string_view format) {
  std::string out(format);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string not_read_here(std::string_view format) {
  std::string list;
  for (const std::string_view f : kFormatsReadHere)
    list += (list.empty() ? "" : ", ") + format_label(f);
  return "cannot read: a " + format_label(format) + " file, not a format read here (" + list + ")";
}

}  // namespace l2::png_codec
