#pragma once
// The wire format's one owner: trivially copyable records packed into message payloads and read
// back. The payload holds exactly the records' bytes; what the network is charged for them is the
// message's charged size (comm.hpp): the payload's size unless the sender gives the modelled
// program's record size. pack/unpack/append handle payloads of one record kind; RecordWriter and
// RecordReader payloads made of several (counts, lengths, then data), every read checked against
// the payload's end.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace zc {

using Bytes = std::vector<std::uint8_t>; // same as comm.hpp

template <class T> Bytes pack(const T* data, std::size_t n) {
  static_assert(std::is_trivially_copyable_v<T>);
  Bytes b(n * sizeof(T));
  if (n) std::memcpy(b.data(), data, b.size());
  return b;
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

// A payload written record by record. Sized up front when the caller knows its size (one
// allocation), grown otherwise; bytes are copied in with memcpy (vector::insert of a few bytes
// trips a GCC 12 -Wstringop-overflow false positive).
class RecordWriter {
public:
  explicit RecordWriter(std::size_t expected_size = 0) : b_(expected_size) {}
  template <class T> void put(const T& v) { put(&v, 1); }
  template <class T> void put(const T* data, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    put_bytes(data, n * sizeof(T));
  }
  template <class T> void put(const std::vector<T>& v) { put(v.data(), v.size()); }
  void put_bytes(const void* data, std::size_t n) {
    if (at_ + n > b_.size()) b_.resize(std::max(at_ + n, 2 * b_.size()));
    if (n) std::memcpy(b_.data() + at_, data, n);
    at_ += n;
  }
  // A length-prefixed block: its size as a u32, then its bytes (RecordReader::get_sized).
  void put_sized(const Bytes& block) {
    if (block.size() > std::size_t(UINT32_MAX)) throw std::length_error("record block over 4 GiB");
    put(std::uint32_t(block.size()));
    put_bytes(block.data(), block.size());
  }
  std::size_t size() const { return at_; }
  Bytes take() && {
    b_.resize(at_);
    return std::move(b_);
  }

private:
  Bytes b_;
  std::size_t at_ = 0;
};

// Reads a payload back record by record. Every read is checked against the payload's end: a
// truncated or corrupt payload throws std::runtime_error("<what>: truncated payload ...") rather
// than reading past it.
class RecordReader {
public:
  RecordReader(const std::uint8_t* data, std::size_t size, const char* what)
      : p_(data), end_(data + size), what_(what) {}
  RecordReader(const Bytes& b, const char* what) : RecordReader(b.data(), b.size(), what) {}
  template <class T> T get() {
    T v;
    get(&v, 1);
    return v;
  }
  template <class T> void get(T* out, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::uint8_t* p = take(n, sizeof(T));
    if (n) std::memcpy(out, p, n * sizeof(T));
  }
  template <class T> std::vector<T> get_vector(std::size_t n) {
    check(n, sizeof(T)); // before allocating what a corrupt count asks for
    std::vector<T> v(n);
    get(v.data(), n);
    return v;
  }
  // The next n bytes, in place (valid while the payload is).
  const std::uint8_t* get_bytes(std::size_t n) { return take(n, 1); }
  // A block written by RecordWriter::put_sized.
  Bytes get_sized() {
    const auto n = get<std::uint32_t>();
    const std::uint8_t* p = get_bytes(n);
    return Bytes(p, p + n);
  }
  std::size_t remaining() const { return std::size_t(end_ - p_); }
  bool done() const { return p_ == end_; }

private:
  // n records of `size` bytes each left to read (n * size not formed: it could overflow).
  void check(std::size_t n, std::size_t size) const {
    if (n > remaining() / size)
      throw std::runtime_error(std::string(what_) + ": truncated payload (" + std::to_string(n) +
                               " records of " + std::to_string(size) + " bytes wanted, " +
                               std::to_string(remaining()) + " bytes left)");
  }
  const std::uint8_t* take(std::size_t n, std::size_t size) {
    check(n, size);
    const std::uint8_t* p = p_;
    p_ += n * size;
    return p;
  }
  const std::uint8_t* p_;
  const std::uint8_t* end_;
  const char* what_;
};

} // namespace zc
