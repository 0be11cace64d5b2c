#include "algo/elastic_wire.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace zc::elastic {

bool materials_travel(const NodeContext& ctx) {
  return ctx.scene_facts().several_materials;
}

std::size_t triangle_wire_bytes(const NodeContext& ctx) {
  return kTriangleWireBytes + (materials_travel(ctx) ? 4 : 0);
}

void append_triangle(Bytes& b, const TriangleRecord& t, bool with_material) {
  append(b, t.tri.v, 3);
  if (with_material) append(b, &t.tri.material, 1);
}

TriangleRecord read_triangle(RecordReader& in, std::uint32_t id, bool with_material,
                             std::uint32_t material) {
  TriangleRecord t{id, {{0, 0, 0}, material}};
  in.get(t.tri.v, 3);
  if (with_material) t.tri.material = in.get<std::uint32_t>();
  return t;
}

Bytes selection_header(std::size_t n, const std::vector<std::uint32_t>& picked,
                       std::size_t record_bytes) {
  Bytes b;
  b.reserve((n + 7) / 8 + picked.size() * record_bytes); // one allocation for the whole message
  b.resize((n + 7) / 8, 0);
  for (auto i : picked)
    b[i / 8] = std::uint8_t(b[i / 8] | (1u << (i % 8)));
  return b;
}

std::vector<std::uint32_t> read_selection(RecordReader& in, std::size_t n) {
  const std::uint8_t* mask = in.get_bytes((n + 7) / 8);
  std::vector<std::uint32_t> picked;
  // Byte by byte, set bits only: a message usually carries few of the block's triangles.
  for (std::size_t byte = 0; byte < (n + 7) / 8; ++byte)
    for (unsigned bits = mask[byte]; bits != 0; bits &= bits - 1) {
      const std::size_t i = byte * 8 + std::size_t(std::countr_zero(bits));
      if (i < n) picked.push_back(std::uint32_t(i));
    }
  return picked;
}

} // namespace zc::elastic
