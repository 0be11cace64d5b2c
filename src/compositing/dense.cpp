// The dense representation (a full z-buffer): rows travel as runs of locations, each charged as
// records.location; a run is a contiguous band of the z-buffer, sent in place, so only a message
// gathered from several runs is a copy. The arriving rows need a buffer of their own, held from
// before the exchange (Kurc et al.'s ZBUF-EXC receives into it).
#include "compositing/dense.hpp"

#include <cstring>
#include <stdexcept>

namespace zc::compositing {

namespace {

// Runs [y0, y1) of the rows with in(y).
template <class Pred> std::vector<std::pair<int, int>> runs(int h, Pred in) {
  std::vector<std::pair<int, int>> r;
  for (int y = 0; y < h; ++y)
    if (in(y)) {
      if (r.empty() || r.back().second != y) r.push_back({y, y});
      r.back().second = y + 1;
    }
  return r;
}

class Dense final : public Picture {
public:
  Dense(Framebuffer full, const PixelRecords& rec)
      : full_(std::move(full)), rec_(rec), held_(std::size_t(full_.rows().end), 1) {}
  const char* representation() const override { return "dense"; }

  std::vector<Message> split(const Routing& r, Merge, Node& n) override {
    const int H = int(held_.size());
    std::vector<Message> out(std::size_t(r.parts));
    std::vector<std::vector<std::pair<int, int>>> bands(std::size_t(r.parts));
    for (int y = 0; y < H; ++y) {
      const int k = held_[y] ? r.dest[y] : -1;
      if (k < 0 || k == r.self || k >= r.parts) continue;
      auto& b = bands[std::size_t(k)];
      if (b.empty() || b.back().second != y) b.push_back({y, y});
      b.back().second = y + 1;
    }
    for (int k = 0; k < r.parts; ++k)
      if (k != r.self) out[std::size_t(k)] = pack(bands[std::size_t(k)], n);
    for (int y = 0; y < H; ++y)
      held_[y] = sends(r, y, r.self);
    kept_ = runs(H, [&](int y) { return held_[y] != 0; });
    std::size_t locations = 0;
    for (auto [y0, y1] : kept_)
      locations += std::size_t(y1 - y0) * std::size_t(full_.width());
    receive_ = double(r.incoming) * double(locations * rec_.location);
    n.memory.alloc(receive_, "receive buffer");
    return out;
  }

  std::uint64_t merge(std::vector<Message> in, Merge, Node& n) override {
    std::uint64_t merged = 0;
    for (const Message& m : in)
      merged += merge_runs(m.payload);
    n.memory.release(receive_ + sent_gathered_);
    sent_gathered_ = 0;
    n.work.merge_ops += merged;
    return merged;
  }

  ActivePixels final_pixels(Counters& w) override;
  Framebuffer& framebuffer() { return full_; }

private:
  bool sends(const Routing& r, int y, int k) const { return held_[y] && r.dest[y] == k; }

  // A message over the rows kept (its runs in order) z-buffered into them.
  // (A message from this process keeps the rows its sender never drew as repeated runs, read as
  // such; one from another process, the MPI backend's, is the whole string.)
  std::uint64_t merge_runs(const Payload& payload) {
    const std::size_t W = std::size_t(full_.width());
    const RunBytes* runs = payload.runs();
    std::uint64_t merged = 0;
    std::size_t at = 0;
    for (auto [y0, y1] : kept_) {
      const std::size_t bytes = std::size_t(y1 - y0) * W * Framebuffer::kLocationBytes;
      if (at + bytes > payload.size()) throw std::logic_error("dense: a message short of its rows");
      const std::size_t first = std::size_t(y0) * W;
      merged += runs ? full_.merge_locations(*runs, at, bytes, first)
                     : full_.merge_locations(payload.data() + at, bytes, first);
      at += bytes;
    }
    return merged;
  }

  // The rows of `band` as one message; gathered into a buffer of its own when not one band.
  Message pack(const std::vector<std::pair<int, int>>& band, Node& n) {
    const std::size_t W = std::size_t(full_.width());
    Message m;
    RunBytes rows;
    for (auto [y0, y1] : band) {
      RunBytes b = full_.pack_location_runs(std::size_t(y0) * W, std::size_t(y1 - y0) * W);
      if (rows.size() == 0)
        rows = std::move(b); // one band (the usual case): its packed bytes are the payload
      else
        rows.append(b);
      m.charged += std::size_t(y1 - y0) * W * rec_.location;
    }
    m.payload = std::move(rows);
    // One band is sent in place by the modelled program; zcube copies it into its message.
    if (band.size() == 1) n.work.wire_bytes += m.payload.size();
    if (band.size() > 1) {
      n.work.bytes_packed += m.charged;
      n.memory.alloc(double(m.charged), "send buffer");
      sent_gathered_ += double(m.charged);
    }
    return m;
  }

  Framebuffer full_;
  PixelRecords rec_;
  std::vector<char> held_;
  std::vector<std::pair<int, int>> kept_;
  double receive_ = 0, sent_gathered_ = 0;
};

// The covered locations of the rows held, as pixel records: every location of those rows is read
// for its coverage (a location scanned) and each covered one becomes a record, field by field.
ActivePixels Dense::final_pixels(Counters& w) {
  ActivePixels a;
  a.width = full_.width();
  a.y0 = 0;
  a.y1 = int(held_.size());
  a.row_begin.assign(held_.size() + 1, 0);
  std::size_t rows = 0;
  const float* depth = full_.depth_data();
  const std::uint32_t* ids = full_.ids_data();
  const std::uint8_t* rgb = full_.rgb_data();
  for (int y = a.y0; y < a.y1; ++y) {
    if (held_[y]) {
      ++rows;
      // A row the host never touched is background: no covered location (the model still scans it).
      for (int x = 0; x < a.width && !full_.untouched(y); ++x) {
        const std::size_t i = full_.index(x, y);
        if (ids[i] == kNoTriangle) continue;
        WinningPixel p{depth[i], ids[i], std::uint16_t(x), {}};
        std::memcpy(p.rgb, &rgb[3 * i], 3);
        a.pixels.push_back(p);
      }
    }
    a.row_begin[std::size_t(y - a.y0) + 1] = std::uint32_t(a.pixels.size());
  }
  w.locations_scanned += std::uint64_t(a.width) * rows;
  w.records_packed += a.pixels.size();
  w.bytes_packed += sizeof(WinningPixel) * a.pixels.size();
  return a;
}

} // namespace

std::unique_ptr<Picture> dense(Framebuffer full, const PixelRecords& records) {
  return std::make_unique<Dense>(std::move(full), records);
}

Framebuffer& framebuffer(Picture& dense_picture) {
  return dynamic_cast<Dense&>(dense_picture).framebuffer();
}

} // namespace zc::compositing
