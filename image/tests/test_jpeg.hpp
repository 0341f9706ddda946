// JPEGs for tests, made with libjpeg's encoder (not the decoder under test): a frame of two
// known colours, as a shared screen would send.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include <jpeglib.h>

namespace l2::test {

// A JPEG of `w`x`h`, its left half red and right half blue, at quality 90.
inline std::string two_halves(int w, int h) {
  jpeg_compress_struct c{};
  jpeg_error_mgr err{};
  c.err = jpeg_std_error(&err);
  jpeg_create_compress(&c);
  unsigned char* out = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&c, &out, &size);
  c.image_width = static_cast<JDIMENSION>(w);
  c.image_height = static_cast<JDIMENSION>(h);
  c.input_components = 3;
  c.in_color_space = JCS_RGB;
  jpeg_set_defaults(&c);
  jpeg_set_quality(&c, 90, TRUE);
  jpeg_start_compress(&c, TRUE);
  std::string row(static_cast<std::size_t>(w) * 3, '\0');
  for (int x = 0; x < w; ++x) {
    row[static_cast<std::size_t>(x) * 3] = static_cast<char>(x < w / 2 ? 255 : 0);
    row[static_cast<std::size_t>(x) * 3 + 2] = static_cast<char>(x < w / 2 ? 0 : 255);
  }
  while (c.next_scanline < c.image_height) {
    JSAMPROW r = reinterpret_cast<JSAMPROW>(row.data());
    jpeg_write_scanlines(&c, &r, 1);
  }
  jpeg_finish_compress(&c);
  jpeg_destroy_compress(&c);
  std::string bytes(reinterpret_cast<char*>(out), size);
  std::free(out);
  return bytes;
}

}  // namespace l2::test
