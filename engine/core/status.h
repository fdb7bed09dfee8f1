// Status and Result<T>: errors as values that name the culprit.
//
// Contract: every fallible engine call returns Status or Result<T>. A message
// names what was wrong and what was expected, e.g.
//   "ALT KL204 FL9X: altitude 'FL9X' is not a flight level or feet".
// No engine function throws across a public API; Lua bindings turn a failed
// Status into a Lua error.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace squawk {

enum class Code {
  kOk = 0,
  kInvalidArgument,  // caller gave a value of the wrong form or range
  kNotFound,         // a named thing (aircraft, file, waypoint) does not exist
  kIOError,          // file or stream failure
  kCorruption,       // a file's content contradicts its own format
  kUnavailable,      // a server or resource could not be reached
  kTimeout,          // a deadline passed
  kUnsupported,      // recognised but not implemented here
  kInternal,         // an invariant broke: a bug in squawk
};

const char* code_name(Code c);

class [[nodiscard]] Status {
 public:
  Status() = default;  // ok
  static Status ok() { return {}; }
  static Status error(Code code, std::string msg) { return Status(code, std::move(msg)); }
  static Status invalid(std::string msg) { return {Code::kInvalidArgument, std::move(msg)}; }
  static Status not_found(std::string msg) { return {Code::kNotFound, std::move(msg)}; }
  static Status io_error(std::string msg) { return {Code::kIOError, std::move(msg)}; }
  static Status corruption(std::string msg) { return {Code::kCorruption, std::move(msg)}; }
  static Status unavailable(std::string msg) { return {Code::kUnavailable, std::move(msg)}; }
  static Status timeout(std::string msg) { return {Code::kTimeout, std::move(msg)}; }
  static Status unsupported(std::string msg) { return {Code::kUnsupported, std::move(msg)}; }
  static Status internal(std::string msg) { return {Code::kInternal, std::move(msg)}; }

  bool is_ok() const { return code_ == Code::kOk; }
  explicit operator bool() const { return is_ok(); }
  Code code() const { return code_; }
  const std::string& message() const { return msg_; }

  // Returns a copy whose message is "context: message"; ok stays ok.
  Status with_context(const std::string& context) const;

 private:
  Status(Code code, std::string msg) : code_(code), msg_(std::move(msg)) {}
  Code code_ = Code::kOk;
  std::string msg_;
};

// Result<T>: a T or a non-ok Status.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  Result(Status status) : status_(std::move(status)) {  // NOLINT
    if (status_.is_ok()) status_ = Status::internal("Result built from an ok Status without a value");
  }

  bool is_ok() const { return value_.has_value(); }
  explicit operator bool() const { return is_ok(); }
  const Status& status() const { return status_; }
  const T& value() const& { return *value_; }
  T& value() & { return *value_; }
  T&& value() && { return std::move(*value_); }
  const T& operator*() const& { return *value_; }
  T& operator*() & { return *value_; }
  const T* operator->() const { return &*value_; }
  T* operator->() { return &*value_; }
  T value_or(T fallback) const { return value_ ? *value_ : std::move(fallback); }

 private:
  std::optional<T> value_;
  Status status_;
};

}  // namespace squawk

// Propagate a failed Status from an expression returning Status.
#define SQUAWK_RETURN_IF_ERROR(expr)            \
  do {                                          \
    ::squawk::Status _st = (expr);              \
    if (!_st.is_ok()) return _st;               \
  } while (0)

#define SQUAWK_CONCAT_INNER(a, b) a##b
#define SQUAWK_CONCAT(a, b) SQUAWK_CONCAT_INNER(a, b)
// Bind the value of a Result expression to `lhs`, or return its Status.
#define SQUAWK_ASSIGN_OR_RETURN(lhs, expr)                                   \
  auto SQUAWK_CONCAT(_res_, __LINE__) = (expr);                              \
  if (!SQUAWK_CONCAT(_res_, __LINE__).is_ok())                               \
    return SQUAWK_CONCAT(_res_, __LINE__).status();                          \
  lhs = std::move(SQUAWK_CONCAT(_res_, __LINE__)).value()
