#pragma once
// The scanline z-buffer (Charles et al. §2): every screen triangle is scanned row by row over the
// rows of the frame buffer, and each generated pixel is kept if it is in front of the stored one.
#include <algorithm>
#include <cstdint>

#include "raster/framebuffer.hpp"
#include "raster/setup.hpp"
#include "raster/shade.hpp"
#include "util/counters.hpp"

namespace zc {

// One edge of a screen triangle walked down its rows: the span bound this edge sets on row y is
// floor(K(y) / D), K growing by the same integer every row, kept as quotient and remainder. Exact
// integers throughout: the bounds ScreenTriangle::span computes, without a division per row.
class EdgeWalk {
public:
  EdgeWalk() = default;
  // Edge e of t from row y on, stepping `stride` rows at a time.
  EdgeWalk(const ScreenTriangle& t, int e, int y, int stride);
  // Narrows [lo, hi] to this edge on the current row (false: the row holds no pixel), then steps.
  bool clip_and_step(std::int64_t& lo, std::int64_t& hi, std::int64_t width) {
    bool ok = true;
    if (sign_ > 0)
      lo = std::max(lo, -std::clamp(q_, -width, std::int64_t(0)));
    else if (sign_ < 0)
      hi = std::min(hi, std::clamp(q_, std::int64_t(-1), width - 1));
    else
      ok = q_ >= 0;
    q_ += dq_;
    r_ += dr_;
    if (r_ >= d_) {
      r_ -= d_;
      ++q_;
    }
    return ok;
  }

private:
  int sign_ = 0;        // sign of the edge's A: a left bound (+), a right bound (-), horizontal (0)
  std::int64_t d_ = 1;  // divisor |A| * kSub (1 for a horizontal edge: q_ is K itself)
  std::int64_t q_ = 0;  // floor(K / d_) on the current row
  std::int64_t r_ = 0;  // K - q_ * d_, in [0, d_)
  std::int64_t dq_ = 0; // the step of K a row, as quotient and remainder of d_
  std::int64_t dr_ = 0;
};

// Up to kMax spans (row, first and last column), as NarrowScan finds them.
struct SpanBatch {
  static constexpr int kMax = 64;
  int n = 0;
  int y[kMax], x0[kMax], x1[kMax];
};

// The spans of a triangle at most 32 columns wide, without a division: its three edge functions
// evaluated at the pixel centres of its column box, 8 columns a vector instruction (AVX2), row
// after row. The same integers as ScreenTriangle::span, so the same spans, when they fit 32 bits.
class NarrowScan {
public:
  static constexpr int kMaxColumns = 32;
  // False when `t` is wider than 32 columns or its column box unknown, when its edge functions
  // over the box and rows [y, yend) of `rows` exceed 2^30, or when the host has no AVX2.
  bool init(const ScreenTriangle& t, const RowSet& rows, int y, int yend);
  // The next non-empty spans in row order; false when none remain.
  bool next(SpanBatch& b);

private:
  int x0_ = 0, columns_ = 0, y_ = 0, yend_ = 0, stride_ = 1;
  std::int32_t e_[3] = {};  // edge function minus bias at the centre of (x0_, y_)
  std::int32_t dx_[3] = {}; // its step a column
  std::int32_t dy_[3] = {}; // its step a row of the set
};

// Calls f(y, x0, x1) for every non-empty span of `t` on the rows of `rows`: the spans of
// ScreenTriangle::span, row after row.
template <class F>
void for_each_span(const ScreenTriangle& t, const RowSet& rows, int width, F&& f) {
  int y = rows.first_from(t.ymin);
  const int yend = std::min(t.ymax + 1, rows.end);
  if (y >= yend) return;
  if (t.bx1 >= t.bx0 && t.bx1 - t.bx0 < NarrowScan::kMaxColumns) {
    NarrowScan scan;
    if (scan.init(t, rows, y, yend)) {
      SpanBatch b;
      while (scan.next(b))
        for (int k = 0; k < b.n; ++k)
          f(b.y[k], b.x0[k], b.x1[k]);
      return;
    }
  }
  if (yend - y <= rows.stride) { // one row: its three divisions cost less than a walk's set-up
    int x0, x1;
    if (t.span(y, width, x0, x1)) f(y, x0, x1);
    return;
  }
  EdgeWalk e[3] = {{t, 0, y, rows.stride}, {t, 1, y, rows.stride}, {t, 2, y, rows.stride}};
  const std::int64_t w = width;
  for (; y < yend; y += rows.stride) {
    std::int64_t lo = 0, hi = w - 1;
    const bool ok0 = e[0].clip_and_step(lo, hi, w);
    const bool ok1 = e[1].clip_and_step(lo, hi, w);
    const bool ok2 = e[2].clip_and_step(lo, hi, w);
    if (ok0 && ok1 && ok2 && lo <= hi) f(y, int(lo), int(hi));
  }
}

// Scan-converts one screen triangle into `fb`, on the rows of `rows` (a subset of fb.rows()).
// When `newly_covered` is given, it is increased by the pixels this triangle writes first (pixels
// that held no triangle before): summed over a frame, the covered pixels without a final scan.
// When `recent` is given, every span enters its depth lines there (c.far_lines: those it did not
// hold).
void draw_triangle(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx,
                   const RowSet& rows, Framebuffer& fb, Counters& c,
                   std::uint64_t* newly_covered = nullptr, RecentLines* recent = nullptr);

// Pixels [x0, x1] of row y of `t` (a span found before, e.g. from Kurc et al.'s span lists)
// z-buffered into `fb`: the span started from its planes, then the same pixel loop as
// draw_triangle's (eight pixels at a time when untextured), so the same pixels bit for bit. Counts
// the span start, the fragments (generated, tested, written) and the far lines of
// fb.recent_lines(), not the span nor an edge walk.
void draw_span(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx, int y,
               int x0, int x1, Framebuffer& fb, Counters& c);

// Draws every triangle of a batch, in order, counting the far lines of fb.recent_lines() (the
// z-buffer of a node or of the sequential program, one triangle after another; the threaded
// renderer's bands draw in another order and do not count them).
void draw_batch(const TriangleBatch& batch, const ShadeContext& ctx, Framebuffer& fb, Counters& c);

} // namespace zc
