// The compositing study (results/compositing/): on the iPSC/2, iPSC/860 and Volvox models, Kurc et
// al.'s scenes, 400x400 and 640x640, the pixel-merging time of Kurc et al.'s PAIR-RS and AAPC-HBP
// and of binary swap, direct send, radix-k for every k dividing P and binary-swap folding (node
// counts that are not powers of two, on a Volvox ring), all from one simulation per point
// (algo/compositing_study.cpp): the scene loaded and rendered once, the contenders run in turn.
// Without --full: 8, 16 and 64 nodes (12 and 48 on the ring); --full 8..1024 (640x640 up to
// 256; the ring 12..96).
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
const char* kScene = "2pot";

struct Point {
  std::string machine;
  Topology topology;
  int size, nodes;
  std::string key() const {
    return machine + "/" + topology_name(topology) + "/" + std::to_string(size) + "/" +
           std::to_string(nodes);
  }
};

std::vector<Point> grid(bool full) {
  std::vector<Point> v;
  std::vector<int> cube = {8, 16, 64};
  if (full) cube = {8, 16, 32, 64, 128, 256, 512, 1024};
  for (const auto& m : kMachines)
    for (int size : {400, 640})
      for (int P : cube)
        if (size == 400 || P <= 256) v.push_back({m, Topology::Cube, size, P});
  for (int size : {400, 640})
    for (int P : full ? std::vector<int>{12, 24, 48, 96} : std::vector<int>{12, 48})
      v.push_back({"volvox", Topology::Ring, size, P});
  return v;
}

struct Row {
  std::string contender;
  double ms, messages, bytes, max_messages, max_bytes, network_ms;
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
                 p.value("charged_bytes", 0.0), mm, mb, (mm * startup + mb * per_byte) * 1e3});
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
    return fixed(r.max_messages, 0) + " start-ups, " + fixed(r.max_bytes / 1e3, 1) + " KB (" +
           fixed(r.network_ms, 1) + " ms of " + fixed(r.ms, 1) + ")";
  };
  return best.contender + ": " + line(best) + (swap ? "; binary swap: " + line(*swap) : "") +
         "; one start-up = " +
         fixed(model.value("startup_long_s", 0.0) / model.value("per_byte_s", 1.0), 0) + " B";
}

struct Written {
  Table merging{{"machine", "topology", "size", "scene", "nodes", "contender", "merging_ms",
                 "messages", "charged_bytes", "max_messages", "max_bytes_sent", "network_ms"},
                {}};
  Table best{{"machine", "topology", "size", "scene", "nodes", "best", "best_ms", "best_k",
              "best_k_ms", "why"},
             {}};
  Table md{{"machine", "size", "P", "PAIR-RS", "AAPC-HBP", "binary swap / folding", "direct send",
            "best k", "best"},
           {}};
  // Each machine's largest node count at 400x400: its best k and why.
  std::map<std::string, std::pair<int, std::string>> largest;
};

void add_point(Written& w, const Point& pt, const nlohmann::json& r) {
  const auto rows = rows_of(r);
  const std::string topo = topology_name(pt.topology), size = std::to_string(pt.size),
                    P = std::to_string(pt.nodes);
  const Row *best = nullptr, *best_k = nullptr, *swap = nullptr;
  std::map<std::string, const Row*> by;
  for (const auto& x : rows) {
    w.merging.add({pt.machine, topo, size, kScene, P, x.contender, fixed(x.ms, 3), num(x.messages),
                   num(x.bytes), num(x.max_messages), num(x.max_bytes), fixed(x.network_ms, 3)});
    by[x.contender] = &x;
    if (!best || x.ms < best->ms) best = &x;
    if (radix_of(x.contender, pt.nodes) && (!best_k || x.ms < best_k->ms)) best_k = &x;
    if (x.contender == "binary-swap") swap = &x;
  }
  if (!best) return;
  const int k = best_k ? radix_of(best_k->contender, pt.nodes) : 0;
  w.best.add({pt.machine, topo, size, kScene, P, best->contender, fixed(best->ms, 3),
              k ? std::to_string(k) : "", best_k ? fixed(best_k->ms, 3) : "",
              best_k ? why(*best_k, swap, r["model"]) : ""});
  const auto ms = [&](const char* c) { return by.count(c) ? fixed(by[c]->ms, 1) : "-"; };
  const std::string machine = pt.machine + (pt.topology == Topology::Ring ? " ring" : "");
  auto& top = w.largest[machine];
  if (pt.size == 400 && best_k && pt.nodes > top.first)
    top = {pt.nodes,
           "P = " + P + ", best k = " + std::to_string(k) + ": " + why(*best_k, swap, r["model"])};
  w.md.add({machine, size, P, ms("pair-rs"), ms("aapc-hbp"),
            by.count("folding") ? ms("folding") : ms("binary-swap"), ms("direct-send"),
            k ? std::to_string(k) + " (" + fixed(best_k->ms, 1) + ")" : "-", best->contender});
}

std::string summary(const Written& w) {
  std::string s;
  for (const auto& [machine, top] : w.largest)
    s += "- **" + machine + "**, " + top.second + "\n";
  return s;
}

std::string readme(const Written& w, bool full) {
  return "# Compositing on the 1990s machines: PAIR-RS, AAPC-HBP, binary swap, direct send, "
         "radix-k\n\n"
         "Written by `zcube reproduce compositing" +
         std::string(full ? " --full" : "") +
         "` (src/repro/reproduce_compositing.cpp, algo/compositing_study.cpp; "
         "docs/compositing.md). Scene: Kurc et al.'s 2 POT (scenes/kurc/2pot.json). One "
         "simulation per row: the scene dealt and z-buffered once (Kurc et al.'s first two "
         "phases), the scanline counts summed once, then each contender in turn from the same "
         "local pictures after a barrier, its share of the screen and its strategy timed as a "
         "phase of its own: the largest time of any node, in ms. PAIR-RS and AAPC-HBP composite "
         "Kurc et al.'s winning pixel arrays; binary swap, direct send, radix-k and folding "
         "composite IceT's run-length encoded pixels shared by heuristic bin packing. radix-k "
         "with k = 2 is binary swap and with k = P direct send (tests/compositing). All-to-all "
         "rounds of more than 64 nodes (16 above 256 nodes) are not simulated (host time). Node "
         "memory is not the limit here (1 GiB nodes): the study is about time. Each round's merge "
         "is "
         "charged before the node sends on (docs/compositing.md, \"Limits\"; Kurc et al.'s own "
         "programs charge it when the phase ends, as calibrated).\n\n" +
         w.md.markdown() + "\n## The best k at the largest node count, and why (400x400)\n\n" +
         summary(w) +
         "\n`best k` is the fastest radix-k (binary swap k = 2, direct send k = P). `best.csv` "
         "says why for every row: the start-ups and kilobytes of the busiest node at the best k "
         "and at binary swap, priced at the machine's start-up and per-byte time (`network_ms`, "
         "a lower bound: no hops, no contention); what is left of the phase is the merging CPU "
         "(list merges of the retained and received pixels at every binary-swap stage, a "
         "z-buffer merge of the kept rows in a round of k > 2) and waiting. `merging.csv`: every "
         "contender at every point.\n\nPlots: `merging.png` (time against P per machine, "
         "400x400), `best_k.png`.\n";
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
    SimConfig c = repro_config(pt.machine, pt.nodes, "compositing-study",
                               o.root + "/scenes/kurc/" + kScene + ".json", pt.size);
    c.topology = pt.topology;
    c.overrides.memory_bytes = 1024.0 * 1048576;
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
