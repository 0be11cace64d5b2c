// repro/regress and regress_output: each tolerance class catches a perturbed golden report, the
// schema check refuses what it must, and the JSON and JUnit forms parse.
#include <pugixml.hpp>

#include <gtest/gtest.h>

#include "repro/provenance.hpp"
#include "repro/regress.hpp"
#include "repro/regress_output.hpp"
#include "util/error.hpp"

using namespace zc;

namespace {

using Reports = std::map<std::string, nlohmann::json>;

Reports golden() {
  return {{"run-a",
           {{"status", "ok"},
            {"virtual_time_s", 1.5},
            {"phases", {{"merge", 0.25}}},
            {"load_imbalance", 0.1},
            {"communication", {{"messages", 237}, {"bytes", 2505817}}},
            {"counters", {{"spans", 11991}}},
            {"peak_memory_bytes", 642397.0},
            {"image", {{"sha256", "ab"}}}}},
          {"run-b", {{"status", "ok"}, {"virtual_time_s", 2.0}}}};
}

// Loose tolerances for every class but the one perturbed, at `loose`; that one at `tight`.
RegressTolerance only_tight(QuantityKind kind, double tight, double loose = 0.5) {
  RegressTolerance t{loose, loose, loose, 0};
  (kind == QuantityKind::time    ? t.rtol_time
   : kind == QuantityKind::count ? t.rtol_count
                                 : t.rtol_bytes) = tight;
  return t;
}

} // namespace

TEST(RegressTolerance, QuantitiesFallIntoTheirClass) {
  EXPECT_EQ(quantity_kind("virtual_time_s", 1.0), QuantityKind::time);
  EXPECT_EQ(quantity_kind("phases.merge", 1.0), QuantityKind::time);
  EXPECT_EQ(quantity_kind("load_imbalance", 0.1), QuantityKind::time);
  EXPECT_EQ(quantity_kind("communication.messages", 3), QuantityKind::count);
  EXPECT_EQ(quantity_kind("counters.spans", 3), QuantityKind::count);
  EXPECT_EQ(quantity_kind("communication.bytes", 3), QuantityKind::bytes);
  EXPECT_EQ(quantity_kind("peak_memory_bytes", 3.0), QuantityKind::bytes);
  EXPECT_EQ(quantity_kind("counters.wire_bytes", 3), QuantityKind::bytes);
  EXPECT_EQ(quantity_kind("image.sha256", "ab"), QuantityKind::text);
}

// Each class: a change within its tolerance passes, the same change beyond it is one difference
// of that class, whatever the other classes allow.
TEST(RegressTolerance, EachClassCatchesItsPerturbation) {
  const Reports a = golden();
  struct Case {
    QuantityKind kind;
    std::vector<std::string> path;
    double rel;
  };
  for (const Case& c : {Case{QuantityKind::time, {"phases", "merge"}, 1e-6},
                        Case{QuantityKind::count, {"communication", "messages"}, 1.0 / 237},
                        Case{QuantityKind::bytes, {"communication", "bytes"}, 1e-4}}) {
    Reports b = a;
    nlohmann::json* v = &b["run-a"];
    for (const auto& k : c.path)
      v = &(*v)[k];
    *v = v->get<double>() * (1 + c.rel);
    const auto caught = compare_reduced(a, b, only_tight(c.kind, c.rel / 10));
    ASSERT_EQ(caught.size(), 1u) << kind_name(c.kind);
    EXPECT_EQ(caught[0].kind, c.kind);
    EXPECT_NE(caught[0].tolerance.find("rtol"), std::string::npos);
    EXPECT_TRUE(compare_reduced(a, b, only_tight(c.kind, c.rel * 10)).empty()) << kind_name(c.kind);
  }
}

