// zcube regress: the standard runs against golden reports, or two report directories against each
// other (repro/regress.hpp); the result as text, JSON or JUnit XML (repro/regress_output.hpp).
#include <iostream>
#include <set>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "repro/provenance.hpp"
#include "repro/regress.hpp"
#include "repro/regress_output.hpp"
#include "repro/table.hpp"
#include "run/batch.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc::cli {

namespace {

struct RegressFlags {
  std::string against, with, write, runs_file, format = "text";
  std::vector<std::string> sets;
  int jobs = default_jobs();
  double rtol = 1e-9, atol = 0;
  CLI::Option *rtol_time = nullptr, *rtol_count = nullptr, *rtol_bytes = nullptr;
  CLI::Option* rtol_given = nullptr;
  RegressTolerance tolerance{};
  bool allow_schema = false;

  void add_to(CLI::App& app);
  // --rtol for every class, except counts, exact unless --rtol or --rtol-count is given.
  RegressTolerance resolve_tolerance() const;
};

void RegressFlags::add_to(CLI::App& app) {
  app.add_option("--against", against, "directory of reduced reports to compare with");
  app.add_option("--with", with,
                 "compare --against with this directory instead of running (two versions or two "
                 "platform files, each written by --write)");
  app.add_option("--write", write, "write the reduced reports of this run to a directory");
  app.add_option("--runs", runs_file, "runs file")->capture_default_str();
  app.add_option("--set", sets, "override a flag in every run: flag=value (e.g. latency=10us)");
  app.add_option("--jobs", jobs, "runs at once")->check(CLI::Range(1, 4096))->capture_default_str();
  const auto range = CLI::Range(0.0, 1.0);
  rtol_given = app.add_option("--rtol", rtol,
                              "numbers within this relative difference are equal (0: bit for "
                              "bit); the default of the three classes below")
                   ->check(range)
                   ->capture_default_str();
  rtol_time = app.add_option("--rtol-time", tolerance.rtol_time,
                             "relative tolerance of times (phases, *_s, load imbalance)")
                  ->check(range);
  rtol_count = app.add_option("--rtol-count", tolerance.rtol_count,
                              "relative tolerance of counts (messages, counters; default 0, or "
                              "--rtol when given: counts must be exact)")
                   ->check(range);
  rtol_bytes = app.add_option("--rtol-bytes", tolerance.rtol_bytes,
                              "relative tolerance of byte counts (*bytes*)")
                   ->check(range);
  app.add_option("--atol", atol,
                 "absolute floor: numbers within it are equal whatever their relative change "
                 "(in the quantity's unit: seconds, bytes)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--format", format, "text (a Markdown table), json or junit (XML) on stdout")
      ->check(CLI::IsMember({"text", "json", "junit"}))
      ->capture_default_str();
  app.add_flag("--allow-schema", allow_schema,
               "compare reports of another schema version (their fields may mean other things)");
}

RegressTolerance RegressFlags::resolve_tolerance() const {
  RegressTolerance t = tolerance;
  if (!rtol_time->count()) t.rtol_time = rtol;
  if (!rtol_bytes->count()) t.rtol_bytes = rtol;
  if (!rtol_count->count()) t.rtol_count = rtol_given->count() ? rtol : 0;
  t.atol = atol;
  return t;
}

std::map<std::string, std::string> parse_sets(const std::vector<std::string>& sets) {
  std::map<std::string, std::string> set;
  for (const auto& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set '" + s + "': expected flag=value");
    set[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return set;
}

std::vector<std::string> run_names(const std::map<std::string, nlohmann::json>& a,
                                   const std::map<std::string, nlohmann::json>& b) {
  std::set<std::string> names;
  for (const auto* side : {&a, &b})
    for (const auto& [name, r] : *side)
      names.insert(name);
  return {names.begin(), names.end()};
}

// Prints the outcome in the format asked; the exit status.
int report_outcome(const RegressOutcome& o, const std::string& format) {
  if (format == "json") {
    std::cout << regress_json(o).dump(1) << "\n";
  } else if (format == "junit") {
    std::cout << regress_junit(o);
  } else {
    std::cout << regress_sides_text(o) << regress_text(o);
  }
  return o.identical() ? 0 : 1;
}

int cmd_regress(std::vector<std::string> args) {
  CLI::App app{"Compare the simulated timings and images of the standard runs with golden reports",
               "zcube regress"};
  const std::string root = source_root();
  RegressFlags f;
  f.runs_file = root + "/tests/golden/runs.json";
  f.add_to(app);
  BatchSimGridFlags simgrid;
  simgrid.add_to(app);
  if (int rc = parse(app, args); rc >= 0) return rc;
  simgrid.apply();
  f.against = data_file(f.against); // tests/golden: the golden runs installed with the binary
  if (f.against.empty() && f.write.empty())
    throw UsageError("regress: give --against DIR (compare) and/or --write DIR (record)");
  if (!f.with.empty() && f.against.empty()) throw UsageError("regress: --with needs --against");
  // Text for people goes to stderr when stdout is a document for a machine.
  std::ostream& say = f.format == "text" ? std::cout : std::cerr;

  // Every input read and checked, and every output checked, before any run (16 simulations).
  RegressOutcome o;
  o.tolerance = f.resolve_tolerance();
  const auto runs = f.with.empty() ? read_regress_runs(f.runs_file) : std::vector<RegressRun>{};
  const auto before =
      f.against.empty() ? std::map<std::string, nlohmann::json>{} : read_report_dir(f.against);
  o.before = {f.against, check_report_schema(before, "--against", f.against, f.allow_schema)};
  if (!f.write.empty()) prepare_output_dir(f.write, "--write");
  std::map<std::string, nlohmann::json> now;
  if (!f.with.empty()) {
    now = read_report_dir(f.with);
    o.after = {f.with, check_report_schema(now, "--with", f.with, f.allow_schema)};
  } else {
    now = run_regress(runs, root, f.jobs, parse_sets(f.sets));
    o.after = {"now", provenance()};
  }
  if (!f.write.empty()) {
    write_report_dir(now, f.write);
    say << "regress: wrote " << now.size() << " reports to " << f.write << "/\n";
  }
  // A run that failed is never a success, even when the golden report failed the same way.
  for (const auto& [name, r] : now)
    if (r.value("status", "error") == "error") o.failed[name] = r.value("error", "?");
  for (const auto& [name, why] : o.failed)
    std::cerr << "regress: run " << name << ": " << why << "\n";
  if (f.against.empty()) return o.failed.empty() ? 0 : 1;
  o.runs = run_names(before, now);
  o.diffs = compare_reduced(before, now, o.tolerance);
  return report_outcome(o, f.format);
}

} // namespace

ZC_COMMAND("regress", "compare simulated timings and images with golden reports", cmd_regress);

} // namespace zc::cli
