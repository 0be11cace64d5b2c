#pragma once
// The designs of a what-if study (zcube sweep --design): the Cartesian product of the swept
// flags' values (grid), one factor at a time around a base point (oat: the first value of every
// flag is the base), or a CSV file of points. And what is checked before any point runs.
#include <string>
#include <vector>

#include "repro/sweep.hpp"

namespace zc {

// The base point (every flag's first value), then, flag by flag, each of its other values with
// every other flag at its base: 1 + sum(values - 1) points.
std::vector<SweepPoint> expand_one_at_a_time(const std::vector<SweepAxis>& axes,
                                             const std::string& scene, const Locate& locate = {});

// A CSV file of points: a header of zcube run flag names, a row a point, an empty cell the flag
// not given. The axes are the header's flags with their values in the order they appear.
// InputError naming the file and line: an unknown flag, a row of the wrong width, a quote.
struct PointFile {
  std::vector<SweepAxis> axes;
  std::vector<SweepPoint> points;
};
PointFile read_point_file(const std::string& path, const std::string& scene,
                          const Locate& locate = {});

// Every distinct scene and platform file the points name, loaded or probed once before anything
// runs: a missing or malformed file is an InputError naming it, not a failed row per point.
void check_point_inputs(const std::vector<SweepPoint>& points);

// The largest sweep that starts without --yes, and the host CPU a small point takes (a node count
// of 16 or less on the bundled scenes): the estimate printed before a larger one is refused.
constexpr std::size_t kSweepPointsWithoutYes = 10000;
constexpr double kHostSecondsPerPoint = 0.1;

} // namespace zc