TEST(RegressTolerance, CountsAreExactByDefaultAndAtolIsAFloor) {
  const Reports a = golden();
  Reports b = a;
  b["run-a"]["communication"]["messages"] = 238;
  EXPECT_EQ(compare_reduced(a, b, RegressTolerance{1e-2, 0, 1e-2, 0}).size(), 1u);
  b = a;
  b["run-b"]["virtual_time_s"] = 2.0 + 1e-12;
  EXPECT_EQ(compare_reduced(a, b, RegressTolerance{}).size(), 1u);
  EXPECT_TRUE(compare_reduced(a, b, RegressTolerance{0, 0, 0, 1e-9}).empty());
  // Provenance is where a report came from, not what it says.
  b = a;
  b["run-b"]["provenance"] = provenance();
  EXPECT_TRUE(compare_reduced(a, b, RegressTolerance{}).empty());
}

TEST(RegressSchema, OtherSchemasRefusedUnlessAllowed) {
  Reports dir = golden();
  EXPECT_THROW(check_report_schema(dir, "--against", "old", false), UsageError);
  EXPECT_TRUE(check_report_schema(dir, "--against", "old", true).is_null());
  for (auto& [name, r] : dir)
    r["provenance"] = provenance(ProvenanceFor::committed_file);
  EXPECT_EQ(check_report_schema(dir, "--against", "new", false)["schema_version"], kSchemaVersion);
  dir["run-b"]["provenance"]["schema_version"] = kSchemaVersion + 1;
  try {
    check_report_schema(dir, "--against", "new", false);
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("run-b.json"), std::string::npos) << what;
    EXPECT_NE(what.find("--allow-schema"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

namespace {

RegressOutcome perturbed_outcome() {
  RegressOutcome o;
  const Reports a = golden();
  Reports b = a;
  b["run-a"]["virtual_time_s"] = 1.6;
  b["run-a"]["image"]["sha256"] = "<cd & \"ef\">";
  o.before = {"tests/golden", provenance(ProvenanceFor::committed_file)};
  o.after = {"now", provenance()};
  o.runs = {"run-a", "run-b"};
  o.tolerance = RegressTolerance::uniform(1e-9);
  o.diffs = compare_reduced(a, b, o.tolerance);
  return o;
}

} // namespace

TEST(RegressOutput, JunitParsesWithOneCasePerRunAndNamedFailures) {
  const std::string xml = regress_junit(perturbed_outcome());
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str())) << xml;
  const auto suite = doc.child("testsuites").child("testsuite");
  EXPECT_EQ(suite.attribute("tests").as_int(), 2);
  EXPECT_EQ(suite.attribute("failures").as_int(), 1);
  int cases = 0;
  for (const auto& c : suite.children("testcase")) {
    ++cases;
    const bool failed = !c.child("failure").empty();
    EXPECT_EQ(failed, std::string(c.attribute("name").value()) == "run-a");
    if (!failed) continue;
    const std::string m = c.child("failure").attribute("message").value();
    for (const char* want :
         {"virtual_time_s", "1.5", "1.6", "rtol 1e-09", "image.sha256", "<cd & \"ef\">"})
      EXPECT_NE(m.find(want), std::string::npos) << want << " in " << m;
  }
  EXPECT_EQ(cases, 2);
}

TEST(RegressOutput, JsonParsesAndSaysBothSides) {
  const auto o = perturbed_outcome();
  const auto j = nlohmann::json::parse(regress_json(o).dump());
  EXPECT_EQ(j["differences"].size(), 2u);
  EXPECT_FALSE(j["identical"].get<bool>());
  EXPECT_EQ(j["before"]["provenance"]["schema_version"], kSchemaVersion);
  EXPECT_TRUE(j["after"]["provenance"].contains("zcube_commit"));
  EXPECT_EQ(j["tolerance"]["rtol_count"], 1e-9);
  const std::string text = regress_sides_text(o) + regress_text(o);
  EXPECT_NE(text.find("tests/golden: zcube "), std::string::npos) << text;
  EXPECT_NE(text.find("2 differences"), std::string::npos) << text;
}
