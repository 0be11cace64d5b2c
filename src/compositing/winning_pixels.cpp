// Kurc, Aykanat, Ozguc's winning pixel array as a compositing representation. The pairwise merge
// is §3.1's (retained and received lists merged into a new array that replaces the WPA), the
// many-message merge §3.2's (the rows kept z-buffered: local pixels scattered, each received one
// compared).
#include "compositing/winning_pixels.hpp"

#include <algorithm>
#include <cstring>

#include "util/record_io.hpp"

namespace zc::compositing {

namespace {

// Runs of consecutive rows routed to each destination, in one pass: a message over more than one
// run is gathered from several places of the array (a copy); one run is sent in place, the local
// foremost pixels being stored consecutively precisely for that (§2).
std::vector<int> runs_per_destination(const std::vector<int>& dest, int parts) {
  std::vector<int> runs(std::size_t(parts), 0);
  for (std::size_t y = 0; y < dest.size(); ++y)
    if (dest[y] >= 0 && dest[y] < parts && (y == 0 || dest[y - 1] != dest[y]))
      ++runs[std::size_t(dest[y])];
  return runs;
}

class WinningPixels final : public Picture {
public:
  WinningPixels(ActivePixels wpa, const PixelRecords& rec, const Encoding& enc)
      : mine_(std::move(wpa)), rec_(rec), enc_(enc), held_(enc.held(mine_, rec)) {}
  const char* representation() const override { return enc_.name; }

  std::vector<Message> split(const Routing& r, Merge how, Node& n) override {
    if (how == Merge::Zbuffer) hold_owned_zbuffer(r, n);
    // The list merge keeps its own rows as pixels (keep_, below): only the others' are serialised.
    std::vector<int> others;
    if (how == Merge::Lists) {
      others = r.dest;
      std::replace(others.begin(), others.end(), r.self, -1);
    }
    auto parts = serialize_sparse_by_owner(mine_, how == Merge::Lists ? others : r.dest, r.parts);
    n.work.wire_records += routed_pixels(r); // converted to wire records, or the kept copied out
    const std::vector<int> runs = runs_per_destination(r.dest, r.parts);
    std::vector<Message> out;
    gathered_ = 0;
    for (int k = 0; k < r.parts; ++k) {
      out.push_back(enc_.message(std::move(parts[std::size_t(k)]), rec_));
      if (k != r.self && runs[std::size_t(k)] > 1) gathered_ += double(out.back().charged);
    }
    n.work.bytes_packed += std::uint64_t(gathered_);
    n.memory.alloc(gathered_, how == Merge::Lists ? "send buffer" : "send buffers");
    if (how == Merge::Lists)
      keep_ = select_rows(mine_, [&](int y) { return r.dest[y - mine_.y0] == r.self; });
    else
      local_ = std::move(out[std::size_t(r.self)].payload).take();
    out[std::size_t(r.self)] = Message{};
    return out;
  }

  std::uint64_t merge(std::vector<Message> in, Merge how, Node& n) override {
    return how == Merge::Lists ? merge_lists(std::move(in), n) : merge_zbuffer(std::move(in), n);
  }

  ActivePixels final_pixels(Counters&) override { return std::move(mine_); }

private:
  // The pixels of the rows the routing sends somewhere (kept rows included).
  std::uint64_t routed_pixels(const Routing& r) const {
    std::uint64_t n = 0;
    for (int y = mine_.y0; y < mine_.y1; ++y)
      if (const int d = r.dest[std::size_t(y - mine_.y0)]; d >= 0 && d < r.parts)
        n += mine_.row_count(y);
    return n;
  }

  // §3.2: "Each processor holds a local z-buffer of size N x N/P" (its owned scanlines).
  void hold_owned_zbuffer(const Routing& r, Node& n) {
    n.memory.release(zbuffer_); // a previous round's, already merged into the pixels held
    std::uint64_t rows = 0;
    for (int d : r.dest)
      rows += d == r.self;
    zbuffer_ = double(rows) * mine_.width * double(rec_.location);
    n.memory.alloc(zbuffer_, "z-buffer of the owned scanlines");
  }

