// Blazek 1991, ch. V: the host's polygon packets and object description packets, and the frame
// buffer record (blazek_wire.hpp).
#include "algo/blazek/blazek_wire.hpp"

#include "algo/records.hpp"
#include "comm/wire.hpp"
#include "util/record_io.hpp"

namespace zc::blazek {

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

std::optional<ObjectMessage> decode_object(const Bytes& msg) {
  if (msg.size() < sizeof(ObjectHeader)) return std::nullopt;
  RecordReader in(msg, "object description");
  ObjectMessage m;
  m.header = in.get<ObjectHeader>();
  m.rest_size = in.remaining();
  m.rest = in.get_bytes(m.rest_size);
  return m;
}

Message polygon_packet(const std::vector<Poly>& polys) {
  return {pack(polys), polys.size() * records::blazek::kPolygon};
}

double frame_buffer_bytes(const Framebuffer& fb) {
  return double(fb.pixel_count() * records::blazek::kFrameBufferPixel);
}

} // namespace zc::blazek
