// The project's errors, one message format for all of them:
// - InputError: a file that cannot be read as what it claims to be ("FILE:LINE: MESSAGE");
// - UsageError: options that make no sense together, independent of any file;
// - ArgumentError: a library function called with arguments outside its domain
//   ("FUNCTION: MESSAGE"; see check.hpp);
// - Cancelled: a long run stopped because its caller asked;
// - InternalError: a broken invariant (SHAPEPROC_ASSERT; a bug, never the user's fault).
// The command line turns the first three into a one-line message and exit code 2; an
// InternalError or any other exception is an internal failure (exit code 1).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace shapeproc::core {

// Messages of InputError and UsageError may name an option of the call as {name}: the name of the
// field or parameter that holds it ({window}, {category_by}). what() shows the name itself; a
// caller that knows its users by other names (the command line: flags) shows them with `shown`.
using OptionNamer = std::function<std::string(std::string_view name)>;

// `text` with every {name} (lower case letters and _) replaced by namer(name); other text as it is.
std::string name_options(std::string_view text, const OptionNamer& namer);

// A problem in an input file. what() reads "FILE:LINE: MESSAGE", or "FILE: MESSAGE" when the
// line is unknown (line 0).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  // what(), its options named by `namer`.
  std::string shown(const OptionNamer& namer) const;

 private:
  std::string file_;
  int line_;
  std::string message_;  // with its {name} marks
};

// A bad option value or combination, independent of any file's contents.
class UsageError : public std::runtime_error {
 public:
  explicit UsageError(const std::string& message);
  // what(), its options named by `namer`.
  std::string shown(const OptionNamer& namer) const;

 private:
  std::string message_;  // with its {name} marks
};

// A library function's argument outside its domain. what() reads "FUNCTION: MESSAGE".
class ArgumentError : public std::invalid_argument {
 public:
  ArgumentError(const std::string& function, const std::string& message);
};

// A run stopped at the caller's request (a cancellation flag was set).
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

// A broken internal invariant, thrown by SHAPEPROC_ASSERT. what() reads
// "internal error at FILE:LINE: CONDITION (MESSAGE)".
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace shapeproc::core
