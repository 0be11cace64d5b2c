#include "algo/blazek_common.hpp"

#include <cmath>
#include <cstring>

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
  for (std::uint32_t i = 0; i < d.triangle_count; ++i) {
    const std::uint32_t id = d.first_triangle + i;
    const Triangle& t = s.triangles[id];
    out.push_back({id, t.material, {s.vertices[t.v[0]], s.vertices[t.v[1]], s.vertices[t.v[2]]}});
  }
  c.triangles_tessellated += d.triangle_count;
  return out;
}

Bytes encode_object(const Scene& s, std::size_t o) {
  const ObjectDesc& d = s.objects[o];
  const bool mesh = d.kind == "mesh";
  ObjectHeader h{d.first_vertex, d.vertex_count, d.first_triangle, d.triangle_count, mesh};
  Bytes b = pack(&h, 1);
  if (mesh) {
    Counters ignored;
    auto polys = host_polygons(s, o, ignored);
    append(b, polys.data(), polys.size());
  } else {
    append(b, d.text.data(), d.text.size());
  }
  return b;
}

std::vector<Poly> object_polygons(NodeContext& ctx, const Bytes& msg) {
  if (msg.size() < sizeof(ObjectHeader)) throw std::runtime_error("object message too short");
  ObjectHeader h;
  std::memcpy(&h, msg.data(), sizeof h);
  const std::uint8_t* rest = msg.data() + sizeof h;
  const std::size_t n = msg.size() - sizeof h;
  if (h.is_mesh) return unpack<Poly>(rest, n);
  ObjectDesc d;
  d.first_vertex = h.first_vertex;
  d.vertex_count = h.vertex_count;
  d.first_triangle = h.first_triangle;
  d.triangle_count = h.triangle_count;
  d.text.assign(reinterpret_cast<const char*>(rest), n);
  const Tessellation t = tessellate(d);
  std::vector<Poly> out;
  out.reserve(t.triangles.size());
  for (std::size_t i = 0; i < t.triangles.size(); ++i) {
    const Triangle& tr = t.triangles[i];
    Poly p{d.first_triangle + std::uint32_t(i), tr.material, {}};
    for (int k = 0; k < 3; ++k)
      p.v[k] = t.vertices[tr.v[k] - d.first_vertex];
    out.push_back(p);
  }
  Counters c;
  c.triangles_tessellated = out.size();
  ctx.charge(c);
  return out;
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

bool polygon_rows(const NodeRenderer& nr, const Poly& p, int& y0, int& y1) {
  ProjectedVertex pv[3];
  for (int k = 0; k < 3; ++k)
    pv[k] = nr.view().project(p.v[k]);
  const ProjectedVertex* pp[3] = {&pv[0], &pv[1], &pv[2]};
  return row_extent(pp, nr.width(), nr.height(), y0, y1);
}

void render_polygons(NodeContext& ctx, const NodeRenderer& nr, const std::vector<Poly>& polys,
                     Framebuffer& fb) {
  Counters c;
  TriangleBatch batch;
  for (const Poly& p : polys) {
    ProjectedVertex pv[3];
    for (int k = 0; k < 3; ++k)
      pv[k] = nr.project(p.v[k], c);
    const ProjectedVertex* pp[3] = {&pv[0], &pv[1], &pv[2]};
    batch.clear();
    nr.setup(p.id, Triangle{{0, 1, 2}, p.material}, pp, nullptr, batch, c);
    draw_batch(batch, nr.shade(), fb, c);
  }
  ctx.charge(c);
}

void render_host_messages_then_merge(
    NodeContext& ctx, const std::function<std::vector<Poly>(const Bytes&)>& polygons_of) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene());
  Framebuffer fb = nr.make_framebuffer(RowSet::all(nr.height()));
  ctx.alloc(double(fb.bytes()), "frame buffer");
  {
    auto ph = ctx.phase("render");
    Counters k;
    k.pixels_cleared = fb.pixel_count();
    ctx.charge(k);
    for (;;) {
      Bytes b = ctx.comm().recv(ctx.comm().host_rank(), kTagHost);
      if (is_end(b)) break;
      ctx.alloc(double(b.size()), "host message");
      render_polygons(ctx, nr, polygons_of(b), fb);
      ctx.release(double(b.size()));
    }
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
      Bytes out(fb.bytes());
      const std::size_t n = fb.pixel_count();
      std::memcpy(out.data(), fb.rgb().data(), 3 * n);
      std::memcpy(out.data() + 3 * n, fb.depth().data(), 4 * n);
      std::memcpy(out.data() + 7 * n, fb.ids().data(), 4 * n);
      Counters k;
      k.bytes_packed = out.size();
      ctx.charge(k);
      c.send(r ^ bit, kTagMerge, std::move(out));
      return;
    }
    Bytes in = c.recv(r ^ bit, kTagMerge);
    ctx.alloc(double(in.size()), "merge receive buffer");
    Framebuffer other(fb.width(), fb.rows(), glm::vec3(0));
    const std::size_t n = other.pixel_count();
    std::memcpy(other.rgb().data(), in.data(), 3 * n);
    std::memcpy(other.depth().data(), in.data() + 3 * n, 4 * n);
    std::memcpy(other.ids().data(), in.data() + 7 * n, 4 * n);
    Counters k;
    k.bytes_packed = in.size();
    k.merge_ops = n; // every location is compared (Algorithm 4)
    fb.merge(other);
    ctx.charge(k);
    ctx.release(double(in.size()));
  }
  if (r == 0) ctx.deliver_image(0, std::move(fb));
}

void paste_at_node0(NodeContext& ctx, const NodeRenderer& nr, const Framebuffer& part) {
  auto ph = ctx.phase("paste");
  Counters k;
  k.bytes_packed = part.rgb().size();
  ctx.charge(k);
  auto parts = coll::gatherv(ctx.comm(), 0, part.rgb());
  auto rows =
      coll::gatherv(ctx.comm(), 0,
                    pack(std::vector<int>{part.rows().begin, part.rows().end, part.rows().stride}));
  if (ctx.rank() != 0) return;
  Framebuffer img = nr.make_framebuffer(RowSet::all(nr.height()));
  const std::size_t row = 3 * std::size_t(nr.width());
  for (std::size_t k2 = 0; k2 < parts.size(); ++k2) {
    auto rs = unpack<int>(rows[k2]);
    const RowSet set{rs[0], rs[1], rs[2]};
    for (int y = set.begin; y < set.end; y += set.stride)
      std::memcpy(&img.rgb()[std::size_t(y) * row], &parts[k2][std::size_t(set.local(y)) * row],
                  row);
  }
  ctx.deliver_image(0, std::move(img));
}

} // namespace zc::blazek
