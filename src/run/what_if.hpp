#pragma once
// What-ifs: a machine figure changed for one run (--latency 27.5us, --bandwidth x4, --memory
// x0.5). Each is one descriptor in what_if_specs(): its flag, its quantity and unit, its bounds,
// its report key and how it edits the machine's figures. The command-line flags, the sweep's
// columns, `regress --set`, the help, the reports and the platform writer all read that table;
// adding a what-if is adding one descriptor (and its line in docs/user-guide.md).
//
// A value is absolute (a figure with its unit, in SI once parsed) or relative ("x0.1": a factor of
// the machine's own figure). The difference matters where a machine has more than one figure for
// a flag: the iPSC/860's two message protocols (75 us up to 100 bytes, 136 us above,
// docs/machines.md) become one start-up under `--latency 7.5us` but keep their two ranges, each a
// tenth, under `--latency x0.1`.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "machine/machine.hpp"

namespace zc {

struct WhatIfValue {
  double value = 0;      // SI units (s, B/s, B) when absolute; the factor when relative
  bool relative = false; // a factor of the machine's own figure
  bool operator==(const WhatIfValue&) const = default;
};

// The figures of one machine a what-if may edit: its network, each node's memory, and factors on
// every CPU cost and on every cost (CPU and network).
struct MachineFigures {
  std::string machine; // its name, for errors
  NetworkParams net;
  std::vector<double> memory_bytes; // per node
  double cpu_factor = 1.0;
};

struct WhatIfSpec {
  enum class Quantity { Time, Rate, Bytes, Factor };
  std::string flag;    // without dashes: "latency"
  std::string key;     // the report's and the sweep's SI column: "latency_s"
  Quantity quantity;   // Factor: a plain number (or "x2"), always a factor
  std::string meaning; // "message start-up"
  std::string example; // "275us or x0.1"
  std::string bounds;  // the allowed range and why, for errors and the help
  // Checks the absolute value against the bounds (UsageError naming the flag); what the factor's
  // result must satisfy is checked by `apply`, which knows the machine's figure.
  std::function<void(const WhatIfSpec&, const std::string& text, double si)> check;
  std::function<void(const WhatIfSpec&, const WhatIfValue&, MachineFigures&)> apply;

  // The key of a relative value in reports and sweeps: "latency_factor".
  std::string factor_key() const;
};

// Every what-if, in the order they apply (--cost-scale last: it multiplies what the others set).
const std::vector<WhatIfSpec>& what_if_specs();
const WhatIfSpec* find_what_if(const std::string& flag); // null when none has that flag

// "275us" or "x0.1" (Factor quantities: "0.25" or "x0.25") as the flag's value; UsageError naming
// the flag and the expected form.
WhatIfValue parse_what_if(const WhatIfSpec& spec, const std::string& text);

// The what-ifs of one run, by flag.
class WhatIfs {
public:
  void set(const std::string& flag, WhatIfValue v); // logic_error for a flag with no descriptor
  void reset(const std::string& flag) { values_.erase(flag); }
  std::optional<WhatIfValue> get(const std::string& flag) const;
  bool empty() const { return values_.empty(); }
  // Each value set, in the order of what_if_specs().
  std::vector<std::pair<const WhatIfSpec*, WhatIfValue>> in_order() const;
  // --cpu-scale and --cost-scale as factors (1 when not set).
  double cpu_scale() const { return factor("cpu-scale"); }
  double cost_scale() const { return factor("cost-scale"); }
  bool operator==(const WhatIfs&) const = default;

private:
  double factor(const std::string& flag) const;
  std::map<std::string, WhatIfValue> values_;
};

// Applies every what-if to `figures` in the table's order (UsageError naming the flag when a
// relative value takes a figure out of its bounds, or the machine has no such figure).
void apply_what_ifs(const WhatIfs& w, MachineFigures& figures);

// A machine's figures: its network, `nodes` nodes of its memory, no factors.
MachineFigures machine_figures(const MachineSpec& m, int nodes);

// The report's "what_if" object: {key: value} for absolute values, {factor_key: factor} for
// relative ones.
std::map<std::string, double> what_if_columns(const WhatIfs& w);

// The value as a person reads it: "27.5 us", "x0.1", "4 MB/s", "16 MiB", "0.25".
std::string what_if_text(const WhatIfSpec& spec, const WhatIfValue& v);

// The value as a flag's text that parses back to it: "2.75e-05s", "x0.1", "4000000Bps".
std::string what_if_flag_text(const WhatIfSpec& spec, const WhatIfValue& v);

// A flag's text with `set` applied on top (regress --set): a factor scales the text's own value,
// anything else replaces it. UsageError when either does not parse.
std::string compose_what_if_text(const WhatIfSpec& spec, const std::string& own,
                                 const std::string& set);

// `regress --set flag=x2` on a run that has its own value of the flag: a factor scales the run's
// own value (absolute or relative); an absolute value replaces it.
WhatIfValue compose_what_if(const WhatIfValue& own, const WhatIfValue& set);

} // namespace zc
