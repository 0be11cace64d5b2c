#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "repro/background_job.hpp"
#include "repro/calibrate.hpp"
#include "repro/claims.hpp"
#include "repro/gantt_chart.hpp"
#include "repro/json_file.hpp"
#include "repro/papers.hpp"
#include "repro/plot_script.hpp"
#include "repro/progress.hpp"
#include "repro/provenance.hpp"
#include "repro/table.hpp"
#include "run/batch.hpp"
#include "util/child_cost.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc {

namespace {

// The folder's README: deterministic text only (no host time), so that a second run of the same
// command rewrites the same bytes.
std::string top_readme(const ReproduceOptions& o, std::size_t points,
                       const std::string& fidelity_md, const std::string& kept) {
  return "# zcube results: the papers reproduced on calibrated machine models\n\n"
         "Written by `zcube reproduce" +
         std::string(o.full ? " --full" : "") +
         "` (src/repro/). Every number here is a deterministic output of the simulator: "
         "running the command again writes the same files. The host's wall time of each run "
         "goes to `host_cost.csv` files, which are not committed (they vary from run to run).\n\n"
         "| folder | paper | what |\n|---|---|---|\n"
         "| [calibration/](calibration/README.md) | Kurc Table 2, Charles §6 | the fitted CPU "
         "cost tables and the residual of every target (`zcube calibrate`) |\n"
         "| [kurc/](kurc/README.md) | Kurc, Aykanat, Ozguc | Table 2 phases at 8 and 16 nodes, "
         "speed-ups of the five merging schemes |\n"
         "| [charles/](charles/README.md) | Charles, Lefevre, Miguet 1995 | speed-ups of the "
         "elastic z-buffer, hypercube and ring; Table 1 |\n"
         "| [blazek/](blazek/README.md) | Blazek 1991 | speed-up and efficiency of the four "
         "decompositions (" +
         (o.full ? std::string("1..2048 spheres, `--full`")
          : kept.empty()
              ? std::string("1..64 spheres; `zcube reproduce blazek --full` for 1..2048, about "
                            "8 minutes")
              : std::string("the `--full` tables, kept; a run without `--full` writes its 1..64 "
                            "spheres to `blazek-quick/`, not committed")) +
         ") |\n"
         "| [compositing/](compositing/README.md) | the three papers' machines | PAIR-RS, "
         "AAPC-HBP, binary swap, direct send, radix-k and folding: pixel-merging time and the "
         "best k per machine and node count (" +
         (o.full ? std::string("8..1024 nodes, `--full`")
                 : std::string("8..64 nodes; `--full` to 1024")) +
         ") |\n"
         "| [mpi/](mpi/README.md) | (this machine) | the same algorithms on MPI processes, "
         "measured "
         "against the prediction on the platform `zcube probe` wrote (scripts/mpi_vs_model.sh) "
         "|\n\n"
         "This run: " +
         std::to_string(points) + " simulations." + (kept.empty() ? "" : " Kept: " + kept + ".") +
         "\n\n"
         "## Error of the network models (fidelity.csv, fidelity.png)\n\n"
         "The same runs under the three network models; the error is against `circuit` (the "
         "reference: each message holds its channels in dimension order, as the iPSC's "
         "Direct-Connect Module). `analytic` ignores contention, `flow` shares bandwidth "
         "(SimGrid's CM02). `virtual_s` is the whole run, `timed_s` the paper's timed region "
         "(Kurc's three Table 2 phases, elastic's per-picture loop; docs/papers.md; the whole run "
         "for Blazek's methods), and `rel_error` is `timed_s`'s. `paper_rel_error` is against the "
         "seeds' figure where one exists "
         "(Kurc Table 2's pixel merging at 16 nodes).\n\n"
         "What each model costs, in the simulator's own events (the reports' `simulation_cost`, "
         "the same in every run, on any host): `messages` the algorithm sent, `flows` the "
         "transfers whose bandwidth SimGrid's model shares (flow: one per message that carries "
         "bytes to another node, per hop on store-and-forward links), `network_events` zcube's "
         "own network events (circuit: a contended channel's release, a message's next stage; "
         "circuit and analytic on the Volvox's half-duplex-limited links: the start and end of "
         "a hop's bytes), `time_steps` the dates SimGrid's engine advanced to, "
         "`actor_switches` the times an actor (a rank, the network's actor, a message's "
         "courier) gave the CPU to SimGrid and was resumed. fidelity.png draws the error "
         "against `actor_switches`, the count that follows the host CPU a model adds over "
         "analytic's (with `flows`, which is 0 under analytic and circuit; "
         "`fidelity_cost.md`). The host CPU of each model, the median of repeated "
         "runs, is measured apart (`bench/fidelity_cost.py`: `fidelity_cost.csv`, "
         "`fidelity_cost.md`, dated, with the machine it ran on); the host's wall time of this "
         "run's simulations is in `host_cost.csv` (not committed).\n\n" +
         fidelity_md;
}

// Everything a simulation depends on, as text: equal keys, equal runs. (A field added to
// RunConfig must be added here too, or two different runs would be taken for one.)
std::string config_key(const RunConfig& c) {
  if (c.custom) throw std::logic_error("reproduce plans name their algorithms");
  nlohmann::json j = program_inputs(c);
  j["machine"] = c.machine;
  j["fidelity"] = fidelity_name(c.fidelity);
  j["simgrid"] = c.simgrid_args;
  for (const auto& [key, value] : what_if_columns(c.what_ifs))
    j[key] = value;
  return j.dump();
}

// "gantt_pair-rs.png" in another plot format: "gantt_pair-rs.svg".
std::string with_plot_format(const std::string& file, const std::string& format) {
  return file.ends_with(".png") ? file.substr(0, file.size() - 3) + format : file;
}

// A README written by a plan names its plots as PNG files: the format drawn instead.
void name_plots_in(const std::string& readme, const std::string& format) {
  if (format == "png" || !std::filesystem::exists(readme)) return;
  std::ifstream in(readme);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  for (std::size_t at = 0; (at = s.find(".png", at)) != std::string::npos; at += format.size() + 1)
    s.replace(at, 4, "." + format);
  write_text(readme, s);
}

// A scratch directory removed with it.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(std::filesystem::path p) : path(std::move(p)) {
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

// plot_results.py's arguments for the given parts of the results directory (a plan's directory,
// "fidelity" or "calibration"), and for the Gantt charts, each from a report file of its own (in
// `scratch`).
std::vector<std::string>
plot_arguments(const std::vector<std::string>& parts,
               const std::vector<std::pair<const nlohmann::json*, std::string>>& charts,
               const ReproduceOptions& o, const ScratchDir& scratch) {
  std::vector<std::string> args = {"--format", o.plot_format, "--jobs", std::to_string(o.jobs)};
  for (const auto& p : parts)
    args.insert(args.end(), {"--part", p});
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const auto& [report, path] = charts[i];
    check_gantt_path(path);
    const auto tmp = scratch.path / (std::to_string(i) + ".json");
    std::ofstream(tmp) << report->dump();
    args.insert(args.end(), {"--gantt", tmp.string(), path});
  }
  args.push_back(o.out);
  return args;
}

