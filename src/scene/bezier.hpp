#pragma once
// Newell's bicubic Bezier patches (the Utah teapot): reading the two file forms and tessellating
// them into a triangle grid with analytic normals.
//   teaset form (ftp.funet.fi "teaset"): a line with the patch count, one line of 16
//     comma-separated 1-based control-point indices per patch, a line with the point count, then
//     one "x,y,z" line per point.
//   .bpt form: a line with the patch count, then per patch a line "3 3" and 16 lines "x y z".
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/primitives.hpp"

namespace zc {

struct BezierPatch {
  glm::dvec3 p[4][4]; // p[i][j]: i along u, j along v
};

// Parses the text of a patch file; `path` names it in errors and its extension (.bpt) picks the
// form. Throws InputError(path, line, reason) for any malformed text.
std::vector<BezierPatch> parse_bezier(const std::string& text, const std::string& path);

// Throws InputError(path, line, reason) for any malformed file. Parsed files are cached (a node
// re-tessellating many copies of one object reads the file once).
std::shared_ptr<const std::vector<BezierPatch>> read_bezier_file(const std::string& path);

// True when the text looks like a patch file (first line a lone count, then a patch line).
bool looks_like_bezier(const std::string& text);

constexpr int kMaxBezierLevel = 256;

// Each patch becomes a (level+1)^2 vertex grid and 2*level^2 triangles. Normals are
// dPdv x dPdu (outward for Newell's patch orientation), and the triangles wind counter-clockwise
// around them; where that vanishes (the collapsed edges at the teapot's lid and bottom poles) the
// normal is taken a little inside the patch.
LocalMesh tessellate_patches(const std::vector<BezierPatch>& patches, int level);

} // namespace zc
