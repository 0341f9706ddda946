// Reading MPCDI's mpcdi.xml with the path and line of every value, so that a refusal is one line
// naming the file, the line and the field: "cal.mpcdi: mpcdi.xml:7:
// display.buffer[0].region[1].xResolution: expected a whole number 1..4095, got \"0\"". Owns the
// XML parse (tinyxml2: no DTDs or external entities are expanded, elements nest at most 100
// deep) and the words of refusal; what the elements mean is import_mpcdi.cpp's.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tinyxml2 {
class XMLDocument;
class XMLElement;
}  // namespace tinyxml2

namespace l2 {

// The name of the XML file inside the MPCDI archive, as the standard names it.
inline constexpr std::string_view kMpcdiXmlName = "mpcdi.xml";

// An element of mpcdi.xml and where it is ("display.buffer[0].region[1]"). `file` names the
// MPCDI file in every message.
class XmlAt {
 public:
  XmlAt(const tinyxml2::XMLElement* element, std::string path, const std::string& file)
      : element_(element), path_(std::move(path)), file_(&file) {}

  bool present() const { return element_ != nullptr; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  int line() const;

  // The first child element named `name`, or an absent one.
  XmlAt child(std::string_view name) const;
  // Every child element named `name`, in file order, indexed in their paths ("region[1]").
  std::vector<XmlAt> children(std::string_view name) const;
  // Every child element's name, in file order.
  std::vector<std::string> child_names() const;

  // An attribute; its name is matched without regard to case, since files differ
  // ("xResolution", older drafts' "Xresolution").
  std::optional<std::string> attribute(std::string_view name) const;
  // The text of the element, spaces around it dropped; empty when it has none.
  std::string text() const;

  // An attribute that must be there: a whole number lo..hi, or a number.
  int integer_attribute(std::string_view name, int lo, int hi) const;
  double number_attribute(std::string_view name, double lo, double hi) const;
  // A child element's text that must be there.
  std::string child_text(std::string_view name) const;
  // A child element's text as a number lo..hi, or `absent` when there is no such child.
  double child_number_or(std::string_view name, double lo, double hi, double absent) const;

  // Throws LayoutError "FILE: mpcdi.xml:LINE: PATH.FIELD: WHAT" (PATH alone when `field` is
  // empty, no line when the element is absent).
  [[noreturn]] void fail(std::string_view field, std::string_view what) const;

 private:
  const tinyxml2::XMLElement* element_;
  std::string path_;
  const std::string* file_;
};

// Parses mpcdi.xml into `doc`. Throws LayoutError "FILE: mpcdi.xml:LINE: not well-formed XML:
// ..." with tinyxml2's reason.
void parse_mpcdi_xml(tinyxml2::XMLDocument& doc, std::string_view text, const std::string& file);

// A value as it appears in a message: quoted, cut short, in plain ASCII.
std::string quoted_value(std::string_view value);

}  // namespace l2
