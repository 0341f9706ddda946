// A FITS file's image headers against what OpenImageIO's reader trusts (fits_header.hpp): files
// built here card by card, each expectation written from the cards set.
#include "image/fits_header.hpp"

#include <gtest/gtest.h>

#include <string>

namespace l2::png_codec {
namespace {

std::string card(const std::string& key, const std::string& value) {
  std::string c = key;
  c.resize(8, ' ');
  c += "= " + std::string(value.size() < 20 ? 20 - value.size() : 0, ' ') + value;
  c.resize(80, ' ');
  return c;
}

// Header blocks of `cards` then END, and a block of data.
std::string fits(const std::string& cards) {
  std::string h = cards + "END";
  h.resize((h.size() + 2879) / 2880 * 2880, ' ');
  return h + std::string(2880, '\0');
}

std::string image(const std::string& axes) {
  return card("SIMPLE", "T") + card("BITPIX", "8") + card("NAXIS", axes) + card("NAXIS1", "4") +
         card("NAXIS2", "4");
}

Status check_file(const std::string& file) {
  return check_fits(
      [&file](std::uint64_t at, std::size_t n) {
        return at >= file.size() ? std::string() : file.substr(at, n);
      },
      file.size());
}

TEST(FitsHeader, ImagesOfTheFormatsAxesPass) {
  EXPECT_TRUE(check_file(fits(image("2"))).ok());
  EXPECT_TRUE(check_file(fits(image("999"))).ok());
  EXPECT_TRUE(check_file("not a FITS file").ok());
}

TEST(FitsHeader, AxesOutsideTheFormatsAreRefused) {
  EXPECT_EQ(check_file(fits(image("1000"))).reason(),
            "cannot read: a FITS file declaring NAXIS = 1000 (the number of axes; the format has "
            "0 to 999)");
  EXPECT_EQ(check_file(fits(image("-1"))).reason(),
            "cannot read: a FITS file declaring NAXIS = -1 (the number of axes; the format has 0 "
            "to 999)");
  // Past an int: the reader clamps it to 2^31-1 and sizes its list of axes by it.
  EXPECT_EQ(check_file(fits(image(std::string(60, '7')))).reason(),
            "cannot read: a FITS file declaring NAXIS = 777777777777777777777777... (the number "
            "of axes; the format has 0 to 999)");
}

TEST(FitsHeader, AnExtensionsAxesAreCheckedToo) {
  std::string extension = card("XTENSION", "'IMAGE   '");
  extension.replace(10, 10, "'IMAGE   '");  // as the reader looks for it: at byte 10
  const std::string file = fits(image("2")) + fits(extension + card("NAXIS", "5000"));
  ASSERT_EQ(file.substr(5760, 20), "XTENSION= 'IMAGE   '");
  EXPECT_EQ(check_file(file).reason(),
            "cannot read: a FITS file declaring NAXIS = 5000 (the number of axes; the format has "
            "0 to 999)");
}

TEST(FitsHeader, AHeaderWithoutAnEndIsRefused) {
  // 64 header blocks without END, then END: past what is read here.
  std::string header = image("2");
  header.resize(64 * 2880, ' ');
  EXPECT_EQ(check_file(fits(header)).reason(),
            "cannot read: a FITS file whose header has no END in its first 64 blocks of 2880 "
            "bytes");
  header.resize(63 * 2880, ' ');
  EXPECT_TRUE(check_file(fits(header)).ok());
}

}  // namespace
}  // namespace l2::png_codec
