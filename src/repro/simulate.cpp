#include "repro/simulate.hpp"

#include <malloc.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <thread>
#include <tuple>

#include "algo/algorithm.hpp"
#include "raster/renderer.hpp"
#include "raster/setup_cache.hpp"
#include "repro/paper_figures.hpp"
#include "run/report.hpp"
#include "scene/load.hpp"
#include "sim/bands.hpp"
#include "sim/platform_load.hpp"
#include "sim/replay.hpp"
#include "sim/simulation.hpp"

namespace zc {

namespace {

// Scenes loaded once in the process that runs a batch, before it forks the simulations: each
// forked simulation inherits them (copy-on-write) instead of reading and tessellating its scene
// again (Blazek's spheres, Kurc's pots: most points of `zcube reproduce` share a scene with
// others, and the calibration's fit steps run the same six scenes over and over).
using SceneKey = std::tuple<std::string, int, int>;
std::map<SceneKey, std::shared_ptr<const Scene>>& scene_cache() {
  static std::map<SceneKey, std::shared_ptr<const Scene>> cache;
  return cache;
}

SceneKey scene_key(const RunConfig& c) {
  return {c.scene_path, c.width, c.height};
}

// A scene is kept while the cache holds at most this many triangles (Blazek --full's largest
// sphere scenes are loaded by their own simulations, as before).
constexpr std::size_t kCacheTriangles = 4'000'000;

// Loads the scenes two or more points use and the cache lacks, `jobs` at a time. A scene that
// fails to load is left to its simulations, which report the error as before.
void preload_scenes(const std::vector<RunConfig>& points, int jobs) {
  auto& cache = scene_cache();
  std::map<SceneKey, int> uses;
  for (const auto& p : points)
    if (!p.scene_path.empty()) ++uses[scene_key(p)];
  std::vector<SceneKey> todo;
  for (const auto& [k, n] : uses)
    if (n >= 2 && !cache.contains(k)) todo.push_back(k);
  std::vector<std::shared_ptr<const Scene>> loaded(todo.size());
  std::vector<std::thread> workers;
  const int n = std::min<int>(std::max(1, jobs), int(todo.size()));
  for (int w = 0; w < n; ++w)
    workers.emplace_back([&, w] {
      for (std::size_t i = std::size_t(w); i < todo.size(); i += std::size_t(n)) {
        try {
          LoadOptions lo;
          lo.width = std::get<1>(todo[i]);
          lo.height = std::get<2>(todo[i]);
          loaded[i] = std::make_shared<const Scene>(load_scene(std::get<0>(todo[i]), lo));
        } catch (const std::exception&) {
        }
      }
    });
  for (auto& t : workers)
    t.join();
  std::size_t held = 0;
  for (const auto& [k, s] : cache)
    held += s->triangles.size();
  for (std::size_t i = 0; i < todo.size(); ++i)
    if (loaded[i] && held + loaded[i]->triangles.size() <= kCacheTriangles) {
      held += loaded[i]->triangles.size();
      cache.emplace(todo[i], std::move(loaded[i]));
    }
}

// The sequential renderer's pictures that points compare their images with, drawn once in the
// process that forks the batch (each simulation would otherwise draw its own: a whole render of
// the scene per point). Keyed by the cached scene, the frame and the run's frame count.
using ReferenceKey = std::tuple<const Scene*, int, int>;
std::map<ReferenceKey, ReferenceFrame>& reference_cache() {
  static std::map<ReferenceKey, ReferenceFrame> cache;
  return cache;
}

const Scene* cached_scene(const RunConfig& c) {
  const auto& cache = scene_cache();
  const auto it = c.scene_path.empty() ? cache.end() : cache.find(scene_key(c));
  return it == cache.end() ? nullptr : it->second.get();
}

bool compares_image(const RunConfig& c) {
  if (!c.compare_with_sequential || c.custom) return false;
  try {
    return find_algorithm(c.algorithm).draws_picture;
  } catch (const std::exception&) {
    return false; // an unknown algorithm: its simulation reports the error
  }
}

// Draws, `jobs` at a time, the references two or more points of a cached scene compare with.
void prepare_references(const std::vector<RunConfig>& points, int jobs) {
  auto& refs = reference_cache();
  std::map<ReferenceKey, int> uses;
  for (const auto& p : points)
    if (const Scene* s = compares_image(p) ? cached_scene(p) : nullptr)
      for (int f = 0; f < p.options.frames; ++f)
        ++uses[{s, f, p.options.frames}];
  // The references no point of this batch compares with are dropped before it forks (as the
  // scenes are, drop_unused_scenes).
  std::erase_if(refs, [&uses](const auto& r) { return !uses.contains(r.first); });
  std::vector<ReferenceKey> todo;
  for (const auto& [k, n] : uses)
    if (n >= 2 && !refs.contains(k)) todo.push_back(k);
  std::vector<ReferenceFrame> drawn(todo.size());
  std::vector<std::thread> workers;
  const int n = std::min<int>(std::max(1, jobs), int(todo.size()));
  for (int w = 0; w < n; ++w)
    workers.emplace_back([&, w] {
      for (std::size_t i = std::size_t(w); i < todo.size(); i += std::size_t(n)) {
        const auto& [scene, frame, frames] = todo[i];
        drawn[i] = reference_frame(*scene, frame, frames);
      }
    });
  for (auto& t : workers)
    t.join();
  for (std::size_t i = 0; i < todo.size(); ++i)
    refs.emplace(todo[i], std::move(drawn[i]));
}

// A reference prepare_references drew (inherited by the batch's forked children), or null.
const ReferenceFrame* drawn_reference(const Scene& scene, int frame, int frames) {
  const auto& r = reference_cache();
  const auto it = r.find({&scene, frame, frames});
  return it == r.end() ? nullptr : &it->second;
}

// The set-up of the cached scenes' triangles (raster/setup_cache.hpp), worked out before the batch
// forks: its points then copy each triangle's set-up instead of computing it. A scene is held when
// kSetupCacheUses points or more use it (a cache used twice barely pays for its building and its
// mapping into each child), most triangles times uses first, up to kSetupCacheTriangles in all
// (about 200 bytes a triangle: Blazek's four sphere scenes, 700,000 triangles, are 135 MB). Caches
// of scenes this batch does not use are dropped.
constexpr std::size_t kSetupCacheUses = 3;
constexpr std::size_t kSetupCacheTriangles = 1'000'000;

void prepare_setup_caches(const std::vector<RunConfig>& points) {
  // ZCUBE_SETUP_CACHE=0: every node sets up its triangles itself (a check, and a baseline).
  if (const char* v = std::getenv("ZCUBE_SETUP_CACHE"); v && std::string(v) == "0") {
    drop_setup_caches([](const Scene&) { return false; });
    return;
  }
  std::map<const Scene*, std::size_t> uses;
  for (const auto& p : points)
    if (const Scene* s = cached_scene(p); s && !s->textured()) ++uses[s];
  std::vector<std::pair<double, std::shared_ptr<const Scene>>> by_work;
  for (const auto& [k, s] : scene_cache())
    if (const auto it = uses.find(s.get()); it != uses.end() && it->second >= kSetupCacheUses)
      by_work.push_back({double(it->second) * double(s->triangles.size()), s});
  std::stable_sort(by_work.begin(), by_work.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::set<const Scene*> chosen;
  std::vector<std::shared_ptr<const Scene>> todo;
  std::size_t held = 0;
  for (const auto& [work, s] : by_work)
    if (held + s->triangles.size() <= kSetupCacheTriangles) {
      held += s->triangles.size();
      chosen.insert(s.get());
      if (!has_setup_cache(*s)) todo.push_back(s);
    }
  drop_setup_caches([&chosen](const Scene& s) { return chosen.contains(&s); });
  // Built here, one after the other, not on worker threads: a thread's temporaries stay in its
  // malloc arena, which the batch collapses into huge pages (copying it) before forking.
  for (const auto& s : todo) {
    try {
      add_setup_cache(std::make_unique<const SetupCache>(
          s, NodeRenderer(*s, s->camera, scene_facts(*s).bounds)));
    } catch (const std::bad_alloc&) {
      // No memory file (memfd_create refused) or no memory for it: this scene's points set up
      // their triangles themselves, as without the cache.
    }
  }
}

// The cached scenes no point of `points` uses, and the references drawn from them, dropped before
// the batch forks: each fork copies the page tables of all the memory the parent holds (the
// calibration's runs, on Kurc's pots alone, would otherwise each copy those of Blazek's spheres).
void drop_unused_scenes(const std::vector<RunConfig>& points) {
  std::set<SceneKey> used;
  for (const auto& p : points)
    used.insert(scene_key(p));
  auto& cache = scene_cache();
  auto& refs = reference_cache();
  for (auto it = cache.begin(); it != cache.end();) {
    if (used.contains(it->first)) {
      ++it;
      continue;
    }
    const Scene* gone = it->second.get();
    std::erase_if(refs, [gone](const auto& r) { return std::get<0>(r.first) == gone; });
    drop_setup_caches([gone](const Scene& s) { return &s != gone; });
    it = cache.erase(it);
  }
}

// A point's host work, roughly: every node touches the picture and the triangles (a 1024-node
// Kurc run costs 100 times a 16-node one, a Blazek run with half a million triangles more than a
// Kurc run of the same nodes), twice under the flow model (SimGrid's bandwidth sharing).
double estimated_cost(const RunConfig& c) {
  const Scene* s = cached_scene(c);
  const double triangles = s ? double(s->triangles.size()) : 0.0;
  const double pixels = c.width > 0 && c.height > 0 ? double(c.width) * double(c.height)
                        : s                         ? double(s->width) * double(s->height)
                                                    : 512.0 * 512.0;
  const double work = double(std::max(1, c.nodes)) * (pixels + triangles) * c.options.frames;
  return c.fidelity == Fidelity::Flow ? 2 * work : work;
}

// The points' indices, longest first (stable): a batch ends on short runs, not on one long run
// with the other jobs idle (longest-processing-time scheduling). Which process runs a point
// changes nothing in its report.
std::vector<std::size_t> longest_first(const std::vector<RunConfig>& points) {
  std::vector<double> cost;
  for (const auto& p : points)
    cost.push_back(estimated_cost(p));
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

} // namespace

void attach_paper_figures(nlohmann::json& report) {
  if (auto paper = paper_figures_for(report); !paper.empty()) report["paper"] = paper;
}

nlohmann::json report_with_paper_figures(const Report& report) {
  nlohmann::json j = report_json(report);
  attach_paper_figures(j);
  return j;
}

namespace {
std::vector<std::string>& batch_simgrid_args() {
  static std::vector<std::string> a;
  return a;
}
} // namespace

void set_batch_simgrid_args(std::vector<std::string> args) {
  batch_simgrid_args() = std::move(args);
}

nlohmann::json program_inputs(const RunConfig& c) {
  return {{"algorithm", c.algorithm},
          {"options", c.options.values},
          {"frames", c.options.frames},
          {"scene", c.scene_path},
          {"width", c.width},
          {"height", c.height},
          {"nodes", c.nodes},
          {"topology", topology_name(c.topology)},
          {"compare", c.compare_with_sequential}};
}

namespace {

// The point with this process's batch SimGrid settings after its own.
RunConfig with_batch_args(const RunConfig& cfg) {
  RunConfig c = cfg;
  const auto& extra = batch_simgrid_args();
  c.simgrid_args.insert(c.simgrid_args.end(), extra.begin(), extra.end());
  c.reference_lookup = drawn_reference;
  return c;
}

// The node count and topology a platform file gives are checked by the replay. A point that draws
// a timeline runs in full (its report is the full run's in any case).
std::string replay_key(const RunConfig& c) {
  if (c.custom || c.timeline) return "";
  return program_inputs(c).dump();
}

// The point's bands (sim/bands.hpp) when it asks for them, from the trace its run recorded or
// replayed.
void attach_bands(const RunConfig& cfg, RunResult& r, const CallTrace* t, const PlatformModel& pm) {
  if (cfg.band_draws <= 0 || !r.ok()) return;
  const BandsRequest req{.draws = cfg.band_draws, .seed = cfg.band_seed};
  if (t)
    add_bands(r.report, *t, pm, cfg, req);
  else
    mark_unavailable(r.report, req, "the run read the clock: its calls may depend on the times");
}

nlohmann::json record_point(const RunConfig& cfg, std::vector<std::uint8_t>* trace) {
  if (!trace && cfg.band_draws <= 0) return simulate_point(cfg);
  std::shared_ptr<CallTrace> t;
  PlatformModel pm;
  RunResult r = record_simulation(with_batch_args(cfg), cached_scene(cfg), t, &pm);
  if (t && trace) *trace = t->serialize();
  attach_bands(cfg, r, t.get(), pm);
  return report_with_paper_figures(r.report);
}

std::optional<nlohmann::json> replay_point(const RunConfig& cfg,
                                           const std::vector<std::uint8_t>& trace) {
  auto t = std::make_shared<const CallTrace>(CallTrace::parse(trace));
  PlatformModel pm;
  std::optional<RunResult> r =
      replay_simulation(with_batch_args(cfg), cached_scene(cfg), t, nullptr, &pm);
  if (!r) return std::nullopt;
  attach_bands(cfg, *r, t.get(), pm);
  return report_with_paper_figures(r->report);
}

// Record and replay is on unless ZCUBE_REPLAY=0 (every point then runs in full, as a check).
bool replay_enabled() {
  const char* v = std::getenv("ZCUBE_REPLAY");
  return !v || std::string(v) != "0";
}

std::vector<nlohmann::json>
replaying_batch(const std::vector<RunConfig>& points, int jobs,
                const std::function<void(const BatchProgress&)>& progress, bool keep) {
  static TraceStore traces; // the kept ones
  std::map<std::string, int> uses;
  for (const auto& p : points)
    ++uses[replay_key(p)];
  // A recording nobody replays costs its trace: only the keys two points share record, unless
  // the traces are kept for later batches.
  const auto key = [&uses, keep](const RunConfig& c) {
    std::string k = replay_key(c);
    return keep || traces.contains(k) || uses[k] >= 2 ? k : std::string();
  };
  TraceStore fresh;
  TraceStore& store = keep ? traces : fresh;
  if (!keep)
    for (const auto& [k, n] : uses)
      if (const auto it = traces.find(k); it != traces.end()) fresh.insert(*it);
  ReplayCounts counts;
  auto reports = run_batch_replaying(points, jobs, {key, record_point, replay_point}, store,
                                     progress, &counts);
  if (std::getenv("ZCUBE_REPLAY_STATS"))
    std::cerr << "replay: " << counts.full << " full, " << counts.recorded << " recorded, "
              << counts.replayed << " replayed, " << counts.diverged << " diverged\n";
  return reports;
}

} // namespace

namespace {

// Each platform file the points name checked once here, before the batch forks: the forked
// simulations find its text checked and skip the checks. A file that fails is left to its
// simulations, which report the error as before.
void check_platform_files(const std::vector<RunConfig>& points) {
  std::set<std::string> done;
  for (const auto& p : points) {
    if (!is_platform_file(p.machine) || !done.insert(p.machine).second) continue;
    try {
      check_platform_file(p.machine);
    } catch (const std::exception&) {
    }
  }
}

} // namespace

nlohmann::json simulate_point(const RunConfig& cfg) {
  if (cfg.band_draws > 0) return record_point(cfg, nullptr);
  return report_with_paper_figures(run_simulation(with_batch_args(cfg), cached_scene(cfg)).report);
}

std::vector<nlohmann::json>
simulate_batch(const std::vector<RunConfig>& points, int jobs,
               const std::function<void(const BatchProgress&)>& progress, bool keep_traces) {
  drop_unused_scenes(points);
  preload_scenes(points, jobs);
  prepare_references(points, jobs);
  check_platform_files(points);
  prepare_setup_caches(points);
  const std::vector<std::size_t> order = longest_first(points);
  std::vector<RunConfig> sorted;
  for (const std::size_t i : order)
    sorted.push_back(points[i]);
  // The parent's free heap handed back: each fork then copies fewer page-table entries, and a
  // simulation's allocations in it take fresh pages instead of copies of the parent's.
  malloc_trim(0);
  std::vector<nlohmann::json> ran = replay_enabled()
                                        ? replaying_batch(sorted, jobs, progress, keep_traces)
                                        : run_batch(sorted, jobs, simulate_point, progress);
  std::vector<nlohmann::json> reports(points.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    reports[order[k]] = std::move(ran[k]);
  return reports;
}

} // namespace zc
