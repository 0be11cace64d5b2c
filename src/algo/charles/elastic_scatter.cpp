// Charles, Lefevre, Miguet 1995, §4: Scatter(Vertices); Scatter(Triangles). "All the vertices of
// the scene are equally distributed on the parallel computer", and the triangles likewise; a
// node's triangles may use vertices another node holds.
#include <algorithm>

#include "algo/charles/elastic_steps.hpp"
#include "algo/charles/elastic_wire.hpp"
#include "algo/records.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"

namespace zc::elastic {

namespace {

std::vector<Vertex> scatter_vertices(NodeContext& ctx, const Scene& scene) {
  auto ph = ctx.phase("scatter_vertices");
  const int P = ctx.nodes();
  const std::size_t V = scene.vertices.size();
  std::vector<Bytes> parts;
  if (ctx.rank() == 0) {
    for (int k = 0; k < P; ++k) {
      const BlockRange b = block_range(V, P, k);
      parts.push_back(pack(scene.vertices.data() + b.begin, b.size()));
    }
    // Each block is a contiguous part of the vertex array: PPCM scatters it in place (zcube's copy
    // into a payload is an artefact of its wire format), so no packing is charged.
  }
  auto mine = unpack<Vertex>(coll::scatterv(ctx.comm(), 0, std::move(parts)));
  ctx.alloc(double(mine.size() * records::charles::kVertex), "vertex block");
  return mine;
}

std::vector<TriangleRecord> scatter_triangles(NodeContext& ctx, const Scene& scene) {
  auto ph = ctx.phase("scatter_triangles");
  const int P = ctx.nodes();
  const std::size_t T = scene.triangles.size();
  const bool with_material = materials_travel(ctx);
  const std::uint32_t material = scene.triangles.empty() ? 0 : scene.triangles.front().material;
  const std::size_t wire = kTriangleWireBytes + (with_material ? 4 : 0);
  std::vector<Bytes> parts;
  if (ctx.rank() == 0) {
    // A block of the paper's triangle array (three vertex numbers each) is contiguous and
    // scattered in place: no packing charged (zcube builds the wire form from its own records).
    for (int k = 0; k < P; ++k) {
      Bytes block;
      const BlockRange b = block_range(T, P, k);
      for (std::size_t i = b.begin; i < b.end; ++i) {
        const Triangle& t = scene.triangles[i];
        append_triangle(block, {std::uint32_t(i), t}, with_material);
      }
      parts.push_back(std::move(block));
    }
  }
  const Bytes got = coll::scatterv(ctx.comm(), 0, std::move(parts));
  const auto first = std::uint32_t(block_begin(T, P, ctx.rank()));
  std::vector<TriangleRecord> mine(got.size() / wire);
  RecordReader in(got, "triangle block");
  for (std::size_t i = 0; i < mine.size(); ++i)
    mine[i] = read_triangle(in, first + std::uint32_t(i), with_material, material);
  ctx.alloc(double(got.size()), "triangle block");
  return mine;
}

// Each node contributes the texture coordinates of its vertex block.
std::vector<glm::vec2> multibroadcast_uvs(NodeContext& ctx, const Scene& scene, std::size_t lo,
                                          std::size_t hi) {
  auto ph = ctx.phase("multibroadcast_uvs");
  std::vector<glm::vec2> uvs;
  for (auto& b : coll::allgatherv(ctx.comm(), pack(scene.uvs.data() + lo, hi - lo))) {
    auto part = unpack<glm::vec2>(b);
    uvs.insert(uvs.end(), part.begin(), part.end());
  }
  ctx.alloc(double(uvs.size() * sizeof(glm::vec2)), "texture coordinates");
  return uvs;
}

} // namespace

LocalScene scatter_scene(NodeContext& ctx) {
  const Scene& scene = ctx.scene(); // node 0 reads it from disk; the others only get blocks
  const int P = ctx.nodes(), r = ctx.rank();
  LocalScene local;
  local.scene_vertices = scene.vertices.size();
  local.scene_triangles = scene.triangles.size();
  const BlockRange my_vertices = block_range(local.scene_vertices, P, r);
  local.first_vertex = my_vertices.begin;
  local.vertices = scatter_vertices(ctx, scene);
  local.triangles = scatter_triangles(ctx, scene);
  if (scene.textured())
    local.uvs = multibroadcast_uvs(ctx, scene, my_vertices.begin, my_vertices.end);
  return local;
}

} // namespace zc::elastic
