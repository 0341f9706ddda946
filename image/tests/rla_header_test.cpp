// An RLA file's header against what its reader trusts (rla_header.hpp): headers built here
// field by field (big-endian), each expectation written from the fields set.
#include "image/rla_header.hpp"

#include <gtest/gtest.h>

#include <string>

namespace l2::png_codec {
namespace {

void put16(std::string& h, std::size_t at, int v) {
  h[at] = static_cast<char>((v >> 8) & 0xFF);
  h[at + 1] = static_cast<char>(v & 0xFF);
}

// A header of 3 colour channels of 8 bits in bytes, no matte or auxiliary channels.
std::string rla_header() {
  std::string h(kRlaHeaderBytes, '\0');
  put16(h, 20, 3);   // colour channels
  put16(h, 658, 8);  // their bits
  return h;
}

TEST(RlaHeader, ChannelsOfBitsTheirTypesHoldPass) {
  std::string h = rla_header();
  EXPECT_TRUE(check_rla(h).ok());
  put16(h, 658, 0);  // colour bits 0: the reader takes 8
  EXPECT_TRUE(check_rla(h).ok());
  put16(h, 18, 1);  // words of 16 bits
  put16(h, 658, 16);
  EXPECT_TRUE(check_rla(h).ok());
  put16(h, 24, 1);  // one auxiliary channel of 32 bits in a float
  put16(h, 664, 4);
  put16(h, 666, 32);
  EXPECT_TRUE(check_rla(h).ok());
}

TEST(RlaHeader, AClassWithoutChannelsIsNotChecked) {
  std::string h = rla_header();
  put16(h, 660, 1);  // matte: words of 0 bits, but no channels
  put16(h, 666, 20);
  put16(h, 664, 1);  // auxiliary: words of 20 bits, but no channels
  EXPECT_TRUE(check_rla(h).ok());
}

TEST(RlaHeader, MatteOrAuxiliaryChannelsOfNoBitsAreRefused) {
  std::string h = rla_header();
  put16(h, 24, 1);  // one auxiliary channel, 0 bits
  EXPECT_EQ(check_rla(h).reason(),
            "cannot read: an RLA file declaring 1 auxiliary channel(s) of 0 bits");
  h = rla_header();
  put16(h, 22, 2);    // two matte channels
  put16(h, 662, -3);  // of -3 bits
  EXPECT_EQ(check_rla(h).reason(),
            "cannot read: an RLA file declaring 2 matte channel(s) of -3 bits");
}

TEST(RlaHeader, WordsOfMoreThanSixteenBitsAreRefused) {
  std::string h = rla_header();
  put16(h, 18, 1);  // colour in words
  put16(h, 658, 17);
  EXPECT_EQ(check_rla(h).reason(),
            "cannot read: an RLA file declaring 3 colour channel(s) of 17 bits in 16-bit words");
  put16(h, 18, 2);  // the same bits in dwords hold
  EXPECT_TRUE(check_rla(h).ok());
}

TEST(RlaHeader, TypeThreeIsRefused) {
  std::string h = rla_header();
  put16(h, 18, 3);  // colour of type 3: between dword (2) and float (4)
  EXPECT_EQ(check_rla(h).reason(),
            "cannot read: an RLA file declaring 3 colour channel(s) of 8 bits of type 3 (the "
            "format's are 0, 1, 2 and 4)");
  put16(h, 20, 0);  // the reader takes the colour class's type even without channels
  EXPECT_FALSE(check_rla(h).ok());
  h = rla_header();
  put16(h, 664, 3);  // auxiliary of type 3, but no auxiliary channels
  EXPECT_TRUE(check_rla(h).ok());
  put16(h, 24, 1);
  put16(h, 666, 8);
  EXPECT_EQ(check_rla(h).reason(),
            "cannot read: an RLA file declaring 1 auxiliary channel(s) of 8 bits of type 3 (the "
            "format's are 0, 1, 2 and 4)");
  put16(h, 664, 4);  // float
  EXPECT_TRUE(check_rla(h).ok());
}

TEST(RlaHeader, AFileOfMoreThanOneImageIsRefused) {
  std::string h = rla_header();
  put16(h, 736, 0xFFFF);  // NextOffset -1
  put16(h, 738, 0xFFFF);
  EXPECT_EQ(check_rla(h).reason(),
            "cannot read: an RLA file declaring a next image at byte -1; RLA files of one image "
            "are read here");
  put16(h, 736, 0);
  put16(h, 738, 1000);
  EXPECT_FALSE(check_rla(h).ok());
}

TEST(RlaHeader, AHeaderCutShortIsTheReadersToRefuse) {
  std::string h = rla_header();
  put16(h, 24, 1);  // refused whole...
  EXPECT_FALSE(check_rla(h).ok());
  EXPECT_TRUE(check_rla(h.substr(0, kRlaHeaderBytes - 1)).ok());  // ...but not cut short
}

}  // namespace
}  // namespace l2::png_codec