// The calibration's fit and its validation, written to out/calibration/.
void reproduce_calibration(const ReproduceOptions& o) {
  CalibrationOptions c;
  c.root = o.root;
  c.jobs = o.jobs;
  c.verbose = o.verbose;
  nlohmann::json fit = calibrate(c);
  // The model selection (`zcube calibrate --select`, five times longer) is not re-run here: its
  // table is kept when it chose the groups this fit kept physical.
  const std::string prev = o.out + "/calibration/fit.json";
  if (std::filesystem::exists(prev)) {
    const nlohmann::json old = read_json_file(prev, "calibration");
    if (old.contains("selection") &&
        old["settings"]["fixed_groups"] == fit["settings"]["fixed_groups"])
      fit["selection"] = old["selection"];
  }
  write_calibration_results(fit, o.out + "/calibration");
}

// What the simulations of a batch cost the host, from the reports of those that ran in processes
// of their own (run/batch.hpp; not those of another backend, such as MPI ranks).
struct SimulationsCost {
  ChildCost cost;
  std::size_t processes = 0;
};
SimulationsCost simulations_cost(const std::vector<nlohmann::json>& reps) {
  SimulationsCost c;
  for (const auto& r : reps) {
    if (!r.contains("host") || !r["host"].contains("process_cpu_s")) continue;
    const nlohmann::json& h = r["host"];
    const double cpu = h.value("process_cpu_s", 0.0), kernel = h.value("process_kernel_s", 0.0);
    c.cost += {cpu - kernel, kernel, h.value("process_minor_faults", 0L)};
    ++c.processes;
  }
  return c;
}

