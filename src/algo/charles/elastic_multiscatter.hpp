#pragma once
// Charles, Lefevre, Miguet 1995, §4 MultiScatter(Triangles): a node's own loops, apart from the
// exchange (elastic.cpp), so that the probe times the same code (src/mpi/probe_cpu.cpp). Each
// triangle goes to every slice it touches (duplicates, Table 1). A message per slice: the bitmask
// of the sender's block it carries, then their records (elastic_wire.hpp); the records are
// gathered from the block and read back one by one (triangles_packed, both ends).
#include <cstdint>
#include <vector>

#include "algo/charles/elastic_steps.hpp"
#include "algo/charles/elastic_wire.hpp"
#include "comm/payload.hpp"
#include "comm/wire.hpp"
#include "util/block_split.hpp"

namespace zc::elastic {

// What a node sends: one payload a slice, and the triangles each carries.
struct SlicePayloads {
  std::vector<Payload> payloads;
  std::vector<std::size_t> triangles;
};

// The messages from the local block `tris` (rows `extents`) to the P slices of `bounds` (P + 1 row
// boundaries). `w` counts a triangle packed a record gathered.
template <class Vertices>
SlicePayloads pack_slices(const std::vector<TriangleRecord>& tris,
                          const std::vector<RowExtent>& extents, const std::vector<int>& bounds,
                          bool with_material, const Vertices& pv, Counters& w) {
  const int P = int(bounds.size()) - 1;
  std::vector<std::vector<std::uint32_t>> picked(P);
  for (std::size_t i = 0; i < tris.size(); ++i)
    for_each_slice(bounds, extents[i], [&](int k) { picked[k].push_back(std::uint32_t(i)); });
  const std::size_t record_bytes =
      kTriangleWireBytes + (with_material ? 4 : 0) + Vertices::kExtraWireBytes;
  SlicePayloads out;
  out.payloads.reserve(std::size_t(P));
  out.triangles.reserve(std::size_t(P));
  // Most slices get none of the block's triangles (all of them at 1024 nodes but a few): their
  // messages are one same bitmask of no triangle, made once and shared (payloads are immutable).
  Payload nothing;
  for (int k = 0; k < P; ++k) {
    if (picked[k].empty()) {
      if (nothing.empty()) nothing = selection_header(tris.size(), picked[k], 0);
      out.payloads.push_back(nothing);
      out.triangles.push_back(0);
      continue;
    }
    Bytes b = selection_header(tris.size(), picked[k], record_bytes);
    for (auto i : picked[k]) {
      append_triangle(b, tris[i], with_material);
      pv.append_extra(b, tris[i]);
    }
    out.payloads.push_back(std::move(b));
    out.triangles.push_back(picked[k].size());
    w.triangles_packed += picked[k].size();
  }
  return out;
}

// The slice's records, read out of the messages `got` of senders 0..P-1 (sender s holds the
// block block_range(T, P, s) of the scene's T triangles), Bytes or Payloads. `w` counts a
// triangle packed a record read.
template <class Vertices, class Got>
std::vector<typename Vertices::Record> read_slices(const Got& got, std::size_t T,
                                                   bool with_material, std::uint32_t material,
                                                   Counters& w) {
  const int P = int(got.size());
  std::vector<typename Vertices::Record> slice;
  for (int s = 0; s < P; ++s) {
    const BlockRange block = block_range(T, P, s);
    const Bytes& bytes = got[std::size_t(s)];
    RecordReader in(bytes, "multiscatter");
    for (auto i : read_selection(in, block.size())) {
      const TriangleRecord t =
          read_triangle(in, std::uint32_t(block.begin + i), with_material, material);
      slice.push_back(Vertices::from_wire(t, in.get_bytes(Vertices::kExtraWireBytes)));
    }
  }
  w.triangles_packed += slice.size();
  return slice;
}

} // namespace zc::elastic
