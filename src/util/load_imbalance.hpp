#pragma once
// Load imbalance as Kurc et al. define it for Fig. 2: (max - min) / mean of the nodes' loads (merge
// loads, workloads, busy times); 0 when nobody worked. The one measure every report uses.
#include <algorithm>
#include <numeric>
#include <vector>

namespace zc {

template <class T> double load_imbalance(const std::vector<T>& loads) {
  if (loads.empty()) return 0.0;
  const auto [mn, mx] = std::minmax_element(loads.begin(), loads.end());
  const double mean =
      double(std::accumulate(loads.begin(), loads.end(), T(0))) / double(loads.size());
  return mean > 0 ? double(*mx - *mn) / mean : 0.0;
}

} // namespace zc
