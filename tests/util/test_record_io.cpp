// The wire format's reader and writers (util/record_io.hpp): what is written reads back, and a
// truncated or corrupt payload is refused instead of read past its end.
#include <cstdint>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "comm/wire.hpp" // unpack
#include "util/record_io.hpp"

namespace zc {
namespace {

struct Pair {
  std::int32_t a;
  float b;
};

TEST(RecordWire, WhatIsWrittenReadsBackInOrder) {
  RecordWriter w;
  w.put(std::uint32_t(3));
  w.put(std::vector<Pair>{{1, 0.5f}, {-2, 1.5f}});
  w.put_sized(Bytes{7, 8, 9});
  w.put_sized(Bytes{});
  const Bytes b = std::move(w).take();
  EXPECT_EQ(b.size(), 4 + 2 * sizeof(Pair) + 4 + 3 + 4);
  RecordReader r(b, "test");
  EXPECT_EQ(r.get<std::uint32_t>(), 3u);
  const auto pairs = r.get_vector<Pair>(2);
  EXPECT_EQ(pairs[1].a, -2);
  EXPECT_EQ(pairs[1].b, 1.5f);
  EXPECT_EQ(r.get_sized(), (Bytes{7, 8, 9}));
  EXPECT_TRUE(r.get_sized().empty());
  EXPECT_TRUE(r.done());
}

TEST(RecordWire, AWriterSizedUpFrontKeepsExactlyWhatWasWritten) {
  RecordWriter w(64);
  w.put(std::uint16_t(5));
  EXPECT_EQ(w.size(), 2u);
  EXPECT_EQ(std::move(w).take().size(), 2u);
  RecordWriter grown(1); // grows past its first guess
  for (std::uint32_t i = 0; i < 100; ++i)
    grown.put(i);
  const Bytes b = std::move(grown).take();
  ASSERT_EQ(b.size(), 400u);
  EXPECT_EQ(unpack<std::uint32_t>(b)[99], 99u);
}

TEST(RecordWire, ATruncatedPayloadIsRefusedNamingWhatWasRead) {
  RecordWriter w;
  w.put_sized(Bytes(10, 1));
  Bytes b = std::move(w).take();
  b.resize(b.size() - 1);
  RecordReader r(b, "host broadcast");
  try {
    (void)r.get_sized();
    FAIL() << "read past the payload's end";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("host broadcast: truncated payload"), std::string::npos)
        << e.what();
  }
}

TEST(RecordWire, ACorruptCountIsRefusedBeforeAnythingIsAllocated) {
  const Bytes b(8, 0xff);
  RecordReader r(b, "blocks");
  EXPECT_THROW((void)r.get_vector<Pair>(std::size_t(-1) / 2), std::runtime_error);
  EXPECT_THROW((void)r.get_bytes(9), std::runtime_error);
  EXPECT_EQ(r.remaining(), 8u);                          // a refused read consumes nothing
  EXPECT_THROW((void)r.get_sized(), std::runtime_error); // a length of 4 GiB - 1
}

TEST(RecordWire, ARegionWriterFillsItsRegionAndRefusesToOverrunIt) {
  Bytes b(6, 0);
  RegionWriter head(b.data(), 2), body(b.data() + 2, 4);
  body.put(std::uint32_t(0x04030201));
  head.put(std::uint16_t(0x0605));
  EXPECT_TRUE(head.full() && body.full());
  EXPECT_EQ(b, (Bytes{5, 6, 1, 2, 3, 4}));
  EXPECT_THROW(head.put(std::uint8_t(1)), std::logic_error);
}

} // namespace
} // namespace zc
