#include "mpi/probe_groups.hpp"

#include "machine/cpu_model.hpp"

namespace zc::cpu_probe {

const std::vector<CounterGroup>& probe_groups() {
  static const std::vector<CounterGroup> g = {
      {"vertex", {"vertices_transformed"}},
      {"triangle", {"triangles_in", "triangles_culled", "triangles_clipped", "triangles_setup"}},
      {"estimate", {"triangles_estimated", "rows_scanned"}},
      {"tessellate", {"triangles_tessellated"}},
      {"clear", {"pixels_cleared"}},
      {"packing", {"bytes_packed", "wire_bytes"}},
      {"merge", {"merge_ops"}},
      {"list_merge", {"list_merges"}},
      {"records", {"records_packed"}},
      {"triangle records", {"triangles_packed"}},
      {"edges", {"edge_walks"}},
      {"spans", {"spans", "span_starts"}},
      {"pixels",
       {"pixels_generated", "pixels_tested", "pixels_written", "pixels_final", "texels_fetched"}},
      {"far lines", {"far_lines"}},
      {"distant lines", {"distant_lines"}},
      {"sort", {"sort_steps"}},
      {"wpa tested", {"wpa_tested"}},
      {"wpa appended", {"wpa_appended"}},
      {"record fetches", {"records_fetched"}},
      {"scan", {"locations_scanned"}},
      {"wire", {"wire_records"}}};
  return g;
}

const std::vector<LoopBlock>& loop_blocks() {
  static const std::vector<LoopBlock> b = {
      {"project", {kVertex}},
      {"set-up", {kTriangle}},
      {"load estimate", {kEstimate}},
      {"tessellate", {kTessellate}},
      {"clear", {kClear}},
      {"location packing", {kPacking}},
      {"location merge", {kMerge}},
      {"active merge", {kListMerge}},
      {"wire records", {kWire}},
      {"sparse output", {kRecords}},
      {"dense output", {kScan}},
      {"multiscatter", {kTriangleRecords}},
      // The frame-buffer z-buffer in a band of rows whose depth the recent-lines window holds (no
      // far line): a triangle's edges, its spans (found and started), its fragments; the scenes'
      // and sizes' different mixes separate them.
      {"near z-buffer", {kEdges, kSpans, kPixels}},
      // The frame-buffer z-buffer on whole pictures, less the above: its far lines (the scattered
      // orders: the same triangles, other far lines), and of them the distant ones, from main
      // memory rather than the last-level cache's share (the bone at 1024, 2048 and 4096: frame
      // buffers of 12, 50 and 200 MB; at 512, 3 MB, it has none).
      {"z-buffer", {kFarLines, kDistantLines}},
      {"span lists", {kSort}},
      // Kurc et al.'s active z-buffer, less its span starts and fragments: a pixel tested through
      // the MSA and one appended to the WPA, apart (zcube's loop appends at a far higher cost
      // than it tests, the reverse of the 80386's mixes). The bone at every size
      // appends one pixel for three tested; its triangles dealt to two nodes two for three, the
      // three bones one for ten (the twelve bunnies' mix) and dealt to two nodes one for five.
      // A span's set-up record fetched from memory (records_fetched), with them: every active loop
      // fetches some, at rates its mix does not follow (from a few to a third of its spans,
      // depending on the scene and size), so the three groups are one block.
      {"active z-buffer", {kWpaTested, kWpaAppended, kRecordFetches}}};
  return b;
}

// The table the probe's multipliers scale: the 80386's physical estimates, and for a far line, a
// distant line (what it costs beyond a far line) and a set-up record fetched (nothing on the
// 80386, whose memory has one level: operations.json) a nominal 100 ns, a DRAM access of this
// era, their multipliers a fraction of it.
CostTable probe_prior() {
  CostTable t = zcube_loop_seconds(cpu_model("i80386"));
  t.far_lines = 100e-9;
  t.records_fetched = 100e-9;
  t.distant_lines = 100e-9;
  return t;
}

} // namespace zc::cpu_probe
