#include "util/run_bytes.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace zc {

void RunBytes::append(const std::uint8_t* p, std::size_t n) {
  if (n == 0) return;
  if (runs_.empty() || runs_.back().from == kFill)
    runs_.push_back({size_, 0, written_.size(), {}, 0});
  written_.insert(written_.end(), p, p + n);
  runs_.back().size += n;
  size_ += n;
  whole_.reset();
}

void RunBytes::append_fill(const std::uint8_t* pattern, std::size_t period, std::size_t n) {
  if (period < 1 || period > 4) throw std::logic_error("RunBytes: a pattern of 1 to 4 bytes");
  if (n == 0) return;
  Run* last = runs_.empty() ? nullptr : &runs_.back();
  // The same pattern right after a whole number of its periods: the same run.
  if (!last || last->from != kFill || last->period != period || last->size % period != 0 ||
      std::memcmp(last->pattern, pattern, period) != 0) {
    Run r{size_, 0, kFill, {}, std::uint8_t(period)};
    std::memcpy(r.pattern, pattern, period);
    runs_.push_back(r);
  }
  runs_.back().size += n;
  size_ += n;
  whole_.reset();
}

void RunBytes::append(const RunBytes& o) {
  for (const Run& r : o.runs_)
    if (r.from == kFill)
      append_fill(r.pattern, r.period, r.size);
    else
      append(o.written_.data() + r.from, r.size);
}

bool RunBytes::has_fill() const {
  return std::any_of(runs_.begin(), runs_.end(), [](const Run& r) { return r.from == kFill; });
}

const RunBytes::Run& RunBytes::run_at(std::size_t at) const {
  // The last run starting at or before `at`.
  const auto it = std::upper_bound(runs_.begin(), runs_.end(), at,
                                   [](std::size_t a, const Run& r) { return a < r.at; });
  return *(it - 1);
}

const std::uint8_t* RunBytes::find(std::size_t at, std::size_t n) const {
  if (n == 0 || at + n > size_) return nullptr;
  const Run& r = run_at(at);
  if (r.from == kFill || at + n > r.at + r.size) return nullptr;
  return written_.data() + r.from + (at - r.at);
}

bool RunBytes::is_fill_of(std::size_t at, std::size_t n, std::uint8_t byte) const {
  if (n == 0 || at + n > size_) return false;
  const Run& r = run_at(at);
  if (r.from != kFill || at + n > r.at + r.size) return false;
  for (std::size_t k = 0; k < r.period; ++k)
    if (r.pattern[k] != byte) return false;
  return true;
}

void RunBytes::copy(std::size_t at, std::size_t n, std::uint8_t* out) const {
  if (at + n > size_) throw std::out_of_range("RunBytes::copy past the end");
  while (n > 0) {
    const Run& r = run_at(at);
    const std::size_t m = std::min(n, r.at + r.size - at);
    if (r.from != kFill) {
      std::memcpy(out, written_.data() + r.from + (at - r.at), m);
    } else {
      for (std::size_t k = 0, phase = (at - r.at) % r.period; k < m; ++k)
        out[k] = r.pattern[(phase + k) % r.period];
    }
    out += m;
    at += m;
    n -= m;
  }
}

const Bytes& RunBytes::whole() const {
  if (!whole_) {
    Bytes b(size_);
    if (size_ > 0) copy(0, size_, b.data());
    whole_ = std::move(b);
  }
  return *whole_;
}

} // namespace zc
