// Reading an imported configuration's JSON with the path of every value, so that a refusal is
// one line naming the file and the field: "config.json: surfaces[0].screenCountX: expected a
// positive integer, got \"two\"". Owns only the reading and the words of refusal; what the
// fields mean is each format's importer's.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace l2 {

// Objects keep the file's order: displays and hosts are numbered as the file lists them.
using Json = nlohmann::ordered_json;

// Parses JSON text (comments allowed: SAGE2's files have them). Throws LayoutError
// "FILE: not valid JSON: ... at line L, column C: ...".
Json parse_json(std::string_view text, const std::string& file);

// A value of the document, or where one is missing, with its path ("surfaces[0].bezelWidth").
class JsonAt {
 public:
  JsonAt(const Json* value, std::string path, const std::string& file)
      : value_(value), path_(std::move(path)), file_(&file) {}

  bool present() const { return value_ != nullptr && !value_->is_null(); }
  const Json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  bool is_object() const { return value_ && value_->is_object(); }
  const std::string& file() const { return *file_; }

  // A member (absent when this is not an object or has no such key) or an element.
  JsonAt operator[](std::string_view key) const;
  JsonAt operator[](std::size_t index) const;

  // The value as a type, or a refusal naming what was expected and what is there.
  const Json& object() const;
  std::size_t array_size() const;  // the value must be an array
  long long integer(long long lo, long long hi) const;
  long long integer_or(long long lo, long long hi, long long absent) const;
  // A count or size: 1..hi ("expected a positive integer").
  int positive(int hi) const;
  double number() const;
  double number_or(double absent) const;
  std::string string() const;
  std::string string_or(std::string absent) const;
  bool boolean_or(bool absent) const;

  // Throws LayoutError "FILE: PATH: WHAT".
  [[noreturn]] void fail(std::string_view what) const;
  // "expected WHAT, got <the value>".
  [[noreturn]] void expected(std::string_view what) const;

 private:
  const Json* value_;
  std::string path_;
  const std::string* file_;
};

}  // namespace l2
