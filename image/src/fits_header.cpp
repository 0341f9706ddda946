#include "image/fits_header.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

namespace l2::png_codec {

namespace {

constexpr std::uint64_t kBlock = 2880, kCard = 80;

Failure refused(const std::string& what) {
  return Failure{"cannot read: a FITS file " + what};
}

// A card's keyword: its first 8 bytes, spaces stripped.
std::string_view keyword(std::string_view card) {
  std::string_view k = card.substr(0, 8);
  while (!k.empty() && std::isspace(static_cast<unsigned char>(k.back()))) k.remove_suffix(1);
  while (!k.empty() && std::isspace(static_cast<unsigned char>(k.front()))) k.remove_prefix(1);
  return k;
}

// The integer the reader takes from a card (from its 11th byte: spaces, a sign, decimal digits),
// clamped as it clamps one past an int's range; 0 without digits.
long long card_integer(std::string_view card) {
  std::string_view v = card.substr(10);
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front()))) v.remove_prefix(1);
  const bool negative = !v.empty() && v.front() == '-';
  if (!v.empty() && (v.front() == '-' || v.front() == '+')) v.remove_prefix(1);
  long long value = 0;
  for (const char c : v) {
    if (!std::isdigit(static_cast<unsigned char>(c))) break;
    value = std::min(value * 10 + (c - '0'), 1LL << 32);
  }
  return negative ? -value : value;
}

// A card's value as written, for a refusal: its first word, cut at 24 characters.
std::string value_text(std::string_view card) {
  std::string_view v = card.substr(10);
  while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
  v = v.substr(0, v.find(' '));
  return v.size() > 24 ? std::string(v.substr(0, 24)) + "..." : std::string(v);
}

// One image's header from `offset`: its cards until END.
Status check_image_header(const ReadAt& read, std::uintmax_t file_size, std::uint64_t offset) {
  for (int block = 0; block < kMaxFitsHeaderBlocks; ++block, offset += kBlock) {
    if (offset + kBlock > file_size) return {};  // the reader says the file ends early
    const std::string cards = read(offset, kBlock);
    for (std::uint64_t at = 0; at + kCard <= cards.size(); at += kCard) {
      const std::string_view card = std::string_view(cards).substr(at, kCard);
      if (keyword(card) == "END") return {};
      if (keyword(card) != "NAXIS") continue;
      const long long axes = card_integer(card);
      if (axes < 0 || axes > 999) {
        return refused("declaring NAXIS = " + value_text(card) +
                       " (the number of axes; the format has 0 to 999)");
      }
    }
  }
  return refused("whose header has no END in its first " + std::to_string(kMaxFitsHeaderBlocks) +
                 " blocks of 2880 bytes");
}

}  // namespace

Status check_fits(const ReadAt& read, std::uintmax_t file_size) {
  if (read(0, 6) != "SIMPLE") return {};
  int images = 0;
  for (std::uint64_t offset = 0; offset + kBlock <= file_size; offset += kBlock) {
    const std::string head = read(offset, 20);
    if (head.rfind("SIMPLE", 0) != 0 && head != "XTENSION= 'IMAGE   '") continue;
    if (++images > kMaxFitsImages) {
      return refused("of more than " + std::to_string(kMaxFitsImages) + " images");
    }
    if (const Status s = check_image_header(read, file_size, offset); !s.ok()) return s;
  }
  return {};
}

}  // namespace l2::png_codec
