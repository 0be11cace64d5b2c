#include "algo/algorithm.hpp"
#include "algo/blazek/blazek_methods.hpp"
#include "algo/charles/elastic.hpp"
#include "algo/kurc/kurc_pixel_merging.hpp"
#include "algo/kurc/kurc_scanline.hpp"
#include "algo/sequential.hpp"
#include "algo/sort_last/compositing_study.hpp"
#include "algo/sort_last/sort_last.hpp"
#include "algo/tools/comm_check.hpp"
#include "algo/tools/pingpong.hpp"
#include "util/error.hpp"

namespace zc {

const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> all = [] {
    std::vector<Algorithm> v = {sequential_algorithm(), elastic_algorithm(), pingpong_algorithm(),
                                comm_check_algorithm(), kurc_scanline_algorithm()};
    for (auto& a : kurc_algorithms())
      v.push_back(a);
    for (auto& a : blazek_algorithms())
      v.push_back(a);
    for (auto& a : sort_last_algorithms())
      v.push_back(a);
    for (auto& a : compositing_study_algorithms())
      v.push_back(a);
    return v;
  }();
  return all;
}

const Algorithm& find_algorithm(const std::string& name) {
  for (const auto& a : algorithms())
    if (a.name == name) return a;
  std::string known;
  for (const auto& a : algorithms())
    known += (known.empty() ? "" : ", ") + a.name;
  throw UsageError("--algorithm '" + name + "': unknown (known: " + known + ")");
}

} // namespace zc
