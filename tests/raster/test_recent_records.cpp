// The set-up records a span loop fetches (raster/recent_records.hpp, Counters::records_fetched):
// the window's rule on hand-counted cases, and Kurc's active z-buffer counting by it.
#include <gtest/gtest.h>

#include "raster/active_pixels.hpp"
#include "raster/recent_records.hpp"
#include "raster/zbuffer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {
constexpr std::size_t N = RecentRecords::kWindow;
}

TEST(RecentRecords, ABatchWithinTheWindowIsAllInItAfterItsSetUp) {
  RecentRecords r;
  r.reset(N);
  for (std::size_t i = 0; i < N; ++i)
    EXPECT_EQ(r.read(N - 1 - i), 0u);
}

TEST(RecentRecords, CountsARecordNotAmongTheLastNRead) {
  // 2N records: the set-up left N..2N-1 in the window; record 0 evicts N from their slot.
  RecentRecords r;
  r.reset(2 * N);
  std::uint64_t fetched = r.read(0) + r.read(0); // two spans of one triangle: one fetch
  EXPECT_EQ(fetched, 1u);
  for (std::size_t i = 1; i <= N; ++i) // N more distinct records, none in the window
    fetched += r.read(i);
  EXPECT_EQ(fetched, N + 1);
  fetched += r.read(0); // the first again: record N took its slot, N + 2 in all
  EXPECT_EQ(fetched, N + 2);
  fetched += r.read(1) + r.read(N - 1); // among the last N read: no fetch
  EXPECT_EQ(fetched, N + 2);
}

TEST(RecentRecords, ActiveZBufferCountsItsSpansRecords) {
  // HandCountedRightTriangle's triangle (rows 0-6) set up once, its record copied to make a batch
  // of N + 1: record N shares record 0's slot and the set-up wrote it last.
  const int w = 64, h = 8;
  TriangleBatch b = right_triangle(w, h);
  ASSERT_EQ(b.tris.size(), 1u);
  Counters ignored;
  const SpanLists one = build_span_lists(b, w, h, ignored);
  ASSERT_EQ(one.spans.size(), 7u);
  ShadeContext ctx;
  std::vector<Material> mats{Material{}};
  ctx.materials = &mats;
  Counters c;
  (void)zbuffer_spans(one, b, ctx, w, c);
  EXPECT_EQ(c.records_fetched, 0u); // one record, in the window after its set-up
  b.tris.resize(N + 1, b.tris[0]);
  // Rows 0-3 drawn by records 0, 0, N, 0: fetched, read last, fetched, fetched.
  SpanLists L = one;
  const std::uint32_t tri[7] = {0, 0, std::uint32_t(N), 0, 0, 0, 0};
  for (std::size_t s = 0; s < L.spans.size(); ++s)
    L.spans[s].tri = tri[s];
  Counters d;
  (void)zbuffer_spans(L, b, ctx, w, d);
  EXPECT_EQ(d.span_starts, 7u);
  EXPECT_EQ(d.records_fetched, 3u);
}
