// The strategies of the layer, each with its default parameters.
#include "compositing/strategy.hpp"

namespace zc::compositing {

std::vector<Strategy> strategies() {
  return {binary_swap(), direct_send(), radix_k({4}), folding(), tree()};
}

} // namespace zc::compositing
