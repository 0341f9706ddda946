// XmlAt: mpcdi.xml's elements read with their paths and lines, every value checked as it is
// read, a refusal one line naming the file, the line and the field.
#include "mpcdi_xml.hpp"

#include <fmt/format.h>
#include <tinyxml2.h>

#include <strings.h>
#include <cctype>
#include <charconv>
#include <cmath>

#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

constexpr std::size_t kMaxQuoted = 40;  // a value longer than this is cut in messages

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::optional<double> parse_number(std::string_view s) {
  s = trimmed(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || error != std::errc() || end != s.data() + s.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

}  // namespace

std::string quoted_value(std::string_view value) {
  std::string out = "\"";
  for (std::size_t i = 0; i < value.size() && i < kMaxQuoted; ++i) {
    const auto u = static_cast<unsigned char>(value[i]);
    out += u >= 0x20 && u < 0x7f ? value[i] : '?';
  }
  return out + (value.size() > kMaxQuoted ? "...\"" : "\"");
}

int XmlAt::line() const {
  return element_ ? element_->GetLineNum() : 0;
}

XmlAt XmlAt::child(std::string_view name) const {
  const std::string n(name);
  const tinyxml2::XMLElement* e = element_ ? element_->FirstChildElement(n.c_str()) : nullptr;
  return {e, path_.empty() ? n : path_ + "." + n, *file_};
}

std::vector<XmlAt> XmlAt::children(std::string_view name) const {
  std::vector<XmlAt> out;
  if (!element_) return out;
  const std::string n(name);
  for (const tinyxml2::XMLElement* e = element_->FirstChildElement(n.c_str()); e;
       e = e->NextSiblingElement(n.c_str())) {
    const std::string indexed = fmt::format("{}[{}]", n, out.size());
    out.emplace_back(e, path_.empty() ? indexed : path_ + "." + indexed, *file_);
  }
  return out;
}

std::vector<std::string> XmlAt::child_names() const {
  std::vector<std::string> out;
  if (!element_) return out;
  for (const tinyxml2::XMLElement* e = element_->FirstChildElement(); e;
       e = e->NextSiblingElement())
    out.emplace_back(e->Name());
  return out;
}

std::optional<std::string> XmlAt::attribute(std::string_view name) const {
  if (!element_) return std::nullopt;
  const std::string n(name);
  for (const tinyxml2::XMLAttribute* a = element_->FirstAttribute(); a; a = a->Next()) {
    if (strcasecmp(a->Name(), n.c_str()) == 0) return std::string(a->Value());
  }
  return std::nullopt;
}

std::string XmlAt::text() const {
  const char* t = element_ ? element_->GetText() : nullptr;
  return t ? std::string(trimmed(t)) : std::string();
}

int XmlAt::integer_attribute(std::string_view name, int lo, int hi) const {
  const std::optional<std::string> value = attribute(name);
  const std::string what = fmt::format("expected a whole number {}..{}", lo, hi);
  if (!value) fail(name, what + ", got nothing (the attribute is missing)");
  const std::optional<double> v = parse_number(*value);
  if (!v || *v != std::floor(*v) || *v < lo || *v > hi)
    fail(name, fmt::format("{}, got {}", what, quoted_value(*value)));
  return static_cast<int>(*v);
}

double XmlAt::number_attribute(std::string_view name, double lo, double hi) const {
  const std::optional<std::string> value = attribute(name);
  const std::string what = fmt::format("expected a number {}..{}", lo, hi);
  if (!value) fail(name, what + ", got nothing (the attribute is missing)");
  const std::optional<double> v = parse_number(*value);
  if (!v || *v < lo || *v > hi) fail(name, fmt::format("{}, got {}", what, quoted_value(*value)));
  return *v;
}

std::string XmlAt::child_text(std::string_view name) const {
  const XmlAt c = child(name);
  if (!c.present()) fail(name, "missing");
  std::string t = c.text();
  if (t.empty()) c.fail("", "empty");
  return t;
}

double XmlAt::child_number_or(std::string_view name, double lo, double hi, double absent) const {
  const XmlAt c = child(name);
  if (!c.present()) return absent;
  const std::string t = c.text();
  const std::optional<double> v = parse_number(t);
  if (!v || *v < lo || *v > hi)
    c.fail("", fmt::format("expected a number {}..{}, got {}", lo, hi, quoted_value(t)));
  return *v;
}

void XmlAt::fail(std::string_view field, std::string_view what) const {
  std::string where = path_;
  if (!field.empty()) where += (where.empty() ? "" : ".") + std::string(field);
  const std::string at =
      element_ ? fmt::format("{}:{}", kMpcdiXmlName, line()) : std::string(kMpcdiXmlName);
  throw LayoutError(fmt::format("{}: {}: {}: {}", *file_, at, where, what));
}

void parse_mpcdi_xml(tinyxml2::XMLDocument& doc, std::string_view text, const std::string& file) {
  if (doc.Parse(text.data(), text.size()) == tinyxml2::XML_SUCCESS) return;
  // ErrorStr() repeats the line and adds tinyxml2's own wording; the reason's name is enough.
  std::string reason = tinyxml2::XMLDocument::ErrorIDToName(doc.ErrorID());
  for (const std::string_view prefix : {"XML_ERROR_", "XML_"}) {
    if (reason.rfind(prefix, 0) == 0) {
      reason = reason.substr(prefix.size());
      break;
    }
  }
  for (char& c : reason) c = c == '_' ? ' ' : static_cast<char>(std::tolower(c));
  throw LayoutError(fmt::format("{}: {}:{}: not well-formed XML: {}", file, kMpcdiXmlName,
                                doc.ErrorLineNum(), reason));
}

}  // namespace l2
