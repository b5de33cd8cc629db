// Errors about the user's input: a file that cannot be read as what it claims to be, or options
// that make no sense. The command line turns both into a one-line message and exit code 2;
// every other exception is an internal failure (exit code 1).
#pragma once

#include <stdexcept>
#include <string>

namespace shapeproc::io {

// A problem in an input file. what() reads "FILE:LINE: MESSAGE", or "FILE: MESSAGE" when the
// line is unknown (line 0).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

// A bad option value or combination, independent of any file's contents.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace shapeproc::io
