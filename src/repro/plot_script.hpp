#pragma once
// Drawing plots with scripts/plot_results.py (python3-matplotlib) from the CSV files zcube wrote.
#include <string>
#include <vector>

namespace zc {

// Runs `python3 <root>/scripts/plot_results.py args...` with Debian's interpreter where there is
// one (the python3-matplotlib scripts/setup.sh installs is its module; a python3 earlier on
// PATH, e.g. pyenv's, may lack it). True when the script succeeded.
bool run_plot_script(const std::string& root, const std::vector<std::string>& args);
// The same for another script of the tree (`script` relative to root, e.g. scripts/plot_gantt.py).
bool run_python_script(const std::string& root, const std::string& script,
                       const std::vector<std::string>& args);

} // namespace zc
