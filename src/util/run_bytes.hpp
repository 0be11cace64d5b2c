#pragma once
// A byte string kept as runs: runs of bytes written out, and runs of one short pattern repeated
// (a frame buffer's rows that nothing was drawn in: each plane its background). Such a string costs
// the host only its written runs until someone asks for it whole; a reader that knows its layout
// finds a written run in place (find) or learns that a range is all one byte (is_fill_of).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace zc {

using Bytes = std::vector<std::uint8_t>;

class RunBytes {
public:
  // Room for n written bytes in all (appending them then moves none).
  void reserve(std::size_t n) { written_.reserve(n); }
  // Appends n bytes from p.
  void append(const std::uint8_t* p, std::size_t n);
  // Appends n bytes of `pattern` (1 to 4 bytes) repeated from its first byte on.
  void append_fill(const std::uint8_t* pattern, std::size_t period, std::size_t n);
  // Appends another such string.
  void append(const RunBytes& o);

  std::size_t size() const { return size_; }
  bool has_fill() const;
  // The address of bytes [at, at + n) when they lie in one written run; null otherwise.
  const std::uint8_t* find(std::size_t at, std::size_t n) const;
  // True when bytes [at, at + n) lie in one repeated run and are all `byte`.
  bool is_fill_of(std::size_t at, std::size_t n, std::uint8_t byte) const;
  // Writes bytes [at, at + n) to out.
  void copy(std::size_t at, std::size_t n, std::uint8_t* out) const;
  // The whole string, written out on the first call and kept.
  const Bytes& whole() const;
  // The written bytes, which are the whole string when it has no repeated run.
  Bytes take_written() && { return std::move(written_); }

private:
  static constexpr std::size_t kFill = ~std::size_t(0);
  struct Run {
    std::size_t at, size; // where in the string
    std::size_t from;     // where in written_, or kFill
    std::uint8_t pattern[4], period;
  };
  const Run& run_at(std::size_t at) const; // the run holding byte `at` (< size())

  Bytes written_;
  std::vector<Run> runs_;
  std::size_t size_ = 0;
  mutable std::optional<Bytes> whole_;
};

} // namespace zc
