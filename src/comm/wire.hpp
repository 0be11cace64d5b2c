#pragma once
// Trivially copyable records packed into message payloads and read back: the payload holds exactly
// the records' bytes. What the network is charged for them is the message's charged size
// (comm.hpp): the payload's size unless the sender gives the modelled program's record size.
// pack/unpack/append handle payloads of one record kind; payloads made of several (counts,
// lengths, then data) are written and read with util/record_io.hpp's RecordWriter and
// RecordReader, every read checked against the payload's end.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "util/record_io.hpp"

namespace zc {

using Bytes = std::vector<std::uint8_t>; // same as comm.hpp

template <class T> Bytes pack(const T* data, std::size_t n) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (n == 0) return {};
  // Copied straight in (not zero-filled first, then copied over: two writes of every byte).
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(data);
  return Bytes(bytes, bytes + n * sizeof(T));
}
template <class T> Bytes pack(const std::vector<T>& v) {
  return pack(v.data(), v.size());
}

template <class T> std::vector<T> unpack(const std::uint8_t* data, std::size_t size) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (size % sizeof(T) != 0)
    throw std::runtime_error("unpack: payload size is not a record multiple");
  std::vector<T> v(size / sizeof(T));
  if (size) std::memcpy(v.data(), data, size);
  return v;
}
template <class T> std::vector<T> unpack(const Bytes& b) {
  return unpack<T>(b.data(), b.size());
}

// Appends records to an existing payload (for payloads made of several record kinds).
template <class T> void append(Bytes& b, const T* data, std::size_t n) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::size_t at = b.size();
  b.resize(at + n * sizeof(T));
  if (n) std::memcpy(b.data() + at, data, n * sizeof(T));
}

} // namespace zc
