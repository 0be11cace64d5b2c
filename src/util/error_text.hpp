#pragma once
// The text of an error message as the user reads it: one line, input echoed at a readable length.
#include <string>

namespace zc {

// Input echoed in a message is cut to a readable length: a run of more than 120 characters without
// a space (a 5,000-digit number, a pasted file) keeps its first 60 and says how long it was.
inline std::string shorten_echo(const std::string& text) {
  constexpr std::size_t kLongest = 120, kKept = 60;
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t space = text.find(' ', at);
    const std::size_t end = space == std::string::npos ? text.size() : space;
    if (end - at > kLongest)
      out.append(text, at, kKept).append("...(" + std::to_string(end - at) + " characters)");
    else
      out.append(text, at, end - at);
    if (end < text.size()) out.push_back(' ');
    at = end + 1;
  }
  return out;
}

// A library's multi-line message (SimGrid's, a parser's) as one line: its lines joined by "; ",
// blank ones and SimGrid's backtrace dropped.
inline std::string one_line(const std::string& text) {
  std::string out;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t nl = text.find('\n', at);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(at, nl - at);
    at = nl + 1;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    line = line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
    if (line.starts_with("->") || line.find("Backtrace") != std::string::npos ||
        line.find("backtrace") != std::string::npos)
      continue;
    out += (out.empty() ? "" : "; ") + line;
  }
  return out;
}

} // namespace zc
