#pragma once
// The one bounds-checked reader and writer of zcube's wire format: payloads made of records of
// several kinds (counts, lengths, then data), written one after another and read back with every
// read checked against the payload's end. comm/wire.hpp (messages), the collectives' framing,
// Blazek's host broadcast and the active pixel messages of raster/ all write and read through it.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace zc {

using Bytes = std::vector<std::uint8_t>; // same as comm.hpp

// A payload written record by record, appended at its end. Reserved up front when the caller knows
// its size (one allocation, no zero-fill).
class RecordWriter {
public:
  explicit RecordWriter(std::size_t expected_size = 0) { b_.reserve(expected_size); }
  template <class T> void put(const T& v) { put(&v, 1); }
  template <class T> void put(const T* data, std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    put_bytes(data, n * sizeof(T));
  }
  template <class T> void put(const std::vector<T>& v) { put(v.data(), v.size()); }
  void put_bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    b_.insert(b_.end(), p, p + n);
  }
  // A length-prefixed block: its size as a u32, then its bytes (RecordReader::get_sized).
  void put_sized(const Bytes& block) {
    if (block.size() > std::size_t(UINT32_MAX)) throw std::length_error("record block over 4 GiB");
    put(std::uint32_t(block.size()));
    put_bytes(block.data(), block.size());
  }
  std::size_t size() const { return b_.size(); }
  Bytes take() && { return std::move(b_); }

private:
  Bytes b_;
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
  // Throws unless n records of `size` bytes remain: before allocating what a count read from the
  // payload asks for.
  void require(std::size_t n, std::size_t size) const { check(n, size); }

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

// Writes records into a region of a buffer the caller has sized (a payload whose header and body
// are filled at once, each through its own region); a write past the region's end is a bug and
// throws std::logic_error.
class RegionWriter {
public:
  RegionWriter(std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}
  template <class T> void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    put_bytes(&v, sizeof(T));
  }
  void put_bytes(const void* data, std::size_t n) {
    if (n > std::size_t(end_ - p_)) throw std::logic_error("record region overflow");
    if (n) std::memcpy(p_, data, n);
    p_ += n;
  }
  bool full() const { return p_ == end_; }

private:
  std::uint8_t* p_;
  std::uint8_t* end_;
};

} // namespace zc
