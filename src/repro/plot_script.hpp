#pragma once
// Drawing plots with scripts/plot_results.py (python3-matplotlib) from the CSV files zcube wrote.
#include <string>
#include <vector>

#include "util/child_cost.hpp"

namespace zc {

// The interpreter: $ZCUBE_PYTHON when set, else Debian's /usr/bin/python3 where there is one (the
// python3-matplotlib scripts/setup.sh installs is its module; a python3 earlier on PATH, e.g.
// pyenv's, may lack it), else python3 on PATH.
std::string python_interpreter();

// How a plot script ended. library_missing: it found no matplotlib (exit status
// kPlotLibraryMissing, scripts/plot_figure.py), said so in one line ("matplotlib not found: plots
// not drawn") and drew nothing; the caller skips its plots without a second message. failed: it
// said why on stderr (or could not be started).
enum class PlotOutcome { drawn, failed, library_missing };
inline constexpr int kPlotLibraryMissing = 3;
// The outcome of a script's waitpid status.
PlotOutcome plot_outcome(int wait_status);

// Runs `python3 <root>/scripts/plot_results.py --units <SimGrid's unit tables> args...` (the script
// reads quantities such as "275us" with zcube's tables, machine/units.hpp).
PlotOutcome plot_script_outcome(const std::string& root, const std::vector<std::string>& args);
// The same for another script of the tree (`script` relative to root, e.g. scripts/plot_gantt.py):
// started directly (no shell), its arguments passed as they are.
PlotOutcome python_script_outcome(const std::string& root, const std::string& script,
                                  const std::vector<std::string>& args);
// The two above as "drawn or not".
bool run_plot_script(const std::string& root, const std::vector<std::string>& args);
bool run_python_script(const std::string& root, const std::string& script,
                       const std::vector<std::string>& args);

// scripts/plot_results.py (with --units, as run_plot_script) started in the background, its
// standard input a pipe: it loads matplotlib while the caller goes on, and draws the figures each
// draw() names (the rest of its arguments: a results directory and its parts, Gantt charts) as soon
// as it is given them, several at once (--jobs); wait() ends its input, waits for the figures and
// tells whether they were all drawn, or matplotlib was missing (the destructor waits; without
// draw(), the script is stopped).
class BackgroundPlots {
public:
  explicit BackgroundPlots(const std::string& root);
  ~BackgroundPlots();
  BackgroundPlots(const BackgroundPlots&) = delete;
  BackgroundPlots& operator=(const BackgroundPlots&) = delete;
  void draw(const std::vector<std::string>& args);
  PlotOutcome wait();
  // What the script cost the host, once waited for (its figures' processes included).
  const ChildCost& cost() const { return cost_; }

private:
  void say(const std::string& line);
  ChildCost cost_;
  int pid_ = -1;
  int to_script_ = -1;
  PlotOutcome outcome_ = PlotOutcome::failed; // until waited for
  bool drawing_ = false;
};

} // namespace zc
