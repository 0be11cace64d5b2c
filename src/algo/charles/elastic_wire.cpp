#include "algo/charles/elastic_wire.hpp"

#include <algorithm>
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
  const std::size_t bytes = (n + 7) / 8;
  const std::uint8_t* mask = in.get_bytes(bytes);
  std::vector<std::uint32_t> picked;
  // Eight bytes at a time, set bits only: a message usually carries few of the block's triangles
  // (at 1024 nodes, most carry none). Bit i of the mask is bit i % 8 of byte i / 8.
  for (std::size_t at = 0; at < bytes; at += 8) {
    const std::size_t len = std::min<std::size_t>(8, bytes - at);
    std::uint64_t word = 0;
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(&word, mask + at, len);
    } else {
      for (std::size_t j = 0; j < len; ++j)
        word |= std::uint64_t(mask[at + j]) << (8 * j);
    }
    for (; word != 0; word &= word - 1) {
      const std::size_t i = at * 8 + std::size_t(std::countr_zero(word));
      if (i < n) picked.push_back(std::uint32_t(i));
    }
  }
  return picked;
}

} // namespace zc::elastic
