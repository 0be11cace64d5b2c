// Several nodes' blocks in one message (comm.hpp): its charged size, and its packed form for a
// backend that sends bytes.
#include "comm/comm.hpp"
#include "comm/wire.hpp"

namespace zc {

namespace {
constexpr std::size_t kPackedBlockHeader = 4 + 8 + 8; // i32 owner, u64 size, u64 charged
}

std::size_t blocks_charged(std::size_t count, std::size_t charged) {
  return kBlocksFrameBytes + kBlockFrameBytes * count + charged;
}

std::size_t blocks_charged(const Blocks& blocks) {
  std::size_t charged = 0;
  for (const auto& k : blocks)
    charged += k.data.charged;
  return blocks_charged(blocks.size(), charged);
}

std::size_t packed_blocks_size(std::size_t count, std::size_t payload_bytes) {
  return 4 + kPackedBlockHeader * count + payload_bytes;
}

std::size_t packed_blocks_size(const Blocks& blocks) {
  std::size_t bytes = 0;
  for (const auto& k : blocks)
    bytes += k.data.payload.size();
  return packed_blocks_size(blocks.size(), bytes);
}

Message pack_blocks(const Blocks& blocks) {
  RecordWriter b(packed_blocks_size(blocks)); // reserved once: one allocation
  b.put(std::uint32_t(blocks.size()));
  for (const auto& k : blocks) {
    b.put(std::int32_t(k.owner));
    b.put(std::uint64_t(k.data.payload.size()));
    b.put(std::uint64_t(k.data.charged));
  }
  for (const auto& k : blocks)
    b.put(k.data.payload.bytes());
  return {std::move(b).take(), blocks_charged(blocks)};
}

Blocks unpack_blocks(const Message& m) {
  RecordReader in(m.payload, "collective");
  const auto n = in.get<std::uint32_t>();
  in.require(n, kPackedBlockHeader); // before allocating what a corrupt count asks for
  Blocks blocks(n);
  std::vector<std::uint64_t> sizes(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    blocks[i].owner = in.get<std::int32_t>();
    sizes[i] = in.get<std::uint64_t>();
    blocks[i].data.charged = std::size_t(in.get<std::uint64_t>());
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    in.require(sizes[i], 1);
    const std::uint8_t* p = in.get_bytes(std::size_t(sizes[i]));
    blocks[i].data.payload = Bytes(p, p + sizes[i]);
  }
  return blocks;
}

} // namespace zc
