#pragma once
// One pass over an OBJ file's text that checks every line tinyobjloader would accept silently
// (numbers, face index ranges, material library names) and keeps the geometry it reads: positions,
// texture coordinates, normals and faces. tinyobjloader parses the same text a second time through
// an std::istream at about 50 MB/s; this pass reads at several hundred. Materials stay
// tinyobjloader's: the lines that choose them (mtllib, usemtl) are handed to it as a small OBJ of
// their own (materials_obj), so material files and ids follow its rules exactly.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace zc {

struct ObjCorner {
  int v, t, n; // 0-based; t and n are -1 when the face vertex has none
};

struct ObjText {
  std::vector<float> positions, texcoords, normals; // 3, 2 and 3 floats each, as tinyobjloader
  std::vector<ObjCorner> corners;                   // every face's corners, face after face
  std::vector<std::uint8_t> face_size;              // corners of each face (3..255)
  // Faces after the k-th material line (mtllib or usemtl) are in segment k: face_segment[f].
  std::vector<std::uint32_t> face_segment;
  // One vertex, then every material line in file order, each followed by a marker face: the k-th
  // marker face's material id in tinyobjloader's result is segment k's (the first precedes all).
  std::string materials_obj;
};

// Called for every file an mtllib line names, with that line's number, when the pass reaches it.
using MtllibCheck = std::function<void(const std::string& file, int line)>;

// Reads and checks the text of `path` (its byte-order mark already removed); throws InputError
// naming path and line for the first fault in file order.
ObjText read_obj_text(const std::string& path, const std::string& text,
                      const MtllibCheck& on_mtllib);

} // namespace zc
