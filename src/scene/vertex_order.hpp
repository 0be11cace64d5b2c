#pragma once
// The order of a mesh's vertices in memory, as the triangles read them.
#include "scene/scene.hpp"

namespace zc {

// Renumbers the scene's vertices (and texture coordinates) in the order its triangles first use
// them, dropping the unused ones: each triangle then reads its vertices where the triangles before
// it left off, as in a mesh listed with locality, whatever order the triangles are in. The
// triangles keep their order and their corners' order; every triangle keeps its positions.
void renumber_vertices_by_first_use(Scene& s);

} // namespace zc
