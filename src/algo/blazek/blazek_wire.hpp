#pragma once
// Blazek 1991, ch. V: what travels between the host (the SRM) and the nodes, and between nodes:
// polygon packets ("Host Initiated Method"), object description packets ("Node Initiated
// Method"), and the frame buffers merged or pasted; each charged as the thesis's records
// (records.hpp), whatever zcube's payload carries.
#include <cstdint>
#include <optional>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/world_polygon.hpp"
#include "raster/framebuffer.hpp"
#include "scene/scene.hpp"

namespace zc::blazek {

// A polygon as it travels (host initiated packets, forwarded polygons): zcube's payload is the
// world polygon record (80 bytes); the network is charged the thesis's 30 bytes a polygon
// (records.hpp: "packets containing 100 polygons each ... three kilobytes", ch. V).
using Poly = WorldPolygon;
// A packet of polygons, charged as the thesis's records.
Message polygon_packet(const std::vector<Poly>& polys);
// A frame buffer (full, strip or interleaved rows) as the thesis's node holds it: 10 bytes a pixel
// (records.hpp).
double frame_buffer_bytes(const Framebuffer& fb);

// The polygons of an object as the host tessellates them (charged to the caller).
std::vector<Poly> host_polygons(const Scene& s, std::size_t object, Counters& c);

// Object description message: ranges + the one-line text, charged as the thesis's 100-byte
// "object description packets" (records.hpp). Mesh objects, which no node can re-tessellate,
// travel as their polygons (kind "mesh" + a polygon payload), charged a description and 30 bytes a
// polygon.
Message encode_object(const Scene& s, std::size_t object);

// An object description message read back: its header and the rest of the payload (the
// description's text, or a mesh's polygons).
struct ObjectHeader {
  std::uint32_t first_vertex, vertex_count, first_triangle, triangle_count, is_mesh;
};
struct ObjectMessage {
  ObjectHeader header;
  const std::uint8_t* rest;
  std::size_t rest_size;
};
// Nothing when the message is shorter than a header.
std::optional<ObjectMessage> decode_object(const Bytes& msg);

} // namespace zc::blazek
