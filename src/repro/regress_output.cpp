#include "repro/regress_output.hpp"

#include <sstream>

#include "repro/provenance.hpp"
#include "repro/table.hpp"

namespace zc {

namespace {

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&apos;";
      break;
    case '\n':
      out += "&#10;";
      break;
    default:
      // Control characters are not allowed in XML 1.0, even escaped.
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
        out += ' ';
      else
        out += c;
    }
  }
  return out;
}

// "virtual_time_s (time): 1.88 -> 1.9 (change +1e-2, beyond rtol 1e-09, atol 0)"
std::string diff_line(const RegressDiff& d) {
  std::string s = d.quantity + " (" + kind_name(d.kind) + "): " + d.before + " -> " + d.after;
  s += " (";
  if (d.rel != 0) s += "relative change " + num(d.rel, 3) + ", ";
  return s + "tolerance " + d.tolerance + ")";
}

nlohmann::json side_json(const RegressSide& s) {
  return {{"name", s.name}, {"provenance", s.provenance}};
}

} // namespace

std::string regress_sides_text(const RegressOutcome& o) {
  return "regress: " + o.before.name + ": " + provenance_text(o.before.provenance) +
         "\nregress: " + o.after.name + ": " + provenance_text(o.after.provenance) + "\n";
}

std::string regress_text(const RegressOutcome& o) {
  if (o.diffs.empty())
    return "regress: " + std::to_string(o.runs.size()) + " runs, identical to " + o.before.name +
           (o.tolerance.rtol_time > 0 || o.tolerance.rtol_bytes > 0 || o.tolerance.rtol_count > 0 ||
                    o.tolerance.atol > 0
                ? " (times " + o.tolerance.text(QuantityKind::time) + "; counts " +
                      o.tolerance.text(QuantityKind::count) + "; bytes " +
                      o.tolerance.text(QuantityKind::bytes) + ")"
                : " (bit for bit)") +
           "\n";
  Table t{{"run", "quantity", "kind", o.before.name, o.after.name, "relative change", "tolerance"},
          {}};
  for (const auto& d : o.diffs)
    t.add({d.run, d.quantity, kind_name(d.kind), d.before, d.after, d.rel != 0 ? num(d.rel, 3) : "",
           d.tolerance});
  return t.markdown() + "regress: " + std::to_string(o.diffs.size()) + " differences" +
         (o.failed.empty() ? "" : ", " + std::to_string(o.failed.size()) + " runs failed") + "\n";
}

nlohmann::json regress_json(const RegressOutcome& o) {
  nlohmann::json diffs = nlohmann::json::array();
  for (const auto& d : o.diffs) {
    nlohmann::json j = {{"run", d.run},       {"quantity", d.quantity}, {"kind", kind_name(d.kind)},
                        {"before", d.before}, {"after", d.after},       {"tolerance", d.tolerance}};
    if (d.rel != 0) j["relative_change"] = d.rel;
    diffs.push_back(j);
  }
  const auto& t = o.tolerance;
  return {{"provenance", provenance()},
          {"before", side_json(o.before)},
          {"after", side_json(o.after)},
          {"tolerance",
           {{"rtol_time", t.rtol_time},
            {"rtol_count", t.rtol_count},
            {"rtol_bytes", t.rtol_bytes},
            {"atol", t.atol}}},
          {"runs", o.runs},
          {"failed_runs", o.failed},
          {"differences", diffs},
          {"identical", o.identical()}};
}

std::string regress_junit(const RegressOutcome& o) {
  std::map<std::string, std::vector<const RegressDiff*>> by_run;
  for (const auto& d : o.diffs)
    by_run[d.run].push_back(&d);
  std::size_t failures = 0;
  std::ostringstream cases;
  for (const auto& run : o.runs) {
    cases << "  <testcase classname=\"zcube.regress\" name=\"" << xml_escaped(run) << "\">\n";
    const auto it = by_run.find(run);
    const auto failed = o.failed.find(run);
    if (it != by_run.end() || failed != o.failed.end()) {
      ++failures;
      std::string message, body;
      if (failed != o.failed.end()) message = "run failed: " + failed->second;
      if (it != by_run.end())
        for (const RegressDiff* d : it->second) {
          message += (message.empty() ? "" : "; ") + diff_line(*d);
          body += diff_line(*d) + "\n";
        }
      cases << "    <failure type=\"regression\" message=\"" << xml_escaped(message) << "\">"
            << xml_escaped(body) << "</failure>\n";
    }
    cases << "  </testcase>\n";
  }
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<testsuites>\n <testsuite name=\"zcube regress\" tests=\"" << o.runs.size()
    << "\" failures=\"" << failures << "\" errors=\"0\">\n"
    << "  <properties>\n"
    << "   <property name=\"before\" value=\""
    << xml_escaped(o.before.name + ": " + provenance_text(o.before.provenance)) << "\"/>\n"
    << "   <property name=\"after\" value=\""
    << xml_escaped(o.after.name + ": " + provenance_text(o.after.provenance)) << "\"/>\n"
    << "  </properties>\n"
    << cases.str() << " </testsuite>\n</testsuites>\n";
  return x.str();
}

} // namespace zc
