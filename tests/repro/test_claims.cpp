// results/claims.csv (repro/claims.hpp): every statement tests/repro/test_paper_claims.cpp checks,
// listed with its test's state, and the probabilities as claim_probability computes them.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "csv.hpp"
#include "repro/claims.hpp"
#include "source_root.hpp"

using namespace zc;
using namespace zc::test;

namespace {

// The PaperClaims tests as the test file declares them (DISABLED_ prefix kept).
std::set<std::string> declared_claim_tests() {
  std::ifstream in(kRoot + "/tests/repro/test_paper_claims.cpp");
  std::stringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  std::set<std::string> names;
  const std::regex re(R"(TEST\(PaperClaims, (\w+)\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    names.insert((*it)[1]);
  return names;
}

// Reports of two runs "a" and "b" whose draws' times are given (NaN: a failed draw).
Reports two_runs(const std::vector<double>& a, const std::vector<double>& b) {
  Reports r;
  const auto report = [](const std::vector<double>& v) {
    nlohmann::json vals = nlohmann::json::array();
    for (double x : v)
      vals.push_back(std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr));
    return nlohmann::json{{"status", "ok"},
                          {"virtual_time_s", 1.0},
                          {"phases", nlohmann::json::array()},
                          {"bands", {{"values", {{"virtual_time_s", vals}}}}}};
  };
  r["a"] = report(a);
  r["b"] = report(b);
  return r;
}

} // namespace

TEST(Claims, EveryPaperClaimTestIsListedOnce) {
  const auto declared = declared_claim_tests();
  ASSERT_GE(declared.size(), 8u);
  std::set<std::string> listed;
  for (const Claim& c : paper_claims())
    EXPECT_TRUE(listed.insert(c.test).second) << c.test << " listed twice";
  EXPECT_EQ(listed, declared);
}

TEST(Claims, ProbabilityIsTheShareOfDrawsThatHold) {
  const Reports r = two_runs({1, 2, 3, std::nan(""), 5}, {2, 1, 4, 9, 4});
  const Claim c{"t", "p", "a below b",
                [](const ClaimDraw& d) { return d.time("a") < d.time("b"); }};
  EXPECT_DOUBLE_EQ(claim_probability(c, r, 5), 2.0 / 5); // draws 0 and 2; draw 3 failed
}

// The committed table: one row per claim, the test's state, probabilities in [0, 1], and the
// enabled claims (checked on the nominal model by their tests) holding at the nominal model.
TEST(Claims, CommittedTableMatchesTheClaims) {
  const auto rows = read_csv(kRoot + "/results/claims.csv");
  ASSERT_EQ(rows.size(), paper_claims().size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Claim& c = paper_claims()[i];
    const bool enabled = !c.test.starts_with("DISABLED_");
    EXPECT_EQ(rows[i].at("test"), enabled ? c.test : c.test.substr(9));
    EXPECT_EQ(rows[i].at("enabled"), enabled ? "1" : "0") << c.test;
    const double p = std::stod(rows[i].at("probability"));
    EXPECT_GE(p, 0.0) << c.test;
    EXPECT_LE(p, 1.0) << c.test;
    if (enabled) {
      EXPECT_EQ(rows[i].at("holds_nominal"), "1") << c.test;
    }
  }
}