  // §3.1: the retained and received pixels merge into a new array, which replaces the WPA.
  std::uint64_t merge_lists(std::vector<Message> in, Node& n) {
    if (in.empty()) { // every row held was sent away or kept: the kept rows replace the array
      mine_ = std::move(keep_);
      n.memory.release(held_ + gathered_);
      held_ = enc_.held(mine_, rec_);
      n.memory.alloc(held_, "pixels kept");
      gathered_ = 0;
      return 0;
    }
    std::uint64_t load = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
      const Message& m = in[i];
      const double received = double(m.charged);
      n.memory.alloc(received, "receive buffer");
      const Bytes& b = m.payload;
      std::uint64_t got = 0;
      mine_ = merge_active_sparse(keep_, b.data(), b.size(), n.work, got);
      n.work.wire_records += got; // each converted back from its wire record as it is merged
      load += got;
      n.memory.alloc(enc_.held(mine_, rec_), "merged pixels");
      n.memory.release(held_ + gathered_ + received);
      held_ = enc_.held(mine_, rec_);
      gathered_ = 0;
      // A next message merges into the merged pixels; after the last, nothing is kept apart
      // (copying the merged array is zcube's work, which no counter prices).
      keep_ = i + 1 < in.size() ? mine_ : ActivePixels{};
    }
    return load;
  }

  // §3.2: the local pixels first, then every other node's in rank order, into the rows kept: one
  // operation a local pixel and one a received pixel, whatever the number of senders.
  std::uint64_t merge_zbuffer(std::vector<Message> in, Node& n) {
    double received = 0;
    std::vector<const Bytes*> order{&local_};
    for (const Message& m : in) {
      received += double(m.charged);
      order.push_back(&m.payload.bytes());
    }
    n.memory.alloc(received, "receive buffers");
    n.memory.release(gathered_);
    std::vector<std::uint64_t> counts;
    mine_ = merge_sparse(order, mine_.width, mine_.y0, mine_.y1, counts);
    std::uint64_t received_pixels = 0;
    for (std::size_t i = 1; i < counts.size(); ++i)
      received_pixels += counts[i];
    n.work.merge_ops += counts[0] + received_pixels;
    n.work.wire_records += counts[0] + received_pixels; // each converted back from the wire
    n.memory.release(received);
    return received_pixels;
  }

  ActivePixels mine_, keep_;
  Bytes local_; // the rows kept, serialised (the z-buffer merge's local pixels)
  PixelRecords rec_;
  Encoding enc_;
  double held_ = 0, gathered_ = 0, zbuffer_ = 0;
};

} // namespace

Message sparse_message(Bytes payload, const PixelRecords& rec) {
  const std::uint32_t rows =
      payload.size() >= 4 ? RecordReader(payload, "winning pixels").get<std::uint32_t>() : 0;
  const std::size_t header = 4 + 8 * std::size_t(rows);
  const std::size_t pixels = (payload.size() - std::min(header, payload.size())) / kWirePixelBytes;
  const std::size_t charged = header + pixels * rec.pixel;
  return {std::move(payload), charged};
}

double held_bytes(const ActivePixels& a, const PixelRecords& rec) {
  return double(a.count() * rec.pixel + a.row_begin.size() * rec.count);
}

std::unique_ptr<Picture> active_pixels(ActivePixels a, const PixelRecords& records,
                                       const Encoding& encoding) {
  return std::make_unique<WinningPixels>(std::move(a), records, encoding);
}

std::unique_ptr<Picture> winning_pixels(ActivePixels wpa, const PixelRecords& records) {
  return active_pixels(std::move(wpa), records, {"winning-pixels", sparse_message, held_bytes});
}

} // namespace zc::compositing
