// The compositing study (results/compositing/): on the iPSC/2, iPSC/860 and Volvox models, Kurc et
// al.'s scenes, 400x400 and 640x640, the pixel-merging time of Kurc et al.'s PAIR-RS and AAPC-HBP
// and of binary swap, direct send, radix-k for every k dividing P and binary-swap folding (node
// counts that are not powers of two, on a Volvox ring), all from one simulation per point
// (algo/sort_last/compositing_study.cpp): the scene loaded and rendered once, the contenders run in
// turn. Without --full: 2 POT at 8, 16 and 64 nodes (12 and 48 on the ring); --full every Kurc
// scene (1 POT .. 8 POT_2, as results/kurc names them) at 8..1024 (640x640 up to 256; the
// ring 12..96).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "repro/reproduce.hpp"
#include "repro/table.hpp"
#include "util/output_file.hpp"

namespace zc {

namespace {

const std::vector<std::string> kMachines = {"ipsc2", "ipsc860", "volvox"};
// Kurc et al.'s scenes (scenes/kurc/, Table 1, named as in results/kurc); the quick grid keeps 2
// POT.
const std::vector<std::string> kScenes = {"1pot", "2pot", "4pot_1", "4pot_2", "8pot_1", "8pot_2"};
const char* kQuickScene = "2pot";

const char* kStudyText =
    "One simulation per row: the scene dealt and z-buffered once (Kurc et al.'s first two phases), "
    "the scanline counts summed once, then each contender in turn from the same local pictures "
    "after a barrier, its share of the screen and its strategy timed as a phase of its own: the "
    "largest time of any node, in ms. PAIR-RS and AAPC-HBP composite Kurc et al.'s winning pixel "
    "arrays; binary swap, direct send, radix-k and folding composite IceT's run-length encoded "
    "pixels shared by heuristic bin packing. radix-k with k = 2 is binary swap and with k = P "
    "direct send (tests/compositing). All-to-all rounds of more than 64 nodes (16 above 256 nodes) "
    "are not simulated (host time). Node memory is not the limit here (1 GiB nodes): the study is "
    "about time. Each round's merge is charged before the node sends on (docs/compositing.md, "
    "\"Limits\"; Kurc et al.'s own programs charge it when the phase ends, as calibrated).";

const char* kFilesText =
    "\n`best.csv`: the best contender and the best k of every machine, size, scene and node "
    "count, with the start-up, byte and rest ms of the best k and why (against binary swap). "
    "`merging.csv`: every contender (`algorithm`) at every point.\n\nPlots: `merging.png` (time "
    "against P per "
    "machine, 2 POT, 400x400), `best_k.png` (the best k against P per machine, one line a "
    "scene, 400x400).\n";

struct Point {
  std::string scene, machine;
  Topology topology;
  int size, nodes;
  std::string key() const {
    return scene + "/" + machine + "/" + topology_name(topology) + "/" + std::to_string(size) +
           "/" + std::to_string(nodes);
  }
  // The point without its scene: where the scenes' best k are compared.
  std::string where() const {
    return machine + (topology == Topology::Ring ? " ring" : "") + "," + std::to_string(size) +
           "," + std::to_string(nodes);
  }
};

std::vector<Point> grid(bool full) {
  std::vector<Point> v;
  std::vector<int> cube = {8, 16, 64};
  if (full) cube = {8, 16, 32, 64, 128, 256, 512, 1024};
  const auto ring = full ? std::vector<int>{12, 24, 48, 96} : std::vector<int>{12, 48};
  for (const auto& scene : full ? kScenes : std::vector<std::string>{kQuickScene}) {
    for (const auto& m : kMachines)
      for (int size : {400, 640})
        for (int P : cube)
          if (size == 400 || P <= 256) v.push_back({scene, m, Topology::Cube, size, P});
    for (int size : {400, 640})
      for (int P : ring)
        v.push_back({scene, "volvox", Topology::Ring, size, P});
  }
  return v;
}

struct Row {
  std::string contender;
  double ms, messages, bytes, max_messages, max_bytes, startup_ms, bytes_ms, network_ms;
  // What the start-ups and bytes do not explain: merging CPU, hops, contention and waiting.
  double rest_ms() const { return ms - network_ms; }
};

// Each contender's phase of one report, with the start-ups and bytes of its busiest node priced
// at the machine's start-up and per-byte time (a lower bound on its network time: no hops, no
// contention).
std::vector<Row> rows_of(const nlohmann::json& r) {
  std::vector<Row> v;
  const auto& model = r["model"];
  const double startup = model.value("startup_long_s", 0.0),
               per_byte = model.value("per_byte_s", 0.0);
  const auto& study = r["compositing_study"];
  for (const auto& p : r["phases"]) {
    const std::string name = p["name"];
    if (!study.contains(name)) continue;
    const double mm = study[name]["max_messages"], mb = study[name]["max_bytes_sent"];
    v.push_back({name, p["max_s"].get<double>() * 1e3, p.value("messages", 0.0),
                 p.value("charged_bytes", 0.0), mm, mb, mm * startup * 1e3, mb * per_byte * 1e3,
                 (mm * startup + mb * per_byte) * 1e3});
  }
  return v;
}

// k of a radix-k contender (binary swap 2, direct send P), or 0.
int radix_of(const std::string& c, int P) {
  if (c == "binary-swap") return 2;
  if (c == "direct-send") return P;
  return c.starts_with("radix-") ? std::stoi(c.substr(6)) : 0;
}

std::string why(const Row& best, const Row* swap, const nlohmann::json& model) {
  const auto line = [&](const Row& r) {
    return fixed(r.max_messages, 0) + " start-ups (" + fixed(r.startup_ms, 1) + " ms), " +
           fixed(r.max_bytes / 1e3, 1) + " KB (" + fixed(r.bytes_ms, 1) + " ms), the rest " +
           fixed(r.rest_ms(), 1) + " ms of " + fixed(r.ms, 1);
  };
  return best.contender + ": " + line(best) + (swap ? "; binary swap: " + line(*swap) : "") +
         "; one start-up = " +
         fixed(model.value("startup_long_s", 0.0) / model.value("per_byte_s", 1.0), 0) + " B";
}

// The fastest contender, the fastest radix-k and binary swap of one point.
struct Picked {
  const Row *best = nullptr, *best_k = nullptr, *swap = nullptr;
  std::map<std::string, const Row*> by;
};

Picked pick(const std::vector<Row>& rows, int P) {
  Picked c;
  for (const auto& x : rows) {
    c.by[x.contender] = &x;
    if (!c.best || x.ms < c.best->ms) c.best = &x;
    if (radix_of(x.contender, P) && (!c.best_k || x.ms < c.best_k->ms)) c.best_k = &x;
    if (x.contender == "binary-swap") c.swap = &x;
  }
  return c;
}

struct Written {
  Table merging{{"machine", "topology", "width", "height", "scene", "nodes", "algorithm",
                 "merging_ms", "messages", "charged_bytes", "max_messages", "max_bytes_sent",
                 "network_ms"},
                {}};
  Table best{{"machine", "topology", "width", "height", "scene", "nodes", "best", "best_ms",
              "best_k", "best_k_ms", "startup_ms", "bytes_ms", "rest_ms", "why"},
             {}};
  // Every contender in 2 POT (the quick grid's scene).
  Table md{{"machine", "size", "P", "PAIR-RS", "AAPC-HBP", "binary swap / folding", "direct send",
            "best k", "best"},
           {}};
  // The points without their scene, in grid order, and each scene's best k (and its ms) there.
  std::vector<Point> wheres;
  std::map<std::string, std::map<std::string, std::pair<int, double>>> best_k;
  // Every radix-k contender's ms (binary swap k = 2, direct send k = P) by point, scene and k.
  std::map<std::string, std::map<std::string, std::map<int, double>>> k_ms;
  // Each machine's and scene's largest node count at 400x400: its best k and why.
  std::map<std::pair<std::string, std::string>, std::pair<int, std::vector<std::string>>> largest;
};

void note_best_k(Written& w, const Point& pt, int k, const Row& bk, const Row* swap) {
  if (!w.best_k.count(pt.where())) w.wheres.push_back(pt);
  w.best_k[pt.where()][pt.scene] = {k, bk.ms};
  const std::string machine = pt.machine + (pt.topology == Topology::Ring ? " ring" : "");
  auto& top = w.largest[{machine, pt.scene}];
  if (pt.size != 400 || pt.nodes <= top.first) return;
  top = {pt.nodes,
         {machine, pt.scene, std::to_string(pt.nodes), std::to_string(k), fixed(bk.ms, 1),
          fixed(bk.max_messages, 0), fixed(bk.startup_ms, 1), fixed(bk.max_bytes / 1e3, 1),
          fixed(bk.bytes_ms, 1), fixed(bk.rest_ms(), 1), swap ? fixed(swap->ms, 1) : "-"}};
}

void add_point(Written& w, const Point& pt, const nlohmann::json& r) {
  const auto rows = rows_of(r);
  const std::string topo = topology_name(pt.topology), size = std::to_string(pt.size),
                    P = std::to_string(pt.nodes);
  for (const auto& x : rows)
    if (const int k = radix_of(x.contender, pt.nodes)) w.k_ms[pt.where()][pt.scene][k] = x.ms;
  for (const auto& x : rows)
    w.merging.add({pt.machine, topo, size, size, pt.scene, P, x.contender, fixed(x.ms, 3),
                   num(x.messages), num(x.bytes), num(x.max_messages), num(x.max_bytes),
                   fixed(x.network_ms, 3)});
  Picked c = pick(rows, pt.nodes);
  if (!c.best) return;
  const Row* bk = c.best_k;
  const int k = bk ? radix_of(bk->contender, pt.nodes) : 0;
  const auto ms = [&](const Row* x, double v) { return x ? fixed(v, 3) : ""; };
  w.best.add({pt.machine, topo, size, size, pt.scene, P, c.best->contender, fixed(c.best->ms, 3),
              k ? std::to_string(k) : "", ms(bk, bk ? bk->ms : 0), ms(bk, bk ? bk->startup_ms : 0),
              ms(bk, bk ? bk->bytes_ms : 0), ms(bk, bk ? bk->rest_ms() : 0),
              bk ? why(*bk, c.swap, r["model"]) : ""});
  if (bk) note_best_k(w, pt, k, *bk, c.swap);
  if (pt.scene != kQuickScene) return;
  const auto shown = [&](const char* n) { return c.by.count(n) ? fixed(c.by[n]->ms, 1) : "-"; };
  w.md.add({pt.machine + (pt.topology == Topology::Ring ? " ring" : ""), size, P, shown("pair-rs"),
            shown("aapc-hbp"), c.by.count("folding") ? shown("folding") : shown("binary-swap"),
            shown("direct-send"), k ? std::to_string(k) + " (" + fixed(bk->ms, 1) + ")" : "-",
            c.best->contender});
}

// The best k (and its ms) of every scene at each point, and whether the scenes agree.
Table scene_table(const Written& w, int* agree) {
  Table t{{"machine", "size", "P"}, {}};
  for (const auto& s : kScenes)
    t.header.push_back(s);
  t.header.push_back("same k");
  for (const auto& pt : w.wheres) {
    std::vector<std::string> row = {pt.machine + (pt.topology == Topology::Ring ? " ring" : ""),
                                    std::to_string(pt.size), std::to_string(pt.nodes)};
    std::set<int> ks;
    for (const auto& s : kScenes) {
      const auto& at = w.best_k.at(pt.where());
      const auto it = at.find(s);
      row.push_back(it == at.end() ? "-"
                                   : std::to_string(it->second.first) + " (" +
                                         fixed(it->second.second, 1) + ")");
      if (it != at.end()) ks.insert(it->second.first);
    }
    row.push_back(ks.size() == 1 ? "yes" : "no");
    *agree += ks.size() == 1;
    t.add(row);
  }
  return t;
}

// What taking 2 POT's best k costs in the other scenes where their own best k differs.
std::string cost_of_one_k(const Written& w) {
  std::vector<double> extra;
  std::string worst;
  for (const auto& pt : w.wheres) {
    const auto& at = w.best_k.at(pt.where());
    if (!at.count(kQuickScene)) continue;
    const int k = at.at(kQuickScene).first;
    for (const auto& [scene, best] : at) {
      const auto& ms = w.k_ms.at(pt.where()).at(scene);
      if (best.first == k || !ms.count(k)) continue;
      extra.push_back(ms.at(k) / best.second - 1);
      if (extra.back() >= *std::max_element(extra.begin(), extra.end()))
        worst = pt.where() + " " + scene + ": k = " + std::to_string(k) + " " + fixed(ms.at(k), 1) +
                " ms against k = " + std::to_string(best.first) + " " + fixed(best.second, 1);
    }
  }
  if (extra.empty()) return "";
  std::sort(extra.begin(), extra.end());
  return " Where a scene's best k differs from 2 POT's (" + std::to_string(extra.size()) +
         " scene points), 2 POT's k is slower by a median " +
         fixed(100 * extra[extra.size() / 2], 1) + " % and at most " +
         fixed(100 * extra.back(), 1) + " % (" + worst + " ms).";
}

std::string largest_table(const Written& w) {
  Table t{{"machine", "scene", "P", "best k", "ms", "start-ups", "ms", "KB", "ms", "rest ms",
           "binary swap ms"},
          {}};
  for (const auto& [key, top] : w.largest)
    t.add(top.second);
  return t.markdown();
}

std::string readme(const Written& w, bool full) {
  int agree = 0;
  const Table scenes = scene_table(w, &agree);
  return "# Compositing on the 1990s machines: PAIR-RS, AAPC-HBP, binary swap, direct send, "
         "radix-k\n\n"
         "Written by `zcube reproduce compositing" +
         std::string(full ? " --full" : "") +
         "` (src/repro/reproduce_compositing.cpp, algo/sort_last/compositing_study.cpp; "
         "docs/compositing.md). Scenes: " +
         (full ? "Kurc et al.'s six (scenes/kurc/1pot.json .. 8pot_2.json, named as in "
                 "results/kurc)"
               : "Kurc et al.'s 2 POT (scenes/kurc/2pot.json; --full runs all six)") +
         ". " + kStudyText + "\n\n## Every contender, 2 POT\n\n" + w.md.markdown() +
         "\n## The best k in each scene\n\nThe fastest radix-k (binary swap k = 2, direct send "
         "k = P) and its ms, per scene: the same k in every scene at " +
         std::to_string(agree) + " of " + std::to_string(w.wheres.size()) + " points." +
         cost_of_one_k(w) + "\n\n" + scenes.markdown() +
         "\n## Why, at each machine's largest node count (400x400)\n\nThe busiest node's "
         "start-ups and kilobytes at the best k, priced at the machine's start-up and per-byte "
         "time (a lower bound: no hops, no contention); the rest is merging CPU (list merges of "
         "the retained and received pixels at every binary-swap stage, a z-buffer merge of the "
         "kept rows in a round of k > 2), hops, contention and waiting.\n\n" +
         largest_table(w) + "\n" + kFilesText;
}

std::string would_degrade(const std::string& dir, bool full) {
  if (full) return "";
  std::ifstream in(dir + "/merging.csv");
  std::string line;
  while (std::getline(in, line))
    if (line.find(",1024,") != std::string::npos) return "holds the --full grid (up to 1024 nodes)";
  return "";
}

} // namespace

PaperPlan compositing_plan(const ReproduceOptions& o) {
  PaperPlan p;
  p.name = "compositing";
  const auto points = grid(o.full);
  for (const auto& pt : points) {
    RunConfig c = repro_config(pt.machine, pt.nodes, "compositing-study",
                               o.root + "/scenes/kurc/" + pt.scene + ".json", pt.size);
    c.topology = pt.topology;
    c.what_ifs.set("memory", {1024.0 * 1048576});
    c.compare_with_sequential = false;
    p.points.push_back({pt.key(), c});
  }
  const bool full = o.full;
  p.write = [points, full](const Reports& reps, const std::string& dir) {
    Written w;
    for (const auto& pt : points)
      if (ok(reps.at(pt.key()))) add_point(w, pt, reps.at(pt.key()));
    w.merging.write_csv(dir + "/merging.csv");
    w.best.write_csv(dir + "/best.csv");
    write_text(dir + "/README.md", readme(w, full));
    return std::string();
  };
  p.would_degrade = [full](const std::string& dir) { return would_degrade(dir, full); };
  return p;
}

} // namespace zc
