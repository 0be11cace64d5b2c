#pragma once
// Charles, Lefevre, Miguet 1995 §4's records on the wire. "A vertex is a set of 6 real numbers"
// (24 bytes, as Vertex); "A triangle is a set of 3 vertices' indices (3 integers)": 12 bytes. A
// triangle's global id (zcube's depth tie-break) does not travel: a block's triangles are numbered
// from the block's first id, and a MultiScatter message says which triangles of the sender's block
// it carries by a bitmask of the block, one bit a triangle. A material index (4 bytes) follows the
// vertex numbers only when the scene has more than one material (the paper's scenes have one).
#include <cstdint>
#include <vector>

#include "algo/charles/elastic_steps.hpp"
#include "comm/wire.hpp"

namespace zc::elastic {

constexpr std::size_t kTriangleWireBytes = 12;

// Whether the triangles' material indices travel: only when the scene's triangles use more than
// one (otherwise every node knows the one colour from the scene description, as the camera).
bool materials_travel(const NodeContext& ctx);
// Bytes of one triangle on the wire in this scene (12, or 16 with its material).
std::size_t triangle_wire_bytes(const NodeContext& ctx);

// Appends triangle t's wire form (vertex numbers, then the material when `with_material`).
void append_triangle(Bytes& b, const TriangleRecord& t, bool with_material);
// Reads one back, as triangle `id` (of `material` when materials do not travel).
TriangleRecord read_triangle(RecordReader& in, std::uint32_t id, bool with_material,
                             std::uint32_t material);

// A message carrying `picked` (ascending indices into a block of n triangles): the block's
// bitmask; `append` then writes each picked triangle's record, `record_bytes` each (reserved).
Bytes selection_header(std::size_t n, const std::vector<std::uint32_t>& picked,
                       std::size_t record_bytes);
// The picked indices of a block of n triangles, read from a message's header.
std::vector<std::uint32_t> read_selection(RecordReader& in, std::size_t n);

} // namespace zc::elastic
