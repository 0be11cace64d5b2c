// The compositing layer's data path on the in-process Comm: every strategy on every picture
// representation composites random partial pictures into the sequential composite (every pixel
// z-buffered into one buffer), on several node counts, rings and cubes, and several screen
// shapes; each node ends with the rows of the region it owns and nothing else, and the gather and
// paste of the output give the whole picture. (test_strategies.cpp runs them in the simulator.)
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "comm/local_comm.hpp"
#include "compositing/dense.hpp"
#include "compositing/gather.hpp"
#include "compositing/run_length.hpp"
#include "compositing/strategy.hpp"
#include "compositing/winning_pixels.hpp"

using namespace zc;
using namespace zc::compositing;

namespace {

const glm::vec3 kBackground(0.25f, 0.5f, 0.75f);
const char* kRepresentations[] = {"dense", "winning-pixels", "run-length"};

class CountedMemory : public Memory {
public:
  void alloc(double bytes, const std::string&) override { held += bytes; }
  void release(double bytes) override { held -= bytes; }
  double held = 0;
};

// Node `node`'s partial picture of a w x h screen: about a third of the locations covered, depths
// from eight values (ties decided by the triangle id, unique over the nodes).
ActivePixels partial(int node, int nodes, int w, int h) {
  std::uint32_t state = 2463534242u + 977u * std::uint32_t(node);
  auto next = [&state] {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  };
  ActivePixels a;
  a.width = w;
  a.y1 = h;
  a.row_begin.push_back(0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (next() % 3 != 0) continue;
      const std::uint32_t r = next();
      WinningPixel p{float(r % 8) / 8,
                     std::uint32_t(node + nodes * (y * w + x)),
                     std::uint16_t(x),
                     {std::uint8_t(r >> 8), std::uint8_t(r >> 16), std::uint8_t(r >> 24)}};
      a.pixels.push_back(p);
    }
    a.row_begin.push_back(std::uint32_t(a.pixels.size()));
  }
  return a;
}

// Every pixel of `a` z-buffered into fb.
void draw(const ActivePixels& a, Framebuffer& fb) {
  for (int y = a.y0; y < a.y1; ++y) {
    fb.ready_row(y);
    for (auto i = a.row_begin[std::size_t(y - a.y0)]; i < a.row_begin[std::size_t(y - a.y0 + 1)];
         ++i) {
      const WinningPixel& p = a.pixels[i];
      fb.test_and_write(fb.index(p.x, y), p.z, p.id, p.rgb);
    }
  }
}

std::unique_ptr<Picture> picture(const std::string& kind, ActivePixels a, int h) {
  if (kind == "winning-pixels") return winning_pixels(std::move(a), PixelRecords{});
  if (kind == "run-length") return run_length(std::move(a), PixelRecords{});
  Framebuffer fb(a.width, RowSet::all(h), kBackground);
  draw(a, fb);
  return dense(std::move(fb), PixelRecords{});
}

// Rows in strips among the owners, every fifth row nobody's.
std::vector<int> region(int owners, int h) {
  std::vector<int> owner(static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y)
    owner[std::size_t(y)] = y % 5 == 4 ? -1 : y * owners / h;
  return owner;
}

struct Case {
  Strategy strategy;
  std::string picture;
  int nodes, width, height;
  std::string name() const {
    return strategy.name + " on " + picture + ", " + std::to_string(nodes) + " nodes, " +
           std::to_string(width) + "x" + std::to_string(height);
  }
};

