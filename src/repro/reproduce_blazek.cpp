// Blazek 1991 on the simulated iPSC/2: speed-up and efficiency of the four decompositions
// (thesis ch. VI, Figures 12-19) on random spheres, 1..32 nodes.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "machine/units.hpp"
#include "repro/reproduce.hpp"
#include "repro/table.hpp"

namespace zc {

namespace {

struct Method {
  std::string name, option_key, option_value;
};
// The options of results/blazek: 100-polygon packets (the thesis's 3-kilobyte example), whole
// objects forwarded, strips.
const std::vector<Method> kMethods = {{"host-initiated", "packet", "100"},
                                      {"node-initiated", "", ""},
                                      {"object-forwarding", "forward", "object"},
                                      {"host-broadcast", "lines", "strips"}};
// The thesis's ranking (ch. VI): node initiated best, then broadcast, then object forwarding,
// host initiated worst.
const std::vector<std::string> kThesisOrder = {"node-initiated", "host-broadcast",
                                               "object-forwarding", "host-initiated"};
const std::vector<int> kBlazekNodes = {1, 2, 4, 8, 16, 32};

std::vector<int> sphere_counts(bool full) {
  if (full) return {1, 4, 16, 64, 256, 1024, 2048};
  return {1, 4, 16, 64};
}

std::string key(const std::string& m, int s, int n) {
  return m + "/" + std::to_string(s) + "/" + std::to_string(n);
}
// The one-processor time (docs/papers.md): Algorithm 3 on one node, which tessellates every object
// ("Tessellate O into polygons") and renders it into its frame buffer: node initiated on 1 node.
std::string seq_key(int s) {
  return key("node-initiated", s, 1);
}

// The representative runs drawn as space-time diagrams: node initiated beside host initiated,
// 16 spheres on 16 nodes.
std::vector<GanttChart> blazek_gantt() {
  return {{key("node-initiated", 16, 16), "gantt_node-initiated.png",
           "node initiated, 16 spheres, 16 nodes"},
          {key("host-initiated", 16, 16), "gantt_host-initiated.png",
           "host initiated, 16 spheres, 16 nodes"}};
}

// speedup.csv and host_cost.csv under dir; returns the README's speed-up tables, a method each.
static std::string write_blazek_speedups(const std::vector<int>& spheres, const Reports& reps,
                                         const std::string& dir) {
  // timed_s is the whole run here (the thesis times "a task", docs/papers.md), as virtual_s.
  Table su{{"algorithm", "spheres", "nodes", "status", "virtual_s", "timed_s", "speedup",
            "speedup_p05", "speedup_p95", "efficiency"},
           {}};
  Table host{{"algorithm", "spheres", "nodes", "status", "triangles", "wall_s", "peak_rss_bytes"},
             {}};
  std::string tables;
  for (const auto& m : kMethods) {
    Table md{{"spheres", "P=1", "P=2", "P=4", "P=8", "P=16", "P=32"}, {}};
    for (int s : spheres) {
      const double seq = timed_s(reps.at(seq_key(s)));
      std::vector<std::string> row = {std::to_string(s)};
      for (int n : kBlazekNodes) {
        const auto& r = reps.at(key(m.name, s, n));
        host.add({m.name, std::to_string(s), std::to_string(n), status_of(r),
                  num(r["scene"].value("triangles", 0.0)),
                  num(r["host"].value("wall_time_s", 0.0), 3),
                  num(r["host"].value("peak_rss_bytes", 0.0))});
        if (!ok(r)) {
          su.add(
              {m.name, std::to_string(s), std::to_string(n), status_of(r), "", "", "", "", "", ""});
          row.push_back(out_of_memory(r) ? "oom" : "error");
          continue;
        }
        const double t = timed_s(r), sp = seq / t;
        const auto [lo, hi] = ratio_band(band_timed_s(reps.at(seq_key(s))), band_timed_s(r));
        su.add({m.name, std::to_string(s), std::to_string(n), "ok", num(whole_run_s(r)), num(t),
                num(sp, 4), std::isfinite(lo) ? num(lo, 4) : "",
                std::isfinite(hi) ? num(hi, 4) : "", num(sp / n, 4)});
        row.push_back(fixed(sp, 2) + " (" + fixed(sp / n, 2) + ")");
      }
      md.add(row);
    }
    tables += "### " + m.name +
              (m.option_key.empty() ? "" : " --" + m.option_key + " " + m.option_value) +
              "\n\nspeed-up (efficiency)\n\n" + md.markdown() + "\n";
  }
  su.write_csv(dir + "/speedup.csv");
  host.write_csv(dir + "/host_cost.csv");
  return tables;
}

std::string write_blazek(const std::vector<int>& spheres, const Reports& reps,
                         const std::string& dir) {
  const bool full = spheres.size() > sphere_counts(false).size();
  const std::string tables = write_blazek_speedups(spheres, reps, dir);

  // The thesis's ordering, at the largest scene on 32 nodes.
  const int big = spheres.back();
  std::vector<std::pair<double, std::string>> rank;
  for (const auto& m : kMethods) {
    const auto& r = reps.at(key(m.name, big, 32));
    rank.push_back({ok(r) ? timed_s(reps.at(seq_key(big))) / timed_s(r) : 0.0, m.name});
  }
  std::sort(rank.rbegin(), rank.rend());
  std::string order, verdict;
  bool same = true;
  for (std::size_t i = 0; i < rank.size(); ++i) {
    order += (i ? " > " : "") + rank[i].second + " (" + fixed(rank[i].first, 2) + ")";
    same = same && rank[i].second == kThesisOrder[i];
  }
  verdict = same ? "the same as the thesis's"
                 : "not the thesis's (node initiated > broadcast > "
                   "object forwarding > host initiated)";
  write_text(
      dir + "/README.md",
      "# Blazek 1991: four decompositions on the simulated iPSC/2\n\n"
      "Written by `zcube reproduce blazek" +
          std::string(full ? " --full" : "") +
          "` (src/repro/reproduce_blazek.cpp; `--full` for 1..2048 spheres, about 8 minutes on "
          "two cores). Thesis: E. M. Blazek, *Parallel Image Generation Using the Z-Buffering "
          "Algorithm on a Medium Grained Distributed Memory Model Computer*, Oklahoma State "
          "University, 1991, ch. V "
          "(methods), ch. VI (results: curves only, no printed figures, so nothing here is fitted "
          "to it). Machine: the iPSC/2 model calibrated on Kurc et al. (results/calibration/), "
          "circuit "
          "fidelity, 512x512.\n\n"
          "- Workload (ch. V): 1.." +
          std::to_string(big) +
          " uniformly random spheres of identical size (`scenes/blazek/thesis_spheres_N.json`), "
          "octahedra subdivided 5 times (8192 triangles each; the thesis's 5102 fits no "
          "subdivision rule, see scenes/README.md).\n"
          "- Node memory 16 MiB (the iPSC/2's largest node, ch. IV: a full 512x512 frame buffer of "
          "10 bytes a pixel, the thesis's 2,621,440 bytes, and the merge's receive buffer need "
          "it).\n"
          "- Speed-up = T(`node-initiated`, 1 node) / T(method, P): the thesis's one-processor "
          "time is its Algorithm 3, which tessellates every object and renders it into one frame "
          "buffer, as node initiated does on one node (docs/papers.md); efficiency = speed-up / P "
          "(the thesis's `E = S_p * P` is a typo).\n\n"
          "Ranking at " +
          std::to_string(big) + " spheres on 32 nodes: " + order + ": " + verdict +
          ".\n\n## Speed-up and efficiency (speedup.csv)\n\n" + tables +
          "`host_cost.csv` (not committed: it varies from run to run): the simulator's wall time "
          "and peak RSS per point (points ran in parallel, so wall times are pessimistic).\n\n"
          "Plots: `speedup.png`, `efficiency.png`.\n" +
          gantt_markdown(blazek_gantt()));
  return "";
}

// Why writing this run's tables into dir would lose rows: its speedup.csv has sphere counts
// this run does not simulate (the committed copy is --full).
std::string would_degrade(const std::vector<int>& spheres, const std::string& dir) {
  std::ifstream in(dir + "/speedup.csv");
  std::string line;
  if (!std::getline(in, line)) return "";
  const auto cells = [](const std::string& l) {
    std::vector<std::string> c(1);
    for (char ch : l)
      if (ch == ',')
        c.emplace_back();
      else
        c.back().push_back(ch);
    return c;
  };
  const auto head = cells(line);
  const auto col = std::find(head.begin(), head.end(), "spheres") - head.begin();
  if (col == std::ssize(head)) return "";
  std::set<int> have;
  while (std::getline(in, line)) {
    const auto c = cells(line);
    try {
      if (col < std::ssize(c)) have.insert(std::stoi(c[col]));
    } catch (const std::exception&) {
    }
  }
  for (int s : have)
    if (std::find(spheres.begin(), spheres.end(), s) == spheres.end())
      return "holds tables up to " + std::to_string(*have.rbegin()) +
             " spheres (zcube reproduce blazek --full) that this run would drop";
  return "";
}

} // namespace

PaperPlan blazek_plan(const ReproduceOptions& o) {
  PaperPlan p;
  p.name = "blazek";
  const auto spheres = sphere_counts(o.full);
  for (int s : spheres) {
    const std::string path =
        o.root + "/scenes/blazek/thesis_spheres_" + std::to_string(s) + ".json";
    for (const auto& m : kMethods)
      for (int n : kBlazekNodes) {
        RunConfig c = repro_config("ipsc2", n, m.name, path, 512);
        c.what_ifs.set("memory", {16.0 * 1048576});
        if (!m.option_key.empty()) c.options.values[m.option_key] = m.option_value;
        p.points.push_back({key(m.name, s, n), c});
      }
  }
  p.gantt = blazek_gantt();
  p.write = [spheres](const Reports& r, const std::string& dir) {
    return write_blazek(spheres, r, dir);
  };
  p.would_degrade = [spheres](const std::string& dir) { return would_degrade(spheres, dir); };
  with_bands(p);
  return p;
}

} // namespace zc
