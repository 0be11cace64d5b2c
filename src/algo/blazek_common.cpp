#include "algo/blazek_common.hpp"

#include <cmath>
#include <cstring>
#include <deque>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "raster/zbuffer.hpp"
#include "scene/tessellate.hpp"
#include "util/error.hpp"

namespace zc::blazek {

namespace {
struct ObjectHeader {
  std::uint32_t first_vertex, vertex_count, first_triangle, triangle_count, is_mesh;
};
} // namespace

void check_scene(const Scene& s) {
  if (s.textured()) throw UsageError("Blazek's methods render untextured scenes");
  if (s.objects.empty() && !s.triangles.empty())
    throw UsageError("Blazek's methods need a scene made of objects (JSON or scene language)");
}

std::vector<Poly> host_polygons(const Scene& s, std::size_t o, Counters& c) {
  const ObjectDesc& d = s.objects[o];
  std::vector<Poly> out;
  for (std::uint32_t i = 0; i < d.triangle_count; ++i)
    out.push_back(world_polygon(s, d.first_triangle + i));
  c.triangles_tessellated += d.triangle_count;
  return out;
}

Message encode_object(const Scene& s, std::size_t o) {
  const ObjectDesc& d = s.objects[o];
  const bool mesh = d.kind == "mesh";
  ObjectHeader h{d.first_vertex, d.vertex_count, d.first_triangle, d.triangle_count, mesh};
  Bytes b = pack(&h, 1);
  std::size_t charged = records::blazek::kObjectDescription;
  if (mesh) {
    Counters ignored;
    auto polys = host_polygons(s, o, ignored);
    append(b, polys.data(), polys.size());
    charged += polys.size() * records::blazek::kPolygon;
  } else {
    append(b, d.text.data(), d.text.size());
  }
  return {std::move(b), charged};
}

Message polygon_packet(const std::vector<Poly>& polys) {
  return {pack(polys), polys.size() * records::blazek::kPolygon};
}

double frame_buffer_bytes(const Framebuffer& fb) {
  return double(fb.pixel_count() * records::blazek::kFrameBufferPixel);
}

Mesh mesh_of(const std::vector<Poly>& polys) {
  Mesh m;
  m.vertices.reserve(3 * polys.size());
  m.tris.reserve(polys.size());
  for (const Poly& p : polys) {
    const auto at = std::uint32_t(m.vertices.size());
    m.tris.push_back({p.id, p.material, {at, at + 1, at + 2}});
    m.vertices.insert(m.vertices.end(), p.v, p.v + 3);
  }
  return m;
}

std::vector<Poly> polys_of(const Mesh& m, const std::vector<std::uint32_t>& subset) {
  std::vector<Poly> out;
  out.reserve(subset.size());
  for (std::uint32_t t : subset) {
    const Mesh::Tri& tr = m.tris[t];
    out.push_back(
        {tr.id, tr.material, {m.vertices[tr.v[0]], m.vertices[tr.v[1]], m.vertices[tr.v[2]]}});
  }
  return out;
}

Mesh object_mesh(NodeContext& ctx, const Bytes& msg) {
  if (msg.size() < sizeof(ObjectHeader)) throw std::runtime_error("object message too short");
  ObjectHeader h;
  std::memcpy(&h, msg.data(), sizeof h);
  const std::uint8_t* rest = msg.data() + sizeof h;
  const std::size_t n = msg.size() - sizeof h;
  if (h.is_mesh) return mesh_of(unpack<Poly>(rest, n));
  ObjectDesc d;
  d.first_vertex = h.first_vertex;
  d.vertex_count = h.vertex_count;
  d.first_triangle = h.first_triangle;
  d.triangle_count = h.triangle_count;
  d.text.assign(reinterpret_cast<const char*>(rest), n);
  Tessellation t = tessellate(d);
  Mesh m;
  m.vertices = std::move(t.vertices);
  m.tris.reserve(t.triangles.size());
  for (std::size_t i = 0; i < t.triangles.size(); ++i) {
    const Triangle& tr = t.triangles[i];
    m.tris.push_back(
        {d.first_triangle + std::uint32_t(i),
         tr.material,
         {tr.v[0] - d.first_vertex, tr.v[1] - d.first_vertex, tr.v[2] - d.first_vertex}});
  }
  Counters c;
  c.triangles_tessellated = m.tris.size();
  ctx.charge(c);
  return m;
}

bool object_may_touch(const NodeRenderer& nr, const Bytes& msg, const RowSet& rows,
                      std::uint32_t& triangles) {
  if (msg.size() < sizeof(ObjectHeader)) return true;
  ObjectHeader h;
  std::memcpy(&h, msg.data(), sizeof h);
  triangles = h.triangle_count;
  if (h.is_mesh) return true;
  const ObjectSpec spec = parse_object_text(
      std::string(reinterpret_cast<const char*>(msg.data() + sizeof h), msg.size() - sizeof h));
  if (spec.kind == "bezier" || spec.kind == "mesh") return true;
  const glm::dmat4 m = nr.view().view_proj * spec.xf.to_matrix();
  double ylo = 1e300, yhi = -1e300;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec4 c =
        m * glm::dvec4(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1, 1);
    if (!(c.w > 1e-9) || !(c.z >= -c.w)) return true; // behind or across the near plane
    const double sy = (0.5 - 0.5 * c.y / c.w) * nr.height();
    ylo = std::min(ylo, sy);
    yhi = std::max(yhi, sy);
  }
  // Rows whose centres fall in [ylo, yhi], widened by a row for rounding.
  const int y0 = int(std::floor(ylo)) - 1, y1 = int(std::ceil(yhi)) + 1;
  const int first = rows.first_from(std::max(y0, 0));
  return first <= y1 && first < rows.end;
}

