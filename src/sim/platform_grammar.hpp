#pragma once
// The subset of SimGrid's platform grammar (version 4.1) that zcube's network and CPU models read,
// checked on the parsed XML (pugixml) before SimGrid sees a file: which elements, in which parents,
// with which attributes and values (platforms/README.md, "What a file may hold"). Anything else is
// an InputError "file:line: element or attribute: why zcube cannot model it", so that what
// SimGrid would refuse by ending the process (a route declared twice, a host with core="0", a trace
// file, 500 nested zones) is a one-line error instead.
#include <string>
#include <vector>

namespace zc {

// A <config> setting of the file, checked as `--cfg key:value` is (sim/simgrid_args.hpp).
struct PlatformSetting {
  std::string key, value;
};

// Checks `xml` (the file `label`); returns its <config> settings that zcube hands to SimGrid (the
// --cfg allow-list), in file order. SMPI's settings, which zcube writes for SMPI programs and does
// not read itself, are checked but not returned.
std::vector<PlatformSetting> check_platform_grammar(const std::string& xml,
                                                    const std::string& label);

} // namespace zc
