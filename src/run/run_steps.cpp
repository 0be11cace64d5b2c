#include "run/run_steps.hpp"

#include "scene/load.hpp"
#include "util/error.hpp"

namespace zc {

PreparedRun prepare_run(const RunConfig& cfg, const Scene* preloaded, bool cube) {
  PreparedRun p;
  p.algo = cfg.custom ? cfg.custom.get() : &find_algorithm(cfg.algorithm);
  p.options = cfg.options;
  validate_options(*p.algo, p.options, cube);
  if (!preloaded && !cfg.scene_path.empty()) {
    LoadOptions lo;
    lo.width = cfg.width;
    lo.height = cfg.height;
    p.loaded = load_scene(cfg.scene_path, lo);
  }
  p.preloaded = preloaded;
  p.scene_path = preloaded ? preloaded->path : cfg.scene_path;
  if (p.algo->untextured && p.scene().textured())
    throw InputError(p.scene().path, 0,
                     p.algo->name + " renders untextured scenes only (Blazek's renderer "
                                    "had no textures)");
  return p;
}

namespace {

RunHeader header_of(const RunConfig& cfg, const PreparedRun& run, const Executed& done) {
  RunHeader h;
  h.machine = done.machine;
  h.platform = done.platform;
  h.topology = done.topology;
  h.fidelity = done.fidelity;
  h.nodes = done.nodes;
  h.algorithm = run.algo->name;
  // Every option of the algorithm, the defaults included: a report says which variant ran.
  h.options = cfg.options.values;
  for (const auto& o : run.algo->options)
    if (!h.options.contains(o.name)) h.options[o.name] = o.default_value;
  h.frames = cfg.options.frames;
  const Scene& s = run.scene();
  h.scene = {run.scene_path, s.triangles.size(), s.vertices.size(), s.width, s.height};
  return h;
}

} // namespace

RunResult finish_run(const RunConfig& cfg, const PreparedRun& run, Executed done) {
  RunResult res;
  Report& r = res.report;
  r.header = header_of(cfg, run, done);
  r.status = done.failure.empty() ? "ok" : (done.out_of_memory ? "out_of_memory" : "error");
  r.error = done.failure;
  r.virtual_time_s = done.total_s;
  r.metrics_rank = run.algo->metrics_node ? run.algo->metrics_node(run.options) : 0;
  r.records = std::move(done.records);
  res.images = assemble_frames(std::move(done.images), run.scene());
  // An algorithm that draws no picture (a benchmark) has nothing to compare.
  const ImageCheck how{cfg.compare_with_sequential && run.algo->draws_picture, cfg.options.frames,
                       &cfg.reference_lookup};
  if (res.ok()) r.image = check_images(res.images, run.scene(), how);
  r.host.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - run.started).count();
  r.host.peak_rss_bytes = peak_rss_bytes();
  return res;
}

} // namespace zc
