#pragma once
// One error type for every bad input: it names the file, the line (0 when the whole file is at
// fault) and the reason, and renders as the single line the CLI prints before exiting with
// status 2.
#include <stdexcept>
#include <string>

namespace zc {

class InputError : public std::runtime_error {
public:
  InputError(std::string file, int line, const std::string& reason)
      : std::runtime_error(format(file, line, reason)), file_(std::move(file)), line_(line),
        reason_(reason) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& reason() const { return reason_; }

private:
  static std::string format(const std::string& file, int line, const std::string& reason) {
    std::string s = file.empty() ? std::string("<input>") : file;
    if (line > 0) s.append(":").append(std::to_string(line));
    s.append(": ");
    // A reason quotes the input; bytes of a binary file are shown as \xNN, not echoed.
    static const char* hex = "0123456789abcdef";
    for (unsigned char c : reason)
      if (c < 0x20 || c >= 0x7f)
        s.append("\\x").push_back(hex[c >> 4]), s.push_back(hex[c & 15]);
      else
        s.push_back(char(c));
    return s;
  }
  std::string file_;
  int line_;
  std::string reason_;
};

// A usage error on the command line (bad flag value, impossible node count): also exit status 2.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace zc