// Where the host's CPU went: the whole job (this process and every process it reaped), and its
// parts; a part not run in a process of its own is in the whole only.
std::string host_cost_line(const SimulationsCost& sims, const ChildCost* calibration,
                           const ChildCost* plots) {
  const ChildCost self = own_cost();
  ChildCost all = self;
  all += reaped_cost();
  std::string s = "reproduce: host CPU " + fixed(all.cpu_s(), 1) + " s (" + fixed(all.system_s, 1) +
                  " in the kernel)";
  const ChildCost& c = sims.cost;
  if (sims.processes > 0)
    s += ": " + std::to_string(sims.processes) + " simulations " + fixed(c.cpu_s(), 1) + " s (" +
         fixed(c.system_s, 1) + " in the kernel, " + fixed(double(c.minor_faults) * 1e-6, 2) +
         " M page faults)";
  s += sims.processes > 0 ? "," : ":";
  if (calibration) s += " calibration " + fixed(calibration->cpu_s(), 1) + " s,";
  if (plots) s += " plots " + fixed(plots->cpu_s(), 1) + " s,";
  return s + " this process " + fixed(self.cpu_s(), 1) + " s\n";
}

} // namespace

std::string plan_directory(const ReproduceOptions& o, const PaperPlan& p, std::string* note) {
  const std::string dir = p.name.empty() ? o.out : o.out + "/" + p.name;
  if (o.overwrite || !p.would_degrade) return dir;
  const std::string why = p.would_degrade(dir);
  if (why.empty()) return dir;
  if (note)
    *note = dir + "/ " + why + ": kept; this run's " + p.name + " tables go to " + dir +
            "-quick/ (--overwrite to replace them)";
  return dir + "-quick";
}

