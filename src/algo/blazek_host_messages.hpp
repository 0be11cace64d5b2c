#pragma once
// Blazek 1991, ch. V "Host Initiated Method" and "Node Initiated Method": the node's loop over the
// host's messages (polygon packets or object descriptions), each rendered into the node's full
// frame buffer, until the host's end marker; then the hierarchical merge.
#include <functional>

#include "algo/algorithm.hpp"
#include "algo/blazek_mesh.hpp"

namespace zc::blazek {

// The node side of host initiated and node initiated: a full frame buffer, every host message
// until the end marker turned into polygons by `polygons_of` and rendered, then the hierarchical
// merge. `tessellates`: the mesh is a tessellation held besides the message (node memory);
// `acknowledge`: send the host an acknowledgement per message (kHostWindow).
void render_host_messages_then_merge(NodeContext& ctx, bool tessellates, bool acknowledge,
                                     const std::function<Mesh(const Bytes&)>& mesh_of_message);

} // namespace zc::blazek
