#pragma once
// Blazek 1991, ch. IV "Software" and ch. V: what the host (SRM) program and the node programs of
// the four decompositions agree on: message tags, the host's end marker, the scenes the methods
// accept, and node memory held for a scope. The methods' pieces, one job a file: blazek_wire
// (what travels), blazek_mesh (tessellation), blazek_culling (strips and what touches them),
// blazek_render (z-buffer rendering), blazek_host_messages (the node's loop over the host's
// messages), blazek_merge_paste (hierarchical merge, pasting).
#include "algo/algorithm.hpp"
#include "scene/scene.hpp"
#include "util/error.hpp"

namespace zc::blazek {

constexpr int kTagHost = 1, kTagForward = 2, kTagMerge = 3, kTagAck = 4;

// Checks the scene suits the methods (untextured; Blazek's renderer had no textures).
inline void check_scene(const Scene& s) {
  if (s.textured()) throw UsageError("Blazek's methods render untextured scenes");
  if (s.objects.empty() && !s.triangles.empty())
    throw UsageError("Blazek's methods need a scene made of objects (JSON or scene language)");
}

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

// The host's end-of-work marker: an empty message.
inline bool is_end(const Bytes& b) {
  return b.empty();
}

} // namespace zc::blazek
