// Kurc, Aykanat, Ozguc on the simulated iPSC/2: Table 2 (phases at 8 and 16 nodes, 400x400) and
// the speed-ups of the five schemes (1 POT and 2 POT, 400x400 and 640x640, 1..16 nodes).
#include <cmath>

#include "repro/paper_figures.hpp"
#include "repro/reproduce.hpp"
#include "repro/table.hpp"

namespace zc {

namespace {

const std::vector<std::string> kKurcSchemes = {"zbuf-exc", "pair-rs", "pair-hbp", "aapc-rs",
                                               "aapc-hbp"};
const std::vector<int> kKurcNodes = {1, 2, 4, 8, 16};
const std::vector<int> kSizes = {400, 640};
const std::vector<std::string> kSpeedupScenes = {"1pot", "2pot"};

std::string scene_path(const ReproduceOptions& o, const std::string& s) {
  return o.root + "/scenes/kurc/" + s + ".json";
}

double phase_ms(const nlohmann::json& r, const std::string& phase) {
  for (const auto& p : r["phases"])
    if (p["name"] == phase) return p["max_s"].get<double>() * 1e3;
  return 0;
}

// The phase's band (docs/uncertainty.md), "p05" or "p95", in ms; "" without one.
std::string phase_band_ms(const nlohmann::json& r, const std::string& phase, const char* q) {
  for (const auto& p : r["phases"])
    if (p["name"] == phase && p.contains("bands"))
      return fixed(p["bands"][q].get<double>() * 1e3, 1);
  return "";
}

std::string band_num(double v) {
  return std::isfinite(v) ? num(v, 4) : "";
}

std::string t2_key(int n, const std::string& scene, const std::string& scheme) {
  return "t2/" + std::to_string(n) + "/" + scene + "/" + scheme;
}
std::string seq_key(const std::string& scene, int size) {
  return "seq/" + scene + "/" + std::to_string(size);
}
std::string su_key(const std::string& scheme, const std::string& scene, int size, int n) {
  return "su/" + scheme + "/" + scene + "/" + std::to_string(size) + "/" + std::to_string(n);
}

// The representative runs drawn as space-time diagrams: AAPC-HBP beside PAIR-RS, 2 POT, 16 nodes.
std::vector<GanttChart> kurc_gantt() {
  return {{su_key("aapc-hbp", "2pot", 400, 16), "gantt_aapc-hbp.png", "AAPC-HBP, 2 POT, 16 nodes"},
          {su_key("pair-rs", "2pot", 400, 16), "gantt_pair-rs.png", "PAIR-RS, 2 POT, 16 nodes"}};
}

const KurcPhaseFigure* paper_figure(const std::string& scene, const std::string& scheme,
                                    const std::string& phase) {
  for (const auto& f : kurc_table2_p16())
    if (f.scene == scene && f.scheme == scheme && f.phase == phase) return &f;
  return nullptr;
}

// table2.csv under dir; returns its README table and the 16-node errors against the paper.
std::pair<Table, std::vector<double>> write_kurc_table2(const Reports& reps,
                                                        const std::string& dir) {
  // table2.csv and its README table.
  Table t2{{"nodes", "scene", "algorithm", "phase", "status", "predicted_ms", "predicted_p05_ms",
            "predicted_p95_ms", "paper_ms"},
           {}};
  Table md{
      {"scene", "scheme", "phase", "P=8 predicted", "P=16 predicted", "P=16 paper", "P=16 error"},
      {}};
  std::vector<double> errs;
  for (int n : {8, 16})
    for (const auto& s : kurc_scenes())
      for (const char* sch : {"pair-rs", "zbuf-exc"}) {
        const auto& r = reps.at(t2_key(n, s, sch));
        for (const auto& ph : kurc_phases()) {
          const KurcPhaseFigure* f = n == 16 ? paper_figure(s, sch, ph) : nullptr;
          const bool run = ok(r);
          t2.add({std::to_string(n), s, sch, ph, status_of(r), run ? fixed(phase_ms(r, ph), 1) : "",
                  run ? phase_band_ms(r, ph, "p05") : "", run ? phase_band_ms(r, ph, "p95") : "",
                  f ? num(f->ms) : ""});
        }
      }
  for (const auto& s : kurc_scenes())
    for (const char* sch : {"pair-rs", "zbuf-exc"})
      for (const auto& ph : kurc_phases()) {
        const auto& r8 = reps.at(t2_key(8, s, sch));
        const auto& r16 = reps.at(t2_key(16, s, sch));
        const KurcPhaseFigure* f = paper_figure(s, sch, ph);
        const double p16 = phase_ms(r16, ph);
        const double e = f ? (p16 - f->ms) / f->ms : 0;
        if (f && ok(r16)) errs.push_back(e);
        md.add({s, sch, ph, ok(r8) ? fixed(phase_ms(r8, ph), 0) : "oom",
                ok(r16) ? fixed(p16, 0) : "oom", f ? num(f->ms) : "", f ? percent(e) : ""});
      }
  t2.write_csv(dir + "/table2.csv");

  return {md, errs};
}

// speedup.csv and measures.csv under dir; returns the README's speed-up table.
Table write_kurc_speedups(const Reports& reps, const std::string& dir) {
  // speedup.csv and measures.csv: timed_s (the three phases, on the critical node) is the time
  // the speed-up divides, as in zcube sweep; virtual_s is the whole run.
  Table su{{"algorithm", "scene", "width", "height", "nodes", "status", "virtual_s", "timed_s",
            "speedup", "speedup_p05", "speedup_p95"},
           {}};
  Table me{{"algorithm", "scene", "width", "height", "nodes", "status", "concurrent_volume_bytes",
            "load_imbalance", "tpg", "tpf"},
           {}};
  Table su_md{{"scene", "size", "scheme", "P=2", "P=4", "P=8", "P=16"}, {}};
  for (const auto& sch : kKurcSchemes)
    for (const auto& s : kSpeedupScenes)
      for (int size : kSizes) {
        const auto& base = reps.at(seq_key(s, size));
        std::vector<std::string> mdrow = {s, std::to_string(size), sch};
        const std::string w = std::to_string(size);
        for (int n : kKurcNodes) {
          const auto& r = reps.at(su_key(sch, s, size, n));
          if (!ok(r) || !ok(base)) {
            const std::string st = status_of(ok(r) ? base : r);
            su.add({sch, s, w, w, std::to_string(n), st, "", "", "", "", ""});
            me.add({sch, s, w, w, std::to_string(n), st, "", "", "", ""});
            if (n > 1) mdrow.push_back(st == "out_of_memory" ? "oom" : st);
            continue;
          }
          const double t = timed_s(r), sp = timed_s(base) / t;
          const auto [lo, hi] = ratio_band(band_timed_s(base), band_timed_s(r));
          su.add({sch, s, w, w, std::to_string(n), "ok", num(whole_run_s(r)), num(t), num(sp, 4),
                  band_num(lo), band_num(hi)});
          if (n > 1) mdrow.push_back(fixed(sp, 2));
          const auto& k = r.value("kurc", nlohmann::json::object());
          me.add({sch, s, w, w, std::to_string(n), "ok",
                  num(r["communication"].value("concurrent_volume_bytes", 0.0)),
                  num(r.value("load_imbalance", 0.0), 4), num(k.value("tpg", 0.0)),
                  num(k.value("tpf", 0.0))});
        }
        su_md.add(mdrow);
      }
  su.write_csv(dir + "/speedup.csv");
  me.write_csv(dir + "/measures.csv");

  return su_md;
}

std::string write_kurc(const Reports& reps, const std::string& dir) {
  const auto [md, errs] = write_kurc_table2(reps, dir);
  const Table su_md = write_kurc_speedups(reps, dir);
  double rms = 0;
  for (double e : errs)
    rms += e * e;
  rms = errs.empty() ? 0 : std::sqrt(rms / double(errs.size()));
  write_text(
      dir + "/README.md",
      "# Kurc, Aykanat, Ozguc: active pixel merging on the simulated iPSC/2\n\n"
      "Written by `zcube reproduce kurc` (src/repro/reproduce_kurc.cpp). Paper: "
      "Kurç, Aykanat, Özgüç, *Active Pixel Merging on Hypercube Multicomputers* (Bilkent "
      "University). Scenes: scenes/kurc/ (teapot "
      "arrangements fitted to Table 1, see scenes/README.md). Machine: the calibrated iPSC/2 model "
      "(`zcube platform --machine ipsc2`), circuit fidelity, 4 MB nodes.\n\n"
      "**The 16-node figures of Table 2 are the calibration's targets** (results/calibration/): "
      "their errors below are fit residuals, not an independent check. The 8-node rows (held out "
      "in the seed) and the speed-ups are predictions.\n\n"
      "## Table 2: time per phase (ms), 400x400\n\n"
      "Predicted = the largest time of any node in the phase (`phases[].max_s`). RMS relative "
      "error over the 36 printed figures: " +
          percent(rms).substr(1) + ".\n\n" + md.markdown() +
          "\n## Speed-ups (speedup.csv)\n\n"
          "Speed-up = T(`scanline`, 1 node) / T(scheme, P), T the paper's timed region on both "
          "sides: the three phases above, the longest time one node spent in them (`timed_s`, "
          "the same T as `zcube sweep`'s speed-ups; `virtual_s` is the whole run): neither "
          "counts the distribution of the triangles nor the output of the picture. The baseline "
          "`scanline` is the paper's "
          "sequential rendering of §1-§2 "
          "with every polygon on one 4 MB node: span lists and the modified scanline z-buffer, "
          "no merging and no frame buffer (docs/papers.md). `oom` (`status` "
          "`out_of_memory` in the CSV): a node (or the baseline) runs out of its 4 MB, operating "
          "system included (docs/memory.md), as the paper's "
          "`*` entries. The paper's own speed-up figure is held out.\n\n" +
          su_md.markdown() +
          "\n`measures.csv`: concurrent communication volume (the sum over steps of the largest "
          "message volume), load imbalance of the merge loads ((max - min) / mean, Fig. 2), TPG "
          "and TPF for every point. `table1.csv` (not written here): the fit of the six scenes to "
          "Table 1 by scripts/kurc_scenes.py.\n\nPlots: `table2.png` (phase bars, paper hatched), "
          "`speedup.png`.\n" +
          gantt_markdown(kurc_gantt()));
  return "";
}

} // namespace

PaperPlan kurc_plan(const ReproduceOptions& o) {
  PaperPlan p;
  p.name = "kurc";
  for (int n : {8, 16})
    for (const auto& s : kurc_scenes())
      for (const char* sch : {"pair-rs", "zbuf-exc"})
        p.points.push_back(
            {t2_key(n, s, sch), repro_config("ipsc2", n, sch, scene_path(o, s), kKurcTableSize)});
  // The speed-ups' baseline (docs/papers.md): the modified scanline z-buffer of §2 on one 4 MB
  // node of the same machine (`scanline`: every polygon local, no merging, no frame buffer).
  for (const auto& s : kSpeedupScenes)
    for (int size : kSizes)
      p.points.push_back(
          {seq_key(s, size), repro_config("ipsc2", 1, "scanline", scene_path(o, s), size)});
  for (const auto& sch : kKurcSchemes)
    for (const auto& s : kSpeedupScenes)
      for (int size : kSizes)
        for (int n : kKurcNodes)
          p.points.push_back(
              {su_key(sch, s, size, n), repro_config("ipsc2", n, sch, scene_path(o, s), size)});
  p.gantt = kurc_gantt();
  p.write = write_kurc;
  with_bands(p);
  return p;
}

} // namespace zc
