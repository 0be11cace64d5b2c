// Kurc et al. §2: the modified scanline z-buffer keeps exactly the plain z-buffer's foremost
// pixels; merging two nodes' winning pixels gives the pixels of the whole scene.
#include <cstring>

#include <gtest/gtest.h>

#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

Scene random_scene(std::uint64_t seed, int w, int h) {
  Scene s = base_scene(w, h);
  Rng rng{seed};
  for (int k = 0; k < 10; ++k)
    add_sphere(s,
               {float(rng.uniform() * 4 - 2), float(rng.uniform() * 3 - 1.5),
                float(rng.uniform() * 2 - 1)},
               float(0.2 + rng.uniform() * 0.7), 2 + int(rng.uniform() * 2));
  // Some coplanar z-fighting quads as well.
  const std::uint32_t b = std::uint32_t(s.vertices.size());
  for (auto p : {glm::vec3(-2, -1, 0.5f), glm::vec3(2, -1, 0.5f), glm::vec3(2, 1, 0.5f),
                 glm::vec3(-2, 1, 0.5f)})
    s.vertices.push_back({p, {0, 0, 1}});
  s.triangles.push_back({{b, b + 1, b + 2}, 0});
  s.triangles.push_back({{b, b + 2, b + 3}, 0});
  s.triangles.push_back({{b + 1, b + 2, b + 3}, 0});
  return s;
}

TriangleBatch setup_range(const Scene& s, const NodeRenderer& nr, std::size_t lo, std::size_t hi,
                          std::size_t step = 1) {
  Counters c;
  std::vector<ProjectedVertex> pv;
  for (const auto& v : s.vertices)
    pv.push_back(nr.project(v, c));
  TriangleBatch b;
  for (std::size_t i = lo; i < hi; i += step) {
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, b, c);
  }
  return b;
}

void expect_same_as_framebuffer(const ActivePixels& a, const Framebuffer& fb) {
  std::size_t n = 0;
  for (int y = a.y0; y < a.y1; ++y) {
    int prev = -1;
    for (std::uint32_t k = a.row_begin[y - a.y0]; k < a.row_begin[y - a.y0 + 1]; ++k) {
      const WinningPixel& p = a.pixels[k];
      ASSERT_GT(int(p.x), prev) << "row " << y << " not sorted by x";
      prev = p.x;
      const std::size_t i = fb.index(p.x, y);
      ASSERT_EQ(p.id, fb.ids()[i]);
      ASSERT_EQ(p.z, fb.depth()[i]);
      ASSERT_EQ(0, std::memcmp(p.rgb, &fb.rgb()[3 * i], 3));
      ++n;
    }
  }
  EXPECT_EQ(n, fb.covered());
}

// Same rows, same pixels in the same order: position, depth, winner and colour.
void expect_same_pixels(const ActivePixels& got, const ActivePixels& want) {
  EXPECT_EQ(got.row_begin, want.row_begin);
  ASSERT_EQ(got.count(), want.count());
  for (std::size_t i = 0; i < got.count(); ++i) {
    EXPECT_EQ(got.pixels[i].x, want.pixels[i].x);
    EXPECT_EQ(got.pixels[i].z, want.pixels[i].z);
    EXPECT_EQ(got.pixels[i].id, want.pixels[i].id);
    EXPECT_EQ(0, std::memcmp(got.pixels[i].rgb, want.pixels[i].rgb, 3));
  }
}

} // namespace

