// JSON values with their paths, and the one-line refusals of import_json.hpp.
#include "import_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "tilelayout/tile_layout.hpp"

namespace l2 {
namespace {

// What is there, short and on one line: a string quoted (cut when long), a number as written.
std::string describe(const Json* v) {
  if (v == nullptr) return "nothing (the field is missing)";
  switch (v->type()) {
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::null:
      return "null";
    default:
      break;
  }
  std::string text = v->dump(-1, ' ', false, Json::error_handler_t::replace);
  constexpr std::size_t kLongest = 40;
  if (text.size() > kLongest) text = text.substr(0, kLongest) + "...";
  return text;
}

}  // namespace

Json parse_json(std::string_view text, const std::string& file) {
  try {
    return Json::parse(text.begin(), text.end(), nullptr, true, true);
  } catch (const Json::exception& e) {
    // A syntax error, or a number past a double's range (out_of_range, found by the fuzzer).
    // nlohmann's words start with its own code ("[json.exception.parse_error.101] ").
    std::string what = e.what();
    if (const auto end = what.find("] "); what.rfind("[json.", 0) == 0 && end != std::string::npos)
      what = what.substr(end + 2);
    std::replace_if(
        what.begin(), what.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    throw LayoutError(fmt::format("{}: not valid JSON: {}", file, what));
  }
}

JsonAt JsonAt::operator[](std::string_view key) const {
  const std::string path = path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
  if (!is_object()) return {nullptr, path, *file_};
  const auto it = value_->find(key);
  return {it == value_->end() ? nullptr : &*it, path, *file_};
}

JsonAt JsonAt::operator[](std::size_t index) const {
  const std::string path = fmt::format("{}[{}]", path_, index);
  if (!value_ || !value_->is_array() || index >= value_->size()) return {nullptr, path, *file_};
  return {&(*value_)[index], path, *file_};
}

void JsonAt::fail(std::string_view what) const {
  throw LayoutError(fmt::format("{}: {}: {}", *file_, path_, what));
}

void JsonAt::expected(std::string_view what) const {
  fail(fmt::format("expected {}, got {}", what, describe(value_)));
}

const Json& JsonAt::object() const {
  if (!is_object()) expected("an object");
  return *value_;
}

std::size_t JsonAt::array_size() const {
  if (!value_ || !value_->is_array()) expected("an array");
  return value_->size();
}

long long JsonAt::integer(long long lo, long long hi) const {
  const std::string want = fmt::format("an integer {}..{}", lo, hi);
  if (!value_ || !value_->is_number_integer()) expected(want);
  long long v = 0;
  if (value_->is_number_unsigned()) {
    const auto u = value_->get<unsigned long long>();
    v = u > static_cast<unsigned long long>(std::numeric_limits<long long>::max())
            ? std::numeric_limits<long long>::max()
            : static_cast<long long>(u);
  } else {
    v = value_->get<long long>();
  }
  if (v < lo || v > hi) expected(want);
  return v;
}

long long JsonAt::integer_or(long long lo, long long hi, long long absent) const {
  return present() ? integer(lo, hi) : absent;
}

int JsonAt::positive(int hi) const {
  if (!value_ || !value_->is_number_integer()) expected("a positive integer");
  const long long v = value_->is_number_unsigned()
                          ? static_cast<long long>(std::min<unsigned long long>(
                                value_->get<unsigned long long>(), 1ULL << 62))
                          : value_->get<long long>();
  if (v < 1) expected("a positive integer");
  if (v > hi) expected(fmt::format("a positive integer up to {}", hi));
  return static_cast<int>(v);
}

double JsonAt::number() const {
  if (!value_ || !value_->is_number()) expected("a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) expected("a finite number");
  return v;
}

double JsonAt::number_or(double absent) const {
  return present() ? number() : absent;
}

std::string JsonAt::string() const {
  if (!value_ || !value_->is_string()) expected("a string");
  return value_->get<std::string>();
}

std::string JsonAt::string_or(std::string absent) const {
  return present() ? string() : absent;
}

bool JsonAt::boolean_or(bool absent) const {
  if (!present()) return absent;
  if (!value_->is_boolean()) expected("true or false");
  return value_->get<bool>();
}

}  // namespace l2
