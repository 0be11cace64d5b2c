// The built-in machines' figures, field by field, exactly as the code before machines/*.json held
// them (printed with %a from that build): moving a machine into a data file must not move a bit.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "machine/machine.hpp"

using namespace zc;

namespace {

struct ExpectedNetwork {
  double startup_short_s, startup_long_s, short_max_bytes, per_byte_s, per_hop_s;
  Switching switching;
  double host_startup_s, host_per_byte_s, both_ways_Bps;
  bool charge_payloads;
};

struct ExpectedMachine {
  const char* name;
  const char* description;
  double memory_bytes, os_resident_bytes;
  ExpectedNetwork net;
  const char* cpu;
  bool cost_calibrated;
  std::vector<double> cost; // CostTable::fields() order
};

const std::vector<ExpectedMachine> kExpected = {
    {"ipsc2",
     "Intel iPSC/2: 80386+80387 16 MHz nodes, DCM circuit-switched hypercube",
     0x1p+22,
     0x1p+19,
     {0x1.205bc01a36e2fp-12, 0x1.205bc01a36e2fp-12, 0x1.9p+6, 0x1.7f7aae5962ecap-22,
      0x1.4f8b588e368f1p-17, Switching::Circuit, 0x1.0624dd2f1a9fcp-10, 0x1.0c6f7a0b5ed8dp-20,
      0x0p+0, false},
     "i80386",
     true,
     {0x1.4773fc6c82196p-12,
      0x1.02fc1d62117edp-15,
      0x1.09e8d859bd161p-19,
      0x1.cd0385c23fa81p-12,
      0x1.314b3fba5d023p-12,
      0x1.797cc39ffd60ep-17,
      0x1.4de55bbda84p-15,
      0x1.98498961f18c9p-18,
      0x1.e7de60e8046d6p-15,
      0x0p+0,
      0x1.d76ef19d06181p-15,
      0x1.0c6f7a0b5ed8dp-20,
      0x1.5c9404803b396p-17,
      0x1.4f8b588e368fp-23,
      0x1.17c24e4914449p-15,
      0x1.b43526527a205p-20,
      0x1.49ca48534c02ep-13,
      0x1.1904b3c3e74bp-16,
      0x1.10a137f38c543p-18,
      0x1.3ec460ed80a17p-20,
      0x1.344806290eedp-16,
      0x1.e4712e40852b4p-15,
      0x1.e68a0d349be9p-19,
      0x1.a36e2eb1c432cp-19,
      0x1.e68a0d349be9p-20,
      0x0p+0,
      0x0p+0,
      0x0p+0,
      0x1.a36e2eb1c432cp-19,
      0x0p+0,
      0x0p+0}},
    {"ipsc860",
     "Intel iPSC/860: i860 XR 40 MHz nodes, DCM circuit-switched hypercube",
     0x1p+23,
     0x1p+20,
     {0x1.3a92a30553261p-14, 0x1.1d3671ac14c66p-13, 0x1.9p+6, 0x1.828c0be769dc1p-22,
      0x1.4f8b588e368f1p-17, Switching::Circuit, 0x1.0624dd2f1a9fcp-10, 0x1.0c6f7a0b5ed8dp-20,
      0x0p+0, false},
     "i860xr",
     true,
     {0x1.f5e77ec2fb4cdp-17,
      0x1.363a51be07446p-19,
      0x1.1ba308e841289p-22,
      0x1.75619eb9bdc67p-16,
      0x1.c6431c43f85bp-17,
      0x1.d5c31593e5fb7p-20,
      0x1.afd0cfc7e9c62p-20,
      0x1.1fe08a8546841p-21,
      0x1.bae34b433168cp-20,
      0x0p+0,
      0x1.043255d1136d9p-19,
      0x1.ad7f29abcaf48p-24,
      0x1.26a5b0b9acbf7p-20,
      0x1.421f5f40d8376p-26,
      0x1.97ba5ccdddaa6p-20,
      0x1.27476ca61b882p-22,
      0x1.d918efdb64aebp-17,
      0x1.8bf13a6a5f196p-19,
      0x1.ad7f29abcaf48p-22,
      0x1.0c6f7a0b5ed8dp-22,
      0x1.88963c1707838p-19,
      0x1.421f5f40d8376p-19,
      0x1.34b365f379dfcp-21,
      0x1.fe07017c01026p-22,
      0x1.27476ca61b882p-22,
      0x0p+0,
      0x0p+0,
      0x0p+0,
      0x1.fe07017c01026p-22,
      0x0p+0,
      0x0p+0}},
    {"volvox",
     "Archipel Volvox: i860 compute + T800 transputer links, store-and-forward",
     0x1p+23,
     0x1p+20,
     {0x1.a36e2eb1c432dp-15, 0x1.a36e2eb1c432dp-15, 0x1.9p+6, 0x1.3bce7176c9fp-21, 0x0p+0,
      Switching::StoreAndForward, 0x1.0624dd2f1a9fcp-10, 0x1.0c6f7a0b5ed8dp-20, 0x1.1edd8p+21,
      false},
     "i860xr",
     true,
     {0x1.f5e77ec2fb4cdp-17,
      0x1.363a51be07446p-19,
      0x1.1ba308e841289p-22,
      0x1.75619eb9bdc67p-16,
      0x1.c6431c43f85bp-17,
      0x1.d5c31593e5fb7p-20,
      0x1.afd0cfc7e9c62p-20,
      0x1.1fe08a8546841p-21,
      0x1.bae34b433168cp-20,
      0x0p+0,
      0x1.043255d1136d9p-19,
      0x1.ad7f29abcaf48p-24,
      0x1.26a5b0b9acbf7p-20,
      0x1.421f5f40d8376p-26,
      0x1.97ba5ccdddaa6p-20,
      0x1.27476ca61b882p-22,
      0x1.d918efdb64aebp-17,
      0x1.8bf13a6a5f196p-19,
      0x1.ad7f29abcaf48p-22,
      0x1.0c6f7a0b5ed8dp-22,
      0x1.88963c1707838p-19,
      0x1.421f5f40d8376p-19,
      0x1.34b365f379dfcp-21,
      0x1.fe07017c01026p-22,
      0x1.27476ca61b882p-22,
      0x0p+0,
      0x0p+0,
      0x0p+0,
      0x1.fe07017c01026p-22,
      0x0p+0,
      0x0p+0}}};

void expect_network(const std::string& name, const NetworkParams& n, const ExpectedNetwork& e) {
  SCOPED_TRACE(name);
  EXPECT_EQ(n.startup_short_s, e.startup_short_s);
  EXPECT_EQ(n.startup_long_s, e.startup_long_s);
  EXPECT_EQ(n.short_max_bytes, e.short_max_bytes);
  EXPECT_EQ(n.per_byte_s, e.per_byte_s);
  EXPECT_EQ(n.per_hop_s, e.per_hop_s);
  EXPECT_EQ(n.switching, e.switching);
  EXPECT_EQ(n.host_startup_s, e.host_startup_s);
  EXPECT_EQ(n.host_per_byte_s, e.host_per_byte_s);
  EXPECT_EQ(n.both_ways_Bps, e.both_ways_Bps);
  EXPECT_EQ(n.charge_payloads, e.charge_payloads);
}

} // namespace

TEST(BuiltinMachines, EveryFigureAsBeforeToTheBit) {
  for (const auto& e : kExpected) {
    SCOPED_TRACE(e.name);
    MachineSpec m = machine_spec(e.name);
    EXPECT_EQ(m.name, e.name);
    EXPECT_EQ(m.description, e.description);
    EXPECT_EQ(m.memory_bytes, e.memory_bytes);
    EXPECT_EQ(m.os_resident_bytes, e.os_resident_bytes);
    expect_network(e.name, m.net, e.net);
    EXPECT_EQ(m.cpu, e.cpu);
    EXPECT_EQ(m.cost_calibrated, e.cost_calibrated);
    EXPECT_TRUE(m.generated_by.empty());
    const auto fields = m.cost.fields();
    ASSERT_EQ(fields.size(), e.cost.size());
    for (std::size_t i = 0; i < fields.size(); ++i)
      EXPECT_EQ(*fields[i].second, e.cost[i]) << fields[i].first;
  }
}

TEST(BuiltinMachines, TheThreeOfThePapersAreThere) {
  for (const auto& e : kExpected)
    EXPECT_NE(std::find(machine_names().begin(), machine_names().end(), e.name),
              machine_names().end())
        << e.name;
}
