// "A value, or the one-line reason there is none": the one shape every part returns where a
// failure is expected input (a bad header, a refused wall, a timeout), so callers test ok()
// and print reason() the same way everywhere. Exceptions stay for what the caller cannot
// handle. Header-only.
//
// Example:
//
//   l2::Result<int> parse_port(std::string_view text) {
//     int port = 0;
//     const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), port);
//     if (ec != std::errc{} || end != text.data() + text.size() || port < 1 || port > 65535)
//       return l2::Failure{fmt::format("'{}' is not a port 1..65535", text)};
//     return port;
//   }
//
//   const l2::Result<int> port = parse_port(argument);
//   if (!port.ok()) {
//     fmt::print(stderr, "--viz-port: {}\n", port.reason());
//     return 2;
//   }
//   listen_on(*port);
//
//   l2::Status ready() { return l2::Failure{"no display connected", ENOTCONN}; }
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace l2 {

inline const std::string& no_reason() {
  static const std::string empty;
  return empty;
}

// What a failed call says: one line, ready to print after the thing it is about.
struct Failure {
  std::string reason;
  int error = 0;  // the errno behind it, where a system call failed and the caller tells them apart
};

// A value of T, or a Failure. No implicit bool on purpose: "if (result)" read as "failed"
// for optional<string> reasons, and as "succeeded" for values.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::in_place_index<0>, std::move(value)) {}  // implicit: `return value;`
  Result(Failure failure)
      : v_(std::in_place_index<1>, std::move(failure)) {}  // and `return Failure{...};`

  bool ok() const { return v_.index() == 0; }
  // Throws std::bad_variant_access when it holds a Failure.
  const T& value() const& { return std::get<0>(v_); }
  T& value() & { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }
  // "" when it holds a value, so a test expecting a reason fails with a readable message.
  const std::string& reason() const { return ok() ? no_reason() : std::get<1>(v_).reason; }
  int error() const { return ok() ? 0 : std::get<1>(v_).error; }

 private:
  std::variant<T, Failure> v_;
};

// Nothing, or a Failure: the result of a check or an action that yields no value.
class [[nodiscard]] Status {
 public:
  Status() = default;                                        // ok
  Status(Failure failure) : failure_(std::move(failure)) {}  // implicit: `return Failure{...};`

  bool ok() const { return !failure_; }
  const std::string& reason() const { return failure_ ? failure_->reason : no_reason(); }
  int error() const { return failure_ ? failure_->error : 0; }

 private:
  std::optional<Failure> failure_;
};

}  // namespace l2
