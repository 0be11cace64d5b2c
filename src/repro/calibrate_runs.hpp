#pragma once
// What the calibration's steps share (repro/calibrate.hpp): platforms with a candidate cost table,
// their runs, and the error summaries.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/machine.hpp"
#include "repro/calibrate.hpp"
#include "run/config.hpp"

namespace zc::calibration {

// A platform file with a candidate cost table, for the runs of one fit step (removed with it).
class TempPlatform {
public:
  TempPlatform(const std::string& machine, const CostTable& cost, int nodes);
  ~TempPlatform();
  TempPlatform(const TempPlatform&) = delete;
  TempPlatform& operator=(const TempPlatform&) = delete;
  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }

private:
  std::string path_, text_;
};

// The runs, several at once; a failed one is an error naming it.
std::vector<nlohmann::json> run_all(const std::vector<RunConfig>& cfgs,
                                    const CalibrationOptions& o);
double rms(const std::vector<double>& e);
double median_abs(std::vector<double> e);

} // namespace zc::calibration
