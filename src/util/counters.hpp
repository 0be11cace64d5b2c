#pragma once
// The renderer's work, counted exactly. These counts are what the simulator charges to a modelled
// CPU (machine/cost_table), so every one is deterministic: the same scene gives the same counts on
// any thread count, and a partition of the work across nodes sums to the sequential counts
// (except where an algorithm duplicates work on purpose, e.g. triangles crossing slices).
#include <cstdint>

#include <nlohmann/json_fwd.hpp>

namespace zc {

struct Counters {
  std::uint64_t vertices_transformed = 0;  // model-view-projection + Gouraud lighting of one vertex
  std::uint64_t triangles_in = 0;          // triangles submitted to set-up
  std::uint64_t triangles_culled = 0;      // back-facing (when culling), off-screen or zero-area
  std::uint64_t triangles_clipped = 0;     // triangles that crossed a clip plane
  std::uint64_t triangles_setup = 0;       // screen triangles set up (after clipping)
  std::uint64_t spans = 0;                 // non-empty (row, triangle) spans rasterised
  std::uint64_t pixels_generated = 0;      // fragments produced (TPG of Kurc et al.)
  std::uint64_t pixels_tested = 0;         // depth comparisons against a frame-buffer location
  std::uint64_t pixels_written = 0;        // fragments that won their depth test
  std::uint64_t pixels_final = 0;          // covered pixels of the final image (TPF)
  std::uint64_t texels_fetched = 0;        // texture samples (0 for an untextured scene)
  std::uint64_t pixels_cleared = 0;        // frame/z-buffer locations initialised
  std::uint64_t merge_ops = 0;             // z-buffer locations compared while merging z-buffers
  std::uint64_t bytes_packed = 0;          // bytes copied into or out of message buffers
  std::uint64_t triangles_estimated = 0;   // per-triangle load estimates (Charles et al. §5)
  std::uint64_t rows_scanned = 0;          // per-row passes: prefix scans, partitions, row counts
  std::uint64_t triangles_tessellated = 0; // polygons made from primitive descriptions (Blazek)
  // One loop each of Kurc et al.'s active pixels (raster/active_pixels.hpp), priced apart from the
  // frame-buffer loops above (docs/machines.md, "One cost per loop"):
  std::uint64_t list_merges = 0; // pixels of two x-sorted pixel lists merged into a new list (§3.1)
  std::uint64_t wpa_tested = 0;  // depth comparisons through the MSA against a WPA entry (§2)
  std::uint64_t wpa_appended = 0; // fragments appended to the WPA without comparison (§2)
  // Loops that profiling the MPI backend's runs found uncounted (docs/machines.md, "Loops the
  // profiler found"):
  std::uint64_t edge_walks = 0;        // triangles' edges set up to walk their rows (a pass each)
  std::uint64_t span_starts = 0;       // spans started: start values from the planes
  std::uint64_t sort_steps = 0;        // comparison-sort steps: n ceil(log2 n) for a list of n
  std::uint64_t records_packed = 0;    // records gathered into / scattered out of messages
  std::uint64_t locations_scanned = 0; // z-buffer locations read for their coverage, in a scan
  // zcube's own work for its messages, which the papers' programs (their arrays sent in place) do
  // not do: 0 on the iPSC machines, probed on this one (docs/machines.md, "zcube's own loops"):
  std::uint64_t wire_records = 0; // pixels converted to or from zcube's wire records for a merge
  std::uint64_t wire_bytes = 0;   // bytes copied into a message the modelled program sends in place
  // Found by the MPI backend's runs on a machine with caches (docs/machines.md, "The order of the
  // triangles"; "A triangle record is not a pixel record"):
  std::uint64_t far_lines = 0;        // depth-buffer lines entered from outside RecentLines' window
  std::uint64_t triangles_packed = 0; // triangle records gathered into / read out of messages
  std::uint64_t records_fetched = 0;  // set-up records a span loop read from outside RecentRecords
  std::uint64_t distant_lines = 0;    // far lines outside RecentLines' last-level-cache window too

  Counters& operator+=(const Counters& o);
  friend Counters operator+(Counters a, const Counters& b) { return a += b; }
  Counters operator-(const Counters& o) const;
  bool operator==(const Counters&) const = default;
};

// The steps a comparison sort counts for a list of n records: n ceil(log2 n) (a merge sort's
// passes).
constexpr std::uint64_t sort_steps(std::uint64_t n) {
  std::uint64_t log = 0;
  while ((std::uint64_t(1) << log) < n)
    ++log;
  return n * log;
}

void to_json(nlohmann::json& j, const Counters& c);
void from_json(const nlohmann::json& j, Counters& c); // absent fields are 0
// The fields that are not zero (what a report keeps of a phase's operations).
nlohmann::json nonzero_json(const Counters& c);

// Every counter field, for code that must treat them uniformly (cost tables, reports):
// ZC_COUNTER_FIELDS(X) expands X(name) once per field, in declaration order.
#define ZC_COUNTER_FIELDS(X)                                                                       \
  X(vertices_transformed)                                                                          \
  X(triangles_in)                                                                                  \
  X(triangles_culled)                                                                              \
  X(triangles_clipped)                                                                             \
  X(triangles_setup)                                                                               \
  X(spans)                                                                                         \
  X(pixels_generated)                                                                              \
  X(pixels_tested)                                                                                 \
  X(pixels_written)                                                                                \
  X(pixels_final)                                                                                  \
  X(texels_fetched)                                                                                \
  X(pixels_cleared)                                                                                \
  X(merge_ops)                                                                                     \
  X(bytes_packed)                                                                                  \
  X(triangles_estimated)                                                                           \
  X(rows_scanned)                                                                                  \
  X(triangles_tessellated)                                                                         \
  X(list_merges)                                                                                   \
  X(wpa_tested)                                                                                    \
  X(wpa_appended)                                                                                  \
  X(edge_walks)                                                                                    \
  X(span_starts)                                                                                   \
  X(sort_steps)                                                                                    \
  X(records_packed)                                                                                \
  X(locations_scanned)                                                                             \
  X(wire_records)                                                                                  \
  X(wire_bytes)                                                                                    \
  X(far_lines)                                                                                     \
  X(triangles_packed)                                                                              \
  X(records_fetched)                                                                               \
  X(distant_lines)

} // namespace zc