// What the nodes composite, gathered and pasted at node 0 (as sort-last's output does); each
// node's stray rows (final pixels in rows the region gives another node) counted into `stray`.
Framebuffer composite_on_nodes(const Case& k, const std::vector<int>& owner,
                               std::vector<int>& stray) {
  Framebuffer out;
  const Topology t = (k.nodes & (k.nodes - 1)) == 0 ? Topology::Cube : Topology::Ring;
  run_local(k.nodes, t, [&](Comm& c) {
    CountedMemory memory;
    Counters work;
    Node node{c, memory, work};
    auto p = picture(k.picture, partial(c.rank(), k.nodes, k.width, k.height), k.height);
    k.strategy.composite(node, *p, owner);
    const ActivePixels mine = p->final_pixels(work);
    for (int y = mine.y0; y < mine.y1; ++y)
      stray[std::size_t(c.rank())] +=
          mine.row_count(y) && owner[std::size_t(y)] >= 0 && owner[std::size_t(y)] != c.rank();
    auto parts = gather(c, 0, pack_pixels(mine, sparse_message, PixelRecords{}, work));
    if (c.rank() != 0) return;
    out = Framebuffer(k.width, RowSet::all(k.height), kBackground);
    paste(parts, out, k.height, work);
  });
  // Nobody's rows may end anywhere (a node that never splits keeps them): not compared.
  for (int y = 0; y < k.height; ++y)
    if (owner[std::size_t(y)] < 0) out.clear_rows(y, y + 1, kBackground);
  return out;
}

// The sequential composite of the region's rows (the others left as background).
Framebuffer sequential(const Case& k, const std::vector<int>& owner) {
  Framebuffer all(k.width, RowSet::all(k.height), kBackground);
  for (int r = 0; r < k.nodes; ++r)
    draw(partial(r, k.nodes, k.width, k.height), all);
  Framebuffer kept(k.width, RowSet::all(k.height), kBackground);
  for (int y = 0; y < k.height; ++y) {
    if (owner[std::size_t(y)] < 0) continue;
    kept.ready_row(y);
    for (int x = 0; x < k.width; ++x) {
      const std::size_t i = all.index(x, y);
      kept.test_and_write(i, all.depth()[i], all.ids()[i], &all.rgb()[3 * i]);
    }
  }
  return kept;
}

void expect_sequential_picture(const Case& k) {
  const auto owner = region(k.strategy.owners(k.nodes), k.height);
  std::vector<int> stray(std::size_t(k.nodes), 0);
  const Framebuffer got = composite_on_nodes(k, owner, stray);
  const Framebuffer want = sequential(k, owner);
  EXPECT_EQ(stray, std::vector<int>(std::size_t(k.nodes), 0)) << k.name();
  EXPECT_TRUE(got.ids() == want.ids()) << k.name();
  EXPECT_TRUE(got.depth() == want.depth()) << k.name();
  EXPECT_TRUE(got.rgb() == want.rgb()) << k.name();
}

std::vector<Strategy> every_strategy() {
  std::vector<Strategy> v = strategies();
  v.push_back(radix_k({3}));
  v.push_back(radix_k({2, 3}));
  v.back().name += " 2,3";
  v.push_back(radix_k({8}));
  v.back().name += " 8";
  return v;
}

} // namespace

TEST(LocalStrategies, EveryStrategyAndPictureGivesTheSequentialComposite) {
  struct Screen {
    int w, h;
  };
  int cases = 0;
  for (const Strategy& s : every_strategy())
    for (const char* kind : kRepresentations)
      for (int P : {1, 2, 3, 4, 5, 6, 7, 8, 12, 16})
        for (Screen sc : {Screen{33, 17}, Screen{8, 40}, Screen{64, 3}}) {
          if (!s.refuses(P).empty()) continue;
          expect_sequential_picture({s, kind, P, sc.w, sc.h});
          ++cases;
        }
  EXPECT_GT(cases, 300);
}

TEST(LocalStrategies, BinarySwapAndFoldingAgreeStepByStepOnPowersOfTwo) {
  for (int P : {2, 4, 8}) {
    std::vector<std::vector<double>> steps[2];
    int which = 0;
    for (const Strategy& s : {binary_swap(), folding()}) {
      steps[which].resize(std::size_t(P));
      const auto owner = region(P, 24);
      run_local(P, Topology::Cube, [&](Comm& c) {
        CountedMemory memory;
        Counters work;
        Node node{c, memory, work};
        auto p = picture("winning-pixels", partial(c.rank(), P, 30, 24), 24);
        steps[which][std::size_t(c.rank())] = s.composite(node, *p, owner).step_bytes;
      });
      ++which;
    }
    EXPECT_EQ(steps[0], steps[1]) << "P=" << P;
  }
}
