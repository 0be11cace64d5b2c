#include "comm/payload.hpp"

namespace zc {

// Out of line: inlined into a caller that builds the Bytes in place, GCC 12 reported a false
// -Wfree-nonheap-object on the moved-from vector.
Payload::Payload(Bytes b) : buf_(b.empty() ? nullptr : std::make_shared<Bytes>(std::move(b))) {}

Payload::Payload(RunBytes b) {
  if (b.has_fill())
    runs_ = std::make_shared<const RunBytes>(std::move(b));
  else
    *this = Payload(std::move(b).take_written());
}

} // namespace zc
