// Kurc, Aykanat, Ozguc: full z-buffer merging (ZBUF-EXC), the paper's baseline. Each node
// z-buffers its spans into a full-screen frame buffer, then recursive halving over all pixel
// locations: stage i halves the current band and swaps halves with the neighbour over channel i;
// every location of the half is compared.
#include <cstring>

#include "algo/kurc_merge_scheme.hpp"
#include "raster/zbuffer.hpp"

namespace zc::kurc {

namespace {

class ZbufExc : public MergeScheme {
public:
  const char* name() const override { return "zbuf-exc"; }

  void local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                     Counters& w) override {
    full_ = nr.make_framebuffer(RowSet::all(nr.height()));
    ctx.alloc(double(full_.pixel_count() * records::kurc::kZbufferLocation), "full z-buffer");
    w.pixels_cleared = std::uint64_t(nr.width()) * nr.height();
    for (int y = 0; y < nr.height(); ++y)
      for (std::uint32_t s = spans.lists.row_begin[y]; s < spans.lists.row_begin[y + 1]; ++s)
        draw_span(nr, spans, spans.lists.spans[s], y, w);
  }

  MergeMeasures merge(NodeContext& ctx, Counters& w) override {
    Comm& c = ctx.comm();
    const int r = c.rank();
    MergeMeasures m;
    y0_ = 0;
    y1_ = full_.rows().end;
    for (int i = 0; i < c.dimension(); ++i) {
      const int partner = r ^ (1 << i), mid = y0_ + (y1_ - y0_) / 2;
      const bool top = !(r & (1 << i));                       // keeps the upper half
      const int sy0 = top ? mid : y0_, sy1 = top ? y1_ : mid; // the half that leaves
      // The leaving half is a contiguous band of the z-buffer, sent in place (zcube's copy of its
      // three arrays into one payload is an artefact); the arriving half needs a buffer of its own.
      const std::size_t W = std::size_t(full_.width());
      // Charged as the paper's locations (z and shading, records.hpp), without zcube's triangle id.
      const std::size_t n_out = (sy1 - sy0) * W;
      Message out{full_.pack_locations(sy0 * W, n_out), n_out * records::kurc::kZbufferLocation};
      m.step_bytes.push_back(double(out.charged));
      const int ky0 = top ? y0_ : mid, ky1 = top ? mid : y1_;
      const double rx = double(records::kurc::kZbufferLocation) * double(ky1 - ky0) * double(W);
      ctx.alloc(rx, "receive buffer");
      auto h = c.isend(partner, kTagZbuf + i, std::move(out));
      Bytes in = c.recv(partner, kTagZbuf + i);
      h->wait();
      const std::size_t n = full_.merge_locations(in, ky0 * W);
      ctx.release(rx);
      w.merge_ops += n;
      m.merge_load += n;
      y0_ = ky0;
      y1_ = ky1;
    }
    return m;
  }

  // The covered locations of the node's final band, packed into pixel records: every location of
  // the band is read (charged as the bytes it scans, kLocationBytes each) and each covered one
  // becomes a record.
  ActivePixels final_pixels(Counters& w) override {
    ActivePixels a;
    a.width = full_.width();
    a.y0 = y0_;
    a.y1 = y1_;
    a.row_begin.assign(std::size_t(y1_ - y0_) + 1, 0);
    const std::size_t W = std::size_t(full_.width());
    std::size_t covered = 0;
    for (std::size_t i = std::size_t(y0_) * W; i < std::size_t(y1_) * W; ++i)
      covered += full_.ids()[i] != kNoTriangle;
    a.pixels.reserve(covered);
    w.bytes_packed +=
        Framebuffer::kLocationBytes * W * std::size_t(y1_ - y0_) + sizeof(WinningPixel) * covered;
    for (int y = y0_; y < y1_; ++y) {
      for (int x = 0; x < a.width; ++x) {
        const std::size_t i = full_.index(x, y);
        if (full_.ids()[i] == kNoTriangle) continue;
        WinningPixel p{full_.depth()[i], full_.ids()[i], std::uint16_t(x), {}};
        std::memcpy(p.rgb, &full_.rgb()[3 * i], 3);
        a.pixels.push_back(p);
      }
      a.row_begin[y - y0_ + 1] = std::uint32_t(a.pixels.size());
    }
    return a;
  }

private:
  // One span of the span lists z-buffered into the full frame buffer.
  void draw_span(const NodeRenderer& nr, const NodeSpans& spans, const SpanRecord& sp, int y,
                 Counters& w) {
    const ScreenTriangle& t = spans.batch.tris[sp.tri];
    const RowShader rs(t, spans.batch, nr.shade(), y);
    for (int x = sp.x0; x <= sp.x1; ++x) {
      const std::size_t i = full_.index(x, y);
      const float z = rs.depth(x);
      if (!in_front(z, t.id, full_.depth()[i], full_.ids()[i])) continue;
      std::uint8_t rgb[3];
      rs.color(x, rgb, w);
      full_.test_and_write(i, z, t.id, rgb);
      ++w.pixels_written;
    }
    w.pixels_generated += std::uint64_t(sp.x1 - sp.x0 + 1);
    w.pixels_tested += std::uint64_t(sp.x1 - sp.x0 + 1);
  }

  Framebuffer full_;
  int y0_ = 0, y1_ = 0; // the band of final pixels this node holds after merging
};

} // namespace

std::unique_ptr<MergeScheme> make_zbuf_exc() {
  return std::make_unique<ZbufExc>();
}

} // namespace zc::kurc
