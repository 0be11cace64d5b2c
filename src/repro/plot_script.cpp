#include "repro/plot_script.hpp"

#include <cstdlib>
#include <filesystem>

namespace zc {

namespace {

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q += "'\\''";
    else
      q += c;
  }
  q += '\'';
  return q;
}

} // namespace

bool run_plot_script(const std::string& root, const std::vector<std::string>& args) {
  return run_python_script(root, "scripts/plot_results.py", args);
}

bool run_python_script(const std::string& root, const std::string& script,
                       const std::vector<std::string>& args) {
  std::string cmd = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  (cmd += ' ') += shell_quote(root + "/" + script);
  for (const auto& a : args)
    (cmd += ' ') += shell_quote(a);
  return std::system(cmd.c_str()) == 0;
}

} // namespace zc
