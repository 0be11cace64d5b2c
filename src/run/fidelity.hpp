#pragma once
#include <string>

namespace zc {

// How messages are charged (platforms/README.md has the details and run costs):
//  analytic: every message costs its closed form, no contention;
//  flow:     SimGrid's flow model shares each channel fairly between the messages crossing it;
//  circuit:  DCM circuit switching: the channels of the e-cube path are held, in dimension order,
//            for the whole transfer; a later message needing one of them waits.
enum class Fidelity { Analytic, Flow, Circuit };

Fidelity parse_fidelity(const std::string& s);
const char* fidelity_name(Fidelity f);

} // namespace zc
