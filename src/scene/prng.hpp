#pragma once
// zcube's own deterministic random numbers for seeded placement (replicated objects, Blazek's
// "color random"): splitmix64 and an exact integer-to-double conversion, so the same seed gives the
// same scene on every compiler and library (std::uniform_real_distribution is
// implementation-defined, so it is never used).
#include <cstdint>

namespace zc {

class SplitMix64 {
public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1): the top 53 bits times 2^-53 (both steps exact in IEEE double).
  double unit() { return double(next() >> 11) * 0x1.0p-53; }
  // Uniform in [lo, hi], rounded to 1e-4 so that an object's one-line description stays short and
  // still round-trips exactly (k / 1e4 prints back as the same short decimal).
  double coord(double lo, double hi) {
    double x = lo + (hi - lo) * unit();
    return double(static_cast<std::int64_t>(x * 1e4 + (x < 0 ? -0.5 : 0.5))) / 1e4;
  }

private:
  std::uint64_t state_;
};

// A well-mixed seed from a base seed and a stream number (one stream per scene line / object).
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream) {
  SplitMix64 g(seed ^ (stream * 0xD1B54A32D192ED03ull));
  return g.next();
}

} // namespace zc