namespace {

// The plans of the papers asked for (all: every paper, then the fidelity study and the claims,
// which read the papers' runs), their charts named in the plot format asked.
std::vector<PaperPlan> plans_of(const ReproduceOptions& o) {
  std::vector<PaperPlan> plans;
  const bool all = o.papers.empty();
  if (all)
    for (const auto& p : papers())
      plans.push_back(p.plan(o));
  for (const auto& name : o.papers) {
    const Paper* p = find_paper(name);
    if (!p)
      throw UsageError("reproduce: unknown paper '" + name + "' (" + paper_names_text() +
                       " or all)");
    plans.push_back(p->plan(o));
  }
  if (all) {
    plans.push_back(fidelity_plan(o));
    plans.push_back(claims_plan(o)); // after every paper's plan: it reads their runs
  }
  // The plans name their charts .png: drawn, and named in the READMEs, in the format asked.
  for (auto& p : plans)
    for (auto& g : p.gantt)
      g.file = with_plot_format(g.file, o.plot_format);
  return plans;
}

// Each plan's directory; `kept` says which committed directories were kept and where this run's
// tables went instead.
std::vector<std::string> plan_directories(const ReproduceOptions& o,
                                          const std::vector<PaperPlan>& plans, std::string& kept) {
  std::vector<std::string> dirs;
  for (const auto& p : plans) {
    std::string note;
    dirs.push_back(plan_directory(o, p, &note));
    if (note.empty()) continue;
    kept += (kept.empty() ? "" : "; ") + note;
    if (o.write && o.verbose) std::cerr << "reproduce: " << note << "\n";
  }
  return dirs;
}

// Plans share some points (Table 2's 16-node runs are also speed-up and fidelity points): each
// distinct configuration is simulated once; point_run[k] is the run of the plans' k-th point.
struct DistinctRuns {
  std::vector<RunConfig> cfgs;
  std::vector<std::size_t> point_run;
};

DistinctRuns distinct_runs(const std::vector<PaperPlan>& plans, const ReproduceOptions& o) {
  DistinctRuns d;
  std::map<std::string, std::size_t> index_of;
  for (const auto& p : plans)
    for (const auto& pt : p.points) {
      const auto [it, fresh] = index_of.emplace(config_key(pt.cfg), d.cfgs.size());
      if (fresh) d.cfgs.push_back(pt.cfg);
      d.point_run.push_back(it->second);
      // A chart's point records its timeline (which changes no result, so is not in the key).
      for (const auto& g : p.gantt)
        if (g.key == pt.key && o.plots) d.cfgs[it->second].timeline = true;
    }
  return d;
}

// Every plan's tables under its directory; returns 1 when a point failed or drew a picture other
// than the sequential renderer's. `summaries` gathers the plans' lines for the top README, and
// `charts` the reports the space-time diagrams are drawn from.
int write_plans(const std::vector<PaperPlan>& plans, const std::vector<std::string>& dirs,
                const std::vector<nlohmann::json>& reps, const std::vector<std::size_t>& point_run,
                const ReproduceOptions& o, std::string& summaries,
                std::vector<std::pair<const nlohmann::json*, std::string>>& charts) {
  int status = 0;
  std::size_t i = 0;
  for (const auto& p : plans) {
    for (const auto& g : p.gantt)
      for (std::size_t k = 0; k < p.points.size(); ++k)
        if (p.points[k].key == g.key && reps[point_run[i + k]].contains("timeline"))
          charts.push_back(
              {&reps[point_run[i + k]], dirs[std::size_t(&p - plans.data())] + "/" + g.file});
    Reports r;
    for (const auto& pt : p.points) {
      const auto& rep = reps[point_run[i++]];
      if (rep.value("status", "") == "error") {
        std::cerr << "reproduce: " << (p.name.empty() ? "fidelity" : p.name) << " point " << pt.key
                  << " failed: " << rep.value("error", "?") << "\n";
        status = 1;
      } else if (ok(rep) && rep["image"].value("identical_to_sequential", nlohmann::json(true)) ==
                                false) { // null: no picture drawn
        std::cerr << "reproduce: " << p.name << " point " << pt.key
                  << ": image differs from the sequential renderer's\n";
        status = 1;
      }
      r[pt.key] = rep;
    }
    const std::string& dir = dirs[std::size_t(&p - plans.data())];
    std::filesystem::create_directories(dir);
    summaries += p.write(r, dir);
    if (!p.name.empty()) {
      name_plots_in(dir + "/README.md", o.plot_format);
      append_provenance(dir + "/README.md");
    }
  }
  return status;
}

// The end of the job: the plots waited for, where the host's CPU went, the whole time.
void finish_reproduce(const ReproduceOptions& o, std::optional<BackgroundPlots>& plots,
                      const std::optional<BackgroundJob>& calibration,
                      const SimulationsCost& sims_cost, std::size_t chart_count,
                      std::chrono::steady_clock::time_point t0) {
  if (plots) {
    if (o.verbose)
      std::cerr << "reproduce: drawing the plots and " << chart_count << " space-time diagrams\n";
    // Without matplotlib the script said so in one line; the tables stand without their plots.
    if (plots->wait() == PlotOutcome::failed)
      std::cerr << "reproduce: plots not drawn (scripts/plot_results.py failed; it needs "
                   "python3-matplotlib, which scripts/setup.sh installs)\n";
  }
  if (o.verbose)
    std::cerr << host_cost_line(sims_cost, calibration ? &calibration->cost() : nullptr,
                                plots ? &plots->cost() : nullptr);
  // The whole job's time, plots included.
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (o.verbose) std::cerr << "reproduce: wrote " << o.out << "/ in " << fixed(wall, 1) << " s\n";
}

} // namespace

