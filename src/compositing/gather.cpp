#include "compositing/gather.hpp"

#include "comm/collectives.hpp"

namespace zc::compositing {

Message pack_pixels(const ActivePixels& mine, Message (*charge)(Bytes, const PixelRecords&),
                    const PixelRecords& records, Counters& w) {
  Message part = charge(serialize_sparse(mine), records);
  w.bytes_packed += part.payload.size();
  w.records_packed += mine.count(); // pixel by pixel, field by field
  return part;
}

std::vector<Message> gather(Comm& c, int root, Message part) {
  return coll::gatherv(c, root, std::move(part));
}

std::uint64_t paste(const std::vector<Message>& parts, Framebuffer& picture, int height,
                    Counters& w) {
  std::uint64_t pasted = 0;
  for (const auto& m : parts) {
    const Bytes& b = m.payload;
    const ActivePixels got = deserialize_sparse(b.data(), b.size(), picture.width(), 0, height);
    scatter_active(got, picture);
    w.bytes_packed += 2 * b.size();
    w.records_packed += 2 * got.count(); // each pixel read from its record, then written
    pasted += got.count();
  }
  return pasted;
}

} // namespace zc::compositing