TEST(ActivePixels, EqualsPlainZBufferOnRandomScenes) {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    Scene s = random_scene(seed, 120, 90);
    NodeRenderer nr(s);
    TriangleBatch b = setup_range(s, nr, 0, s.triangles.size());
    Counters c1, c2;
    Framebuffer fb = nr.make_framebuffer(RowSet::all(s.height));
    draw_batch(b, nr.shade(), fb, c1);
    SpanLists L = build_span_lists(b, s.width, s.height, c2);
    ActivePixels a = zbuffer_spans(L, b, nr.shade(), s.width, c2);
    expect_same_as_framebuffer(a, fb);
    EXPECT_EQ(c1.spans, c2.spans);
    EXPECT_EQ(c1.pixels_generated, c2.pixels_generated);
    // Pixels on fresh columns need no comparison: fewer depth tests than the plain z-buffer, and
    // they are the MSA/WPA loop's own (wpa_tested, wpa_appended), not the frame buffer's.
    EXPECT_LT(c2.wpa_tested, c1.pixels_tested);
    EXPECT_EQ(c2.pixels_tested, 0u);
    EXPECT_EQ(c2.wpa_tested + a.count(), c2.pixels_generated);
    EXPECT_EQ(c2.wpa_appended, a.count());
    EXPECT_EQ(c1.wpa_tested + c1.wpa_appended, 0u);
    // The span lists' covered columns are the WPA's size: its array reserved once, exactly.
    EXPECT_EQ(L.covered, a.count());
    EXPECT_EQ(a.pixels.capacity(), a.count());
  }
}

TEST(ActivePixels, MergingPartitionsGivesTheWholeScene) {
  Scene s = random_scene(9, 100, 80);
  NodeRenderer nr(s);
  Counters c;
  const auto full = render_scene(s, 1);
  // Interleaved triangle partition over 2 "nodes", merged.
  ActivePixels parts[2];
  for (int k = 0; k < 2; ++k) {
    TriangleBatch b = setup_range(s, nr, std::size_t(k), s.triangles.size(), 2);
    parts[k] = zbuffer_spans(build_span_lists(b, s.width, s.height, c), b, nr.shade(), s.width, c);
  }
  const std::uint64_t ops0 = c.list_merges;
  ActivePixels m = merge_active(parts[0], parts[1], c);
  EXPECT_EQ(c.list_merges - ops0, parts[0].pixels.size() + parts[1].pixels.size());
  EXPECT_EQ(c.merge_ops, 0u); // a sorted-list merge, not a z-buffer merge
  expect_same_as_framebuffer(m, full.image);
  // Splitting by rows and merging slices gives the same pixels.
  const auto upper = [](int y) { return y < 37; };
  const auto lower = [](int y) { return y >= 37; };
  ActivePixels top = merge_active(select_rows(parts[0], upper), select_rows(parts[1], upper), c);
  ActivePixels bot = merge_active(select_rows(parts[0], lower), select_rows(parts[1], lower), c);
  Framebuffer fb = nr.make_framebuffer(RowSet::all(80));
  scatter_active(top, fb);
  scatter_active(bot, fb);
  EXPECT_EQ(fb.rgb(), full.image.rgb());
  EXPECT_EQ(fb.ids(), full.image.ids());
}

TEST(ActivePixels, WireFormatRoundTrips) {
  Scene s = random_scene(5, 64, 48);
  NodeRenderer nr(s);
  Counters c;
  TriangleBatch b = setup_range(s, nr, 0, s.triangles.size());
  ActivePixels a = zbuffer_spans(build_span_lists(b, 64, 48, c), b, nr.shade(), 64, c);
  ActivePixels part = select_rows(a, [](int y) { return y >= 10 && y < 30; });
  std::size_t rows = 0;
  for (int y = 10; y < 30; ++y)
    rows += part.row_count(y) > 0;
  ASSERT_GT(rows, 0u);
  auto bytes = serialize_sparse(part);
  EXPECT_EQ(bytes.size(), 4 + 8 * rows + kWirePixelBytes * part.count());
  expect_same_pixels(deserialize_sparse(bytes.data(), bytes.size(), 64, 0, 48), part);
  EXPECT_THROW(deserialize_sparse(bytes.data(), bytes.size() - 1, 64, 0, 48), std::runtime_error);
}