int reproduce(const ReproduceOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (o.write) prepare_output_dir(o.out); // before anything runs
  std::vector<PaperPlan> plans = plans_of(o);
  const bool all = o.papers.empty();
  std::string kept;
  const std::vector<std::string> dirs = plan_directories(o, plans, kept);

  auto [cfgs, point_run] = distinct_runs(plans, o);
  if (o.verbose && o.write)
    std::cerr << "reproduce: " << cfgs.size() << " simulations, " << o.jobs << " at a time\n";
  const auto progress = o.verbose && o.write ? progress_printer("reproduce", cfgs.size())
                                             : std::function<void(const BatchProgress&)>{};
  // The calibration needs none of the plans' points: with the local batch and two jobs or more,
  // it runs beside them in a process of its own, with as many jobs (its batches and the plans'
  // share the cores: it ends first, its points being short, and its plot is drawn while the plans'
  // batch runs; after it, as before, a core would idle at the end of each of its fit steps).
  const bool calibrating = all && o.calibration && o.write;
  std::optional<BackgroundJob> calibration;
  if (calibrating && !o.runner && o.jobs >= 2)
    calibration.emplace([&o] { reproduce_calibration(o); });
  // One interpreter draws every plot: started now, it loads matplotlib (a large share of a plot's
  // cost) while the simulations run, and draws each figure once its files are written.
  std::optional<ScratchDir> plot_dir;
  std::optional<BackgroundPlots> plots;
  if (o.plots && o.write) {
    plot_dir.emplace(std::filesystem::temp_directory_path() /
                     ("zcube-" + std::to_string(getpid()) + "-plots"));
    plots.emplace(o.root);
  }
  bool calibration_drawn = false;
  const auto draw_calibration = [&] {
    if (plots && !calibration_drawn) plots->draw(plot_arguments({"calibration"}, {}, o, *plot_dir));
    calibration_drawn = true;
  };
  const auto on_point = [&](const BatchProgress& pr) {
    if (progress) progress(pr);
    if (calibration && calibration->finished() && calibration->succeeded()) draw_calibration();
  };
  auto reps = o.runner ? o.runner(cfgs, o.jobs, progress) : simulate_batch(cfgs, o.jobs, on_point);
  if (!o.write) return 0;
  const SimulationsCost sims_cost = simulations_cost(reps);

  std::string summaries;
  std::vector<std::pair<const nlohmann::json*, std::string>> charts;
  const int status = write_plans(plans, dirs, reps, point_run, o, summaries, charts);
  if (plots) {
    // The plots of what this run wrote: a directory kept because it holds more (the --full
    // tables) keeps its plots too, drawn by the run that wrote its tables.
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < plans.size(); ++k)
      if (plans[k].plotted)
        parts.push_back(plans[k].name.empty() ? "fidelity" : dirs[k].substr(o.out.size() + 1));
    plots->draw(plot_arguments(parts, charts, o, *plot_dir));
  }
  // The reports are written: freed before the calibration, when it runs here, forks its runs (a
  // fork copies the page tables of the memory its parent holds).
  const std::size_t chart_count = charts.size();
  charts.clear();
  std::vector<nlohmann::json>().swap(reps);
  if (calibration) {
    if (const std::string e = calibration->wait(); !e.empty()) throw std::runtime_error(e);
  } else if (calibrating) {
    reproduce_calibration(o);
  }
  if (calibrating) draw_calibration();
  if (all) {
    write_text(o.out + "/README.md", top_readme(o, cfgs.size(), summaries, kept));
    name_plots_in(o.out + "/README.md", o.plot_format);
    append_provenance(o.out + "/README.md");
  }

  finish_reproduce(o, plots, calibration, sims_cost, chart_count, t0);
  return status;
}

} // namespace zc
