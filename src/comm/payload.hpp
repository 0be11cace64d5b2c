#pragma once
// A message's payload: an immutable byte buffer shared by the sender, the network and every
// receiver. All the simulated nodes live in one host process, so passing a message on, or the same
// block to many nodes (a broadcast, a multi-broadcast), shares one buffer by reference count
// instead of copying it per hop and per receiver. The modelled machine still holds a copy on each
// node: its memory is charged by the node programs (NodeContext::alloc), never by the host's.
//
// Made from a Bytes (implicitly, so `Message{pack(v), n}` reads as before); read as a const Bytes
// (implicitly too); take() gives the bytes back as a Bytes of one's own, moved when this is the
// only holder, copied otherwise.
//
// Made from a RunBytes with repeated runs (the background of a frame buffer's rows never drawn),
// it keeps the runs: its size is the whole string's, a receiver that knows the layout reads the
// runs (runs()), and whoever reads its bytes (the MPI backend sending it) gets the whole string,
// written out once.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "util/run_bytes.hpp"

namespace zc {

class Payload {
public:
  Payload() = default;
  Payload(Bytes b);    // NOLINT(google-explicit-constructor): a payload is made from its bytes
  Payload(RunBytes b); // NOLINT(google-explicit-constructor)

  const Bytes& bytes() const {
    return !buf_ ? none() : buf_->runs ? buf_->runs->whole() : buf_->bytes;
  }
  // The runs of a payload made from a RunBytes with repeated runs; null otherwise.
  const RunBytes* runs() const { return buf_ ? buf_->runs.get() : nullptr; }
  operator const Bytes&() const& { return bytes(); } // NOLINT(google-explicit-constructor)
  // The bytes as a vector of one's own: moved out when no one else holds them, else copied.
  Bytes take() && {
    if (!buf_) return {};
    Bytes b = buf_.use_count() == 1 && !buf_->runs ? std::move(buf_->bytes) : bytes();
    buf_.reset();
    return b;
  }

  std::size_t size() const {
    return !buf_ ? 0 : buf_->runs ? buf_->runs->size() : buf_->bytes.size();
  }
  bool empty() const { return size() == 0; }
  const std::uint8_t* data() const { return bytes().data(); }
  Bytes::const_iterator begin() const { return bytes().begin(); }
  Bytes::const_iterator end() const { return bytes().end(); }
  std::uint8_t operator[](std::size_t i) const { return bytes()[i]; }
  std::uint8_t at(std::size_t i) const { return bytes().at(i); }
  // The payload read in place as an array of records (wire.hpp's pack wrote them): no copy.
  template <class T> std::span<const T> records() const {
    static_assert(std::is_trivially_copyable_v<T>);
    if (size() % sizeof(T) != 0) throw std::runtime_error("payload size is not a record multiple");
    if (reinterpret_cast<std::uintptr_t>(data()) % alignof(T) != 0)
      throw std::runtime_error("payload not aligned for its records");
    return {reinterpret_cast<const T*>(data()), size() / sizeof(T)};
  }
  // How many payloads share these bytes (0 when empty).
  long holders() const { return buf_.use_count(); }
  bool shares(const Payload& o) const { return buf_ && buf_ == o.buf_; }

  friend bool operator==(const Payload& a, const Payload& b) {
    return a.shares(b) || a.bytes() == b.bytes();
  }
  friend bool operator==(const Payload& a, const Bytes& b) { return a.bytes() == b; }

private:
  static const Bytes& none() {
    static const Bytes empty;
    return empty;
  }
  // One pointer a payload (a Message is copied by the million in a 1024-node run): the bytes, or
  // the runs of a string with repeated runs.
  struct Body {
    Bytes bytes;
    std::unique_ptr<const RunBytes> runs;
  };
  std::shared_ptr<Body> buf_; // never written through once made
};

} // namespace zc
