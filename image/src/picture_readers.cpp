#include "picture_readers.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "image/picture_formats.hpp"
#include "image/rla_header.hpp"
#include "media_oiio.hpp"

namespace l2::png_codec {

namespace {

namespace OIIO = OIIO_NAMESPACE;

// Once a process, before any reader is made: OpenImageIO may then try no reader but the one
// asked for (its image cache makes its own readers by a file's name too).
void only_readers_asked_for() {
  static const bool off = OIIO::attribute("try_all_readers", 0);
  (void)off;
}

// A file's first bytes, as many as format_by_signature and check_chosen look at.
std::string first_bytes(const char* path) {
  std::string head(kRlaHeaderBytes, '\0');
  std::FILE* file = std::fopen(path, "rb");
  if (!file) return {};
  head.resize(std::fread(head.data(), 1, head.size(), file));
  std::fclose(file);
  return head;
}

template <std::size_t I>
OIIO::ImageInput* create_read_here() {
  return make_reader(kFormatsReadHere[I]).release();
}

template <std::size_t... I>
constexpr std::array<OIIO::ImageInput::Creator, sizeof...(I)> creators(std::index_sequence<I...>) {
  return {&create_read_here<I>...};
}

constexpr auto kCreators = creators(std::make_index_sequence<kFormatsReadHere.size()>());

}  // namespace

std::unique_ptr<OIIO::ImageInput> make_reader(std::string_view format) {
  only_readers_asked_for();
  if (!read_here(format)) return nullptr;
  return OIIO::ImageInput::create(std::string(format));
}

Result<ReaderChoice> choose_reader(std::string_view head, const std::string& name) {
  only_readers_asked_for();
  ReaderChoice choice{format_by_signature(head), true};
  if (choice.format.empty() && !name.empty()) {
    // The reader OpenImageIO names for the extension, made (not opened) only to learn its name:
    // by the extension alone, as a file's name would have the reader judge the file.
    const std::string extension = std::filesystem::path(name).extension().string();
    const auto reader = OIIO::ImageInput::create(extension.empty() ? name : extension.substr(1));
    OIIO::geterror();  // cleared: our wording replaces OpenImageIO's
    if (reader) choice = {reader->format_name(), false};
  }
  if (choice.format.empty()) return Failure{"cannot read: not a picture of a format known here"};
  if (!read_here(choice.format)) return Failure{not_read_here(choice.format)};
  return choice;
}

Status check_chosen(const ReaderChoice& choice, std::string_view head) {
  return choice.format == "rla" ? check_rla(head) : Status{};
}

Result<std::unique_ptr<OIIO::ImageInput>> open_reader(const char* path,
                                                      const OIIO::ImageSpec* config) {
  const std::string head = first_bytes(path);
  const Result<ReaderChoice> choice = choose_reader(head, path);
  if (!choice.ok()) return Failure{choice.reason()};
  if (const Status s = check_chosen(*choice, head); !s.ok()) return Failure{s.reason()};
  auto reader = make_reader(choice->format);
  if (!reader) {  // read here, but this OpenImageIO was built without the format's reader
    OIIO::geterror();
    return Failure{"cannot read: a " + format_label(choice->format) +
                   " file, and OpenImageIO here has no reader of it"};
  }
  OIIO::ImageSpec spec;
  const bool opened = config ? reader->open(path, spec, *config) : reader->open(path, spec);
  if (opened) return reader;
  std::string why = one_line(reader->geterror());
  OIIO::geterror();
  if (!choice->by_signature)
    return Failure{"cannot read: " + (why.empty() ? "not a picture" : why)};
  if (why.empty()) why = "damaged or ends early";
  return Failure{"cannot read: a " + format_label(choice->format) + " file: " + why};
}

OIIO::ImageInput::Creator reader_creator(std::string_view format) {
  const auto at = std::find(kFormatsReadHere.begin(), kFormatsReadHere.end(), format);
  return at == kFormatsReadHere.end() ? nullptr : kCreators[at - kFormatsReadHere.begin()];
}

}  // namespace l2::png_codec
