#pragma once
// What the modelled machine is charged for a picture's records, in bytes: the caller's paper
// decides (algo/records.hpp, docs/papers.md "Records"); zcube's payloads may carry more (the
// triangle id of the depth tie-break).
#include <cstddef>

namespace zc::compositing {

struct PixelRecords {
  std::size_t pixel = 9;    // an active pixel: x, z, R.G.B. (Kurc et al. §2's WPA entry)
  std::size_t location = 7; // a z-buffer location: z, R.G.B.
  std::size_t count = 4;    // a row's pixel count or a run length (a C int)
};

} // namespace zc::compositing