ProjectedMesh::ProjectedMesh(NodeContext& ctx, const NodeRenderer& nr, const Mesh& m) : mesh(m) {
  Counters c;
  pv.reserve(m.vertices.size());
  for (const Vertex& v : m.vertices)
    pv.push_back(nr.project(v, c));
  ctx.charge(c);
}

bool ProjectedMesh::rows(const NodeRenderer& nr, std::uint32_t t, int& y0, int& y1) const {
  const Mesh::Tri& tr = mesh.tris[t];
  const ProjectedVertex* pp[3] = {&pv[tr.v[0]], &pv[tr.v[1]], &pv[tr.v[2]]};
  return row_extent(pp, nr.width(), nr.height(), y0, y1);
}

std::vector<std::uint32_t> triangles_touching(NodeContext& ctx, const NodeRenderer& nr,
                                              const ProjectedMesh& pm, const RowSet& rows) {
  std::vector<std::uint32_t> out;
  const auto n = std::uint32_t(pm.mesh.tris.size());
  for (std::uint32_t t = 0; t < n; ++t) {
    int y0, y1;
    if (!pm.rows(nr, t, y0, y1)) continue;
    const int first = rows.first_from(y0);
    if (first <= y1 && first < rows.end) out.push_back(t);
  }
  Counters k;
  k.triangles_estimated = n;
  ctx.charge(k);
  return out;
}

void render_mesh(NodeContext& ctx, const NodeRenderer& nr, const ProjectedMesh& pm, Framebuffer& fb,
                 const std::vector<std::uint32_t>* subset) {
  Counters c;
  TriangleBatch batch;
  auto draw = [&](std::uint32_t t) {
    const Mesh::Tri& tr = pm.mesh.tris[t];
    const ProjectedVertex* pp[3] = {&pm.pv[tr.v[0]], &pm.pv[tr.v[1]], &pm.pv[tr.v[2]]};
    batch.clear();
    nr.setup(tr.id, Triangle{{0, 1, 2}, tr.material}, pp, nullptr, batch, c);
    draw_batch(batch, nr.shade(), fb, c);
  };
  if (subset)
    for (std::uint32_t t : *subset)
      draw(t);
  else
    for (std::uint32_t t = 0; t < pm.mesh.tris.size(); ++t)
      draw(t);
  ctx.charge(c);
}

