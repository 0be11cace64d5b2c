#pragma once
// Charles, Lefevre, Miguet 1995: the two ways a node learns the projected vertices of its
// triangles. Each is a small policy the node program (elastic.cpp) is instantiated with:
//   exchange()  the communication step, one report phase;
//   at(id)      a projected vertex the node's own triangles use;
//   Record      what MultiScatter(Triangles) sends per triangle and slice;
//   record()/triangle()/vertices()  making and reading such a record.
#include <cstdint>
#include <cstring>
#include <span>
#include <unordered_map>
#include <vector>

#include "algo/charles/elastic_steps.hpp"
#include "algo/records.hpp"
#include "comm/wire.hpp"
#include "util/block_split.hpp"

namespace zc::elastic {

// §4 MultiBroadcast(Projected Vertices): every node receives all of them, so a triangle travels
// as its bare record.
// The node reads them in place in the blocks it received: those blocks' payloads are the senders',
// shared by every node of the simulation (the modelled node holds its own copy of all of them, and
// is charged for it: `bytes`).
struct BroadcastVertices {
  using Record = TriangleRecord;
  std::vector<Message> blocks;                         // node k's projected vertices, by k
  std::vector<std::span<const ProjectedVertex>> block; // the same, read in place
  std::size_t scene_vertices = 0; // V: node k holds the ids of block_range(V, P, k)
  double bytes = 0;               // held by the node (modelled memory)

  void exchange(NodeContext& ctx, const LocalScene& local,
                const std::vector<ProjectedVertex>& mine);
  const ProjectedVertex& at(std::uint32_t id) const {
    const int P = int(block.size());
    const int k = block_of(scene_vertices, P, id);
    return block[std::size_t(k)][id - block_begin(scene_vertices, P, k)];
  }
  Record record(const TriangleRecord& t) const { return t; }
  // What a MultiScatter record carries besides the triangle's wire form: nothing (and what the
  // modelled machine is charged for it, records.hpp).
  static constexpr std::size_t kExtraWireBytes = 0, kExtraRecordBytes = 0;
  void append_extra(Bytes&, const TriangleRecord&) const {}
  static Record from_wire(const TriangleRecord& t, const std::uint8_t*) { return t; }
  static const TriangleRecord& triangle(const Record& r) { return r; }
  void vertices(const Record& r, const ProjectedVertex* p[3]) const {
    for (int k = 0; k < 3; ++k)
      p[k] = &at(r.tri.v[k]);
  }
};

// §7 (the paper's future work): each node asks the owners for only the vertices its triangles use
// (request/answer), so a triangle crossing to another slice carries its projected vertices along.
struct RequestedVertices {
  struct Record {
    TriangleRecord t;
    ProjectedVertex pv[3];
  };
  std::unordered_map<std::uint32_t, ProjectedVertex> known; // the needed ones
  double bytes = 0;

  void exchange(NodeContext& ctx, const LocalScene& local,
                const std::vector<ProjectedVertex>& mine);
  const ProjectedVertex& at(std::uint32_t id) const { return known.at(id); }
  Record record(const TriangleRecord& t) const {
    return {t, {at(t.tri.v[0]), at(t.tri.v[1]), at(t.tri.v[2])}};
  }
  // A MultiScatter record carries the triangle's three projected vertices.
  static constexpr std::size_t kExtraWireBytes = 3 * sizeof(ProjectedVertex),
                               kExtraRecordBytes = 3 * records::charles::kProjectedVertex;
  void append_extra(Bytes& b, const TriangleRecord& t) const {
    for (int k = 0; k < 3; ++k)
      append(b, &at(t.tri.v[k]), 1);
  }
  static Record from_wire(const TriangleRecord& t, const std::uint8_t* extra) {
    Record r{t, {}};
    std::memcpy(r.pv, extra, kExtraWireBytes);
    return r;
  }
  static const TriangleRecord& triangle(const Record& r) { return r.t; }
  static void vertices(const Record& r, const ProjectedVertex* p[3]) {
    for (int k = 0; k < 3; ++k)
      p[k] = &r.pv[k];
  }
};

} // namespace zc::elastic
