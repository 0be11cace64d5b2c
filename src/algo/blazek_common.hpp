#pragma once
// Pieces shared by Blazek's four decompositions (thesis ch. V): what travels between the host
// (SRM) and the nodes, node-side tessellation and rendering, the hierarchical merge of Algorithm 4
// and the pasting of strips.
#include <functional>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/records.hpp"
#include "algo/world_polygon.hpp"
#include "raster/framebuffer.hpp"
#include "raster/renderer.hpp"
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

constexpr int kTagHost = 1, kTagForward = 2, kTagMerge = 3, kTagAck = 4;

// Host initiated flow control: a node buffers at most this many unconsumed polygon packets (its
// message buffers are part of its few megabytes); it acknowledges each packet it has rendered,
// and the host waits for the acknowledgement of packet i - kHostWindow before sending packet i to
// the same node. (An assumption: the thesis does not say how its host was throttled.)
constexpr int kHostWindow = 4;

// Checks the scene suits the methods (untextured; Blazek's renderer had no textures).
void check_scene(const Scene& s);

// Modelled node memory held for a scope (messages, tessellated polygons): alloc now, release at
// the end of the scope.
class Held {
public:
  Held(NodeContext& ctx, double bytes, const char* what) : ctx_(ctx), bytes_(bytes) {
    ctx_.alloc(bytes_, what);
  }
  ~Held() { ctx_.release(bytes_); }
  Held(const Held&) = delete;
  Held& operator=(const Held&) = delete;

private:
  NodeContext& ctx_;
  double bytes_;
};

// A node's polygons, as a shared-vertex mesh: an object's tessellation keeps its shared vertices,
// so each is transformed once (as the sequential renderer does); polygons that travelled as Poly
// records (host initiated packets, forwarded polygons) bring three vertices each, which the node
// transforms one by one: the price of shipping polygons rather than descriptions.
struct Mesh {
  struct Tri {
    std::uint32_t id, material, v[3]; // global id; indices into vertices
  };
  std::vector<Vertex> vertices;
  std::vector<Tri> tris;
  double bytes() const {
    return double(vertices.size() * sizeof(Vertex) + tris.size() * sizeof(Tri));
  }
};
Mesh mesh_of(const std::vector<Poly>& polys);
// The polygons of a subset (indices into m.tris) of a mesh, to be sent.
std::vector<Poly> polys_of(const Mesh& m, const std::vector<std::uint32_t>& subset);

// Object description message: ranges + the one-line text, charged as the thesis's 100-byte
// "object description packets" (records.hpp). Mesh objects, which no node can re-tessellate,
// travel as their polygons (kind "mesh" + a polygon payload), charged a description and 30 bytes a
// polygon.
Message encode_object(const Scene& s, std::size_t object);
// Decodes and tessellates (charging triangles_tessellated).
Mesh object_mesh(NodeContext& ctx, const Bytes& msg);
// The polygons of an object as the host tessellates them (charged to the caller).
std::vector<Poly> host_polygons(const Scene& s, std::size_t object, Counters& c);

// Whether an object (its message) can touch any row of `rows`, judged from its description's
// bounding box alone (primitives fit [-1, 1]^3 before their transform). `triangles` receives its
// polygon count. Conservative: true when unsure (meshes, Bezier patches, near-plane crossings).
bool object_may_touch(const NodeRenderer& nr, const Bytes& msg, const RowSet& rows,
                      std::uint32_t& triangles);

// A mesh with its vertices projected (vertices_transformed charged once per vertex).
struct ProjectedMesh {
  const Mesh& mesh;
  std::vector<ProjectedVertex> pv;
  ProjectedMesh(NodeContext& ctx, const NodeRenderer& nr, const Mesh& m);
  // Rows [y0, y1] triangle t can touch (false: none: culled or off screen).
  bool rows(const NodeRenderer& nr, std::uint32_t t, int& y0, int& y1) const;
};

// The triangles of a projected mesh that can touch `rows` (charges triangles_estimated: the test
// the strip methods make for every polygon).
std::vector<std::uint32_t> triangles_touching(NodeContext& ctx, const NodeRenderer& nr,
                                              const ProjectedMesh& pm, const RowSet& rows);

// Sets up and scan-converts triangles of a projected mesh (all, or `subset`) into fb (on fb's
// rows); charges the work.
void render_mesh(NodeContext& ctx, const NodeRenderer& nr, const ProjectedMesh& pm, Framebuffer& fb,
                 const std::vector<std::uint32_t>* subset = nullptr);

// The node side of host initiated and node initiated: a full frame buffer, every host message
// until the end marker turned into polygons by `polygons_of` and rendered, then the hierarchical
// merge. `tessellates`: the mesh is a tessellation held besides the message (node memory);
// `acknowledge`: send the host an acknowledgement per message (kHostWindow).
void render_host_messages_then_merge(NodeContext& ctx, bool tessellates, bool acknowledge,
                                     const std::function<Mesh(const Bytes&)>& mesh_of_message);

// Algorithm 4 / Figure 10: log2 P steps; at step i the active nodes with bit i set send their
// frame buffer to the neighbour over channel i, which keeps the nearer pixel. Node 0 ends with
// the merged picture, which it delivers. Any P: a node whose partner would be P or above skips
// that step (a binomial tree).
void hierarchical_merge(NodeContext& ctx, Framebuffer fb);

// Strips or interleaved rows sent to node 0 (colour only, timed); each node hands over its rows,
// colour and depth, which make the picture.
void paste_at_node0(NodeContext& ctx, const Framebuffer& part);

// The strip methods' decomposition: node k of P owns rows [kH/P, (k+1)H/P) (some strips are empty
// when P > H), and row y lies in strip ((y+1)P - 1) / H, the last strip starting at or before y
// (yP/H is not: with H = 77 and P = 2, row 38 starts strip 1 but 38*2/77 = 0).
inline RowSet strip_rows(int k, int P, int H) {
  return RowSet::band(int(std::int64_t(k) * H / P), int(std::int64_t(k + 1) * H / P));
}
inline int strip_of_row(int y, int P, int H) {
  return int(((std::int64_t(y) + 1) * P - 1) / H);
}

// The host's end-of-work marker: an empty message.
inline bool is_end(const Bytes& b) {
  return b.empty();
}

} // namespace zc::blazek
