#include "comm/payload.hpp"

namespace zc {

// Out of line: inlined into a caller that builds the Bytes in place, GCC 12 reported a false
// -Wfree-nonheap-object on the moved-from vector.
Payload::Payload(Bytes b)
    : buf_(b.empty() ? nullptr : std::make_shared<Body>(Body{std::move(b), nullptr})) {}

Payload::Payload(RunBytes b) {
  if (b.size() == 0) return;
  buf_ = b.has_fill()
             ? std::make_shared<Body>(Body{{}, std::make_unique<const RunBytes>(std::move(b))})
             : std::make_shared<Body>(Body{std::move(b).take_written(), nullptr});
}

} // namespace zc
