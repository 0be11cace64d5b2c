// The probe's entry point: the workloads (probe_workloads.hpp) registered and timed on the harness
// (probe_harness.hpp), then fitted (probe_solve.hpp), alone and at once.
#include "mpi/probe_cpu.hpp"

#include <algorithm>

#include "mpi/premap_heap.hpp"
#include "mpi/probe_groups.hpp"
#include "mpi/probe_solve.hpp"
#include "mpi/probe_workloads.hpp"

namespace zc {

CpuProbe measure_cpu(const std::string& root, double min_seconds, const ProbeRanks& ranks) {
  using namespace cpu_probe;
  premap_heap(std::size_t(1) << 30);
  Probe p{min_seconds, ranks, {}, {}, {}};
  // The bone's 78,738 triangles (a dense mesh as the bunny's, on no workload) at the workloads'
  // sizes and triangle sizes: 512 and 1024 (elastic's bunny at 1024x1024: 2-4 rows and 2 pixels a
  // span), 2048 and 4096 (Kurc's bunny at 5120x5120: 20 rows, 8 pixels a span; a frame buffer of
  // hundreds of megabytes). The thesis's 16 spheres: Blazek's triangles at the workload's size.
  // The bone shuffled: the z-buffer's far lines of a scanned mesh listed without locality (the
  // bunny's file). The bands: the z-buffer without far lines, the spheres' (a triangle a pixel or
  // less) and Figure 9's cubes (spans of hundreds of pixels) beside the bone's; whole pictures
  // then price the far lines alone. MultiScatter's triangle records: the bone's triangles among
  // 1 and 2 nodes. Three bones overlapping, and a pair's node's half of the triangles: the active
  // z-buffer's tested and appended pixels in other proportions than the bone's.
  render_loops(p, load_probe_scene(root + "/scenes/bone.json", 512), false);
  render_loops(p, load_probe_scene(root + "/scenes/bone.json", 1024), false);
  render_loops(p, load_probe_scene(root + "/scenes/bone.json", 2048), false);
  render_loops(p, load_probe_scene(root + "/scenes/bone.json", 4096), true);
  active_loops(p, load_probe_scene(root + "/scenes/bone.json", 4096), false);
  active_loops(p, load_probe_scene(root + "/scenes/bones.json", 2048), true);
  for (int size : {512, 1024, 2048, 4096})
    near_loops(p, load_probe_scene(root + "/scenes/bone.json", size));
  near_loops(p, load_probe_scene(root + "/scenes/blazek/thesis_spheres_16.json", 512));
  near_loops(p, load_probe_scene(root + "/scenes/blazek_fig9.sdl", 4096));
  multiscatter_loops(p, load_probe_scene(root + "/scenes/bone.json", 1024), 1);
  multiscatter_loops(p, load_probe_scene(root + "/scenes/bone.json", 1024), 2);
  sphere_loops(p, load_probe_scene(root + "/scenes/blazek/thesis_spheres_16.json", 512));
  buffer_loops(p, 4096, true);
  buffer_loops(p, 5120, false);
  // Every loop recorded in block order, so a block's loops come after those it subtracts.
  const auto by_block = [](const Loop& a, const Loop& b) { return a.block < b.block; };
  std::stable_sort(p.loops.begin(), p.loops.end(), by_block);
  std::stable_sort(p.loops_alone.begin(), p.loops_alone.end(), by_block);
  CpuProbe out;
  if (!p.loops_alone.empty()) {
    const std::vector<double> k = solve(p.loops_alone, {}, out.alone_log);
    out.alone = {scale_groups(probe_prior(), probe_groups(), k), k};
  }
  // At once, a block of several groups keeps the split rank 0 found alone (solve_block).
  const std::vector<double> alone = ranks.share(out.alone.multipliers);
  const std::vector<double> k = solve(p.loops, alone, out.at_once_log);
  out.at_once = {scale_groups(probe_prior(), probe_groups(), k), k};
  return out;
}

} // namespace zc