void render_host_messages_then_merge(NodeContext& ctx, bool tessellates, bool acknowledge,
                                     const std::function<Mesh(const Bytes&)>& mesh_of_message) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene());
  Framebuffer fb;
  {
    auto ph = ctx.phase("render"); // the clear of the new frame buffer is the phase's
    fb = nr.make_framebuffer(RowSet::all(nr.height()));
    ctx.alloc(frame_buffer_bytes(fb), "frame buffer");
    Counters k;
    k.pixels_cleared = fb.pixel_count();
    ctx.charge(k);
    std::deque<SendHandle> acks;
    for (;;) {
      const Message got = ctx.comm().recv_message(ctx.comm().host_rank(), kTagHost);
      const Bytes& b = got.payload;
      if (is_end(b)) break;
      const Held msg(ctx, double(got.charged), "host message");
      const Mesh m = mesh_of_message(b);
      // Host initiated renders out of the packet itself; node initiated holds the tessellation
      // (the projected vertices are counted with it).
      const Held held(
          ctx, tessellates ? m.bytes() + double(m.vertices.size() * sizeof(ProjectedVertex)) : 0.0,
          "polygons");
      render_mesh(ctx, nr, ProjectedMesh(ctx, nr, m), fb);
      if (acknowledge) {
        acks.push_back(ctx.comm().isend(ctx.comm().host_rank(), kTagAck, Bytes(4)));
        if (acks.size() > std::size_t(kHostWindow)) {
          acks.front()->wait();
          acks.pop_front();
        }
      }
    }
    for (auto& a : acks)
      a->wait();
  }
  hierarchical_merge(ctx, std::move(fb));
}

void hierarchical_merge(NodeContext& ctx, Framebuffer fb) {
  Comm& c = ctx.comm();
  const int r = c.rank();
  auto ph = ctx.phase("merge");
  for (int i = 0; (1 << i) < c.size(); ++i) {
    const int bit = 1 << i;
    if (r & (bit - 1)) break; // already sent its buffer
    if (r & bit) {
      // The frame buffer is sent in place (its arrays are contiguous): no packing is charged;
      // zcube's copy into one payload is an artefact of its wire format.
      // Charged as the thesis's frame buffer (records.hpp), without zcube's triangle ids.
      c.send(r ^ bit, kTagMerge,
             Message{fb.pack_locations(0, fb.pixel_count()), std::size_t(frame_buffer_bytes(fb))});
      return;
    }
    if ((r ^ bit) >= c.size()) continue; // no partner when P is not a power of two (a ring of 3)
    const Message got = c.recv_message(r ^ bit, kTagMerge);
    const Bytes& in = got.payload;
    ctx.alloc(double(got.charged), "merge receive buffer");
    Counters k;
    // Every location is compared (Algorithm 4), straight out of the received buffer.
    k.merge_ops = fb.merge_locations(in, 0);
    ctx.charge(k);
    ctx.release(double(got.charged));
  }
  if (r == 0) ctx.deliver_image(0, std::move(fb));
}

void paste_at_node0(NodeContext& ctx, const Framebuffer& part) {
  auto ph = ctx.phase("paste");
  // The node's rows (a strip or interleaved) are one contiguous array of its frame buffer, sent
  // in place to node 0, which displays them: no packing is charged. Only colour travels (ch. V);
  // the picture and its depth map are the rows each node rendered, handed over once sent (the
  // colour node 0 receives is these rows' colour, byte for byte).
  (void)coll::gatherv(ctx.comm(), 0, part.rgb());
  (void)coll::gatherv(
      ctx.comm(), 0,
      pack(std::vector<int>{part.rows().begin, part.rows().end, part.rows().stride}));
  ctx.deliver_rows(0, part);
}

} // namespace zc::blazek