// Merging a message as it is read gives the pixels, counts and errors of deserialising it first.
TEST(ActivePixels, MergeFromTheWireEqualsMergeAfterDeserialising) {
  Scene s = random_scene(9, 100, 80);
  NodeRenderer nr(s);
  Counters c;
  ActivePixels parts[2];
  for (int k = 0; k < 2; ++k) {
    TriangleBatch b = setup_range(s, nr, std::size_t(k), s.triangles.size(), 2);
    parts[k] = zbuffer_spans(build_span_lists(b, s.width, s.height, c), b, nr.shade(), s.width, c);
  }
  const auto kept = [](int y) { return y % 3 != 1; };
  const ActivePixels mine = select_rows(parts[0], kept);
  const auto msg = serialize_sparse(select_rows(parts[1], kept));
  Counters before, fused;
  const ActivePixels want =
      merge_active(mine, deserialize_sparse(msg.data(), msg.size(), 100, 0, 80), before);
  std::uint64_t received = 0;
  const ActivePixels got = merge_active_sparse(mine, msg.data(), msg.size(), fused, received);
  EXPECT_EQ(received, select_rows(parts[1], kept).count());
  EXPECT_EQ(fused.list_merges, before.list_merges);
  expect_same_pixels(got, want);
  EXPECT_THROW(merge_active_sparse(mine, msg.data(), msg.size() - 1, fused, received),
               std::runtime_error);
}

// The all-to-all's shortcuts (one pass for every destination's message, one merge of many
// messages) give exactly the bytes and pixels of the row-by-row originals.
TEST(ActivePixels, ByOwnerMessagesAndManyWayMergeEqualTheOriginals) {
  Scene s = random_scene(11, 96, 64);
  NodeRenderer nr(s);
  Counters c;
  constexpr int kNodes = 5;
  std::vector<int> owner(64);
  for (int y = 0; y < 64; ++y)
    owner[std::size_t(y)] = (y / 3 + y % 2) % kNodes; // fragmented, as an HBP partition can be
  std::vector<std::vector<std::vector<std::uint8_t>>> sent; // [node][destination]
  for (int k = 0; k < kNodes; ++k) {
    TriangleBatch b = setup_range(s, nr, std::size_t(k), s.triangles.size(), kNodes);
    ActivePixels a = zbuffer_spans(build_span_lists(b, 96, 64, c), b, nr.shade(), 96, c);
    sent.push_back(serialize_sparse_by_owner(a, owner, kNodes));
    ASSERT_EQ(sent.back().size(), std::size_t(kNodes));
    for (int d = 0; d < kNodes; ++d)
      EXPECT_EQ(sent.back()[std::size_t(d)], serialize_sparse(select_rows(a, [&](int y) {
                  return owner[std::size_t(y)] == d;
                })));
  }
  std::size_t nonempty = 0;
  for (int d = 0; d < kNodes; ++d) {
    std::vector<const std::vector<std::uint8_t>*> in;
    ActivePixels expected;
    for (int k = 0; k < kNodes; ++k) {
      const auto& m = sent[std::size_t(k)][std::size_t(d)];
      in.push_back(&m);
      ActivePixels got = deserialize_sparse(m.data(), m.size(), 96, 0, 64);
      expected = k == 0 ? got : merge_active(expected, got, c);
    }
    std::vector<std::uint64_t> counts;
    ActivePixels merged = merge_sparse(in, 96, 0, 64, counts);
    ASSERT_EQ(counts.size(), std::size_t(kNodes));
    EXPECT_EQ(merged.row_begin, expected.row_begin);
    ASSERT_EQ(merged.count(), expected.count());
    nonempty += merged.count() > 0;
    for (std::size_t i = 0; i < merged.count(); ++i) {
      const WinningPixel &p = merged.pixels[i], &q = expected.pixels[i];
      EXPECT_TRUE(p.x == q.x && p.z == q.z && p.id == q.id && std::memcmp(p.rgb, q.rgb, 3) == 0);
    }
  }
  EXPECT_GT(nonempty, 1u);
  auto bad = sent[0][std::size_t(owner[0])]; // holds row 0's pixels at least
  ASSERT_GT(bad.size(), 12u);
  bad.pop_back();
  std::vector<const std::vector<std::uint8_t>*> truncated{&bad};
  std::vector<std::uint64_t> counts;
  EXPECT_THROW(merge_sparse(truncated, 96, 0, 64, counts), std::runtime_error);
}
