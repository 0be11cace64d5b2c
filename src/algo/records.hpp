#pragma once
// The records each paper's program holds and sends, in bytes, declared once per algorithm family
// (docs/papers.md, "Records"): what the modelled machine's network and node memory are charged.
// zcube's payloads may carry more (a triangle id on every pixel for the depth tie-break that keeps
// pictures byte-identical, clip-space floats in a projected vertex); a send charges the record,
// not the payload (comm/comm.hpp, Message::charged).
#include <cstddef>

namespace zc::records {

// Charles, Lefevre, Miguet 1995 (elastic, and its sequential reference).
namespace charles {
// §4: "A vertex is a set of 6 real numbers which define a point ... and a normal": 6 floats.
constexpr std::size_t kVertex = 24;
// §4: "A triangle is a set of 3 vertices' indices (3 integers)".
constexpr std::size_t kTriangle = 12;
// §4: a vertex "projected in the coordinate system of the screen" (x, y, z: 3 floats) to which the
// shading assigns "a R.G.B. color" (3 bytes): 15 bytes, 16 as a C structure (4-byte aligned).
constexpr std::size_t kProjectedVertex = 16;
// §5: a row's load is a count of triangles, a C int.
constexpr std::size_t kLoadEntry = 4;
// §2's z-buffer: a depth (a 32-bit float) and the pixel's R.G.B. colour (3 bytes).
constexpr std::size_t kZbufferLocation = 7;
} // namespace charles

// Kurc, Aykanat, Ozguc (zbuf-exc, pair-*, aapc-*, and the scanline reference).
namespace kurc {
// §2: a WPA entry holds "location information, z value, and shading information"; "only x value of
// the pixel ... needs to be stored": x (16 bits: N <= 640), z (a 32-bit float), R.G.B. (3 bytes).
constexpr std::size_t kWinningPixel = 9;
// Full z-buffer merging (§1, §5): a location holds z and shading, no x: 4 + 3 bytes.
constexpr std::size_t kZbufferLocation = 7;
// §4.1: a scanline's count of local foremost pixels, a C int.
constexpr std::size_t kCountEntry = 4;
// §5 deals polygons (Table 1 counts polygons): three vertices, each a point and a normal for the
// shading (6 floats, the vertex of Charles et al. §4); the paper prints no polygon record.
constexpr std::size_t kPolygon = 72;
} // namespace kurc

// Blazek 1991 (host-initiated, node-initiated, object-forwarding, host-broadcast).
namespace blazek {
// Ch. V: "Using packets containing 100 polygons each, the size of each message sent to the nodes
// is three kilobytes": 3,000 / 100 bytes a polygon.
constexpr std::size_t kPolygon = 30;
// Ch. V: "object description packets (only 100 bytes each)".
constexpr std::size_t kObjectDescription = 100;
// Ch. II: "a 24 bit RGB&Z image requires 2,621,440 bytes" for 512 x 512 pixels: 10 bytes a
// pixel (ch. V's "1024x1024 pixel RGB image requires eleven megabytes" agrees: 10.5 MB).
constexpr std::size_t kFrameBufferPixel = 10;
} // namespace blazek

} // namespace zc::records
