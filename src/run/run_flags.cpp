#include "run/run_flags.hpp"

#include <algorithm>
#include <sstream>

#include "machine/machine.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"

namespace zc {

std::vector<std::pair<OptionSpec, std::string>> run_option_specs() {
  auto all = all_option_specs();
  std::erase_if(all, [](const auto& p) { return p.second == "pingpong"; }); // zcube pingpong's
  return all;
}

namespace {

using G = RunFlag::Group;
constexpr int kMaxFrames = 10000; // --frames

std::string machine_form() {
  std::string f;
  for (const auto& m : machine_names())
    f += m + "|";
  return f + "FILE.xml";
}

// An option's values as the help shows them: "a|b|c", "1..64", "LIST".
std::string option_form(const OptionSpec& s) {
  std::string f;
  switch (s.kind) {
  case OptionSpec::Kind::Choice:
    for (const auto& c : s.choices)
      f += (f.empty() ? "" : "|") + c;
    return f;
  case OptionSpec::Kind::Integer:
    return std::to_string(s.min) + ".." + std::to_string(s.max);
  case OptionSpec::Kind::SizeList:
    return "SIZES";
  case OptionSpec::Kind::NodeList:
    return "NODES";
  }
  return "VALUE";
}

std::vector<RunFlag> make_flags() {
  std::vector<RunFlag> v = {
      {"machine", G::Run, machine_form(), "ipsc2",
       "the machine model: a built-in one or a "
       "SimGrid platform file"},
      {"nodes", G::Run, "INT", "1",
       "simulated nodes (a power of two on a cube; a platform .xml states its own)"},
      {"topology", G::Run, "cube|ring", "cube", "a platform .xml states its own"},
      {"fidelity", G::Run, "analytic|flow|circuit", "circuit",
       "how messages are timed (docs/user-guide.md: Fidelity)"},
      {"algorithm", G::Run, "NAME", "sequential", "the algorithm (zcube run --list)"},
      {"scene", G::Run, "FILE", "scenes/teapot.json", "the scene (.json, .sdl or .obj)"},
      {"size", G::Run, "WxH", "", "image size (default: the scene's own)"},
      {"frames", G::Run, "INT", "1",
       "pictures along the scene's camera path (1.." + std::to_string(kMaxFrames) + ")"}};
  for (const auto& w : what_if_specs())
    v.push_back({w.flag, G::WhatIf, w.example, "", "what-if: " + w.meaning + "; " + w.bounds});
  for (const auto& [s, algos] : run_option_specs())
    v.push_back({s.name, G::Option, option_form(s), s.default_value, algos + ": " + s.help});
  return v;
}

int parse_int(const std::string& s, const std::string& flag) {
  std::size_t used = 0;
  int v = 0;
  try {
    v = std::stoi(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty())
    throw UsageError("--" + flag + " '" + s + "': expected an integer");
  return v;
}

// The run flags proper (machine .. frames) into c; the what-ifs and options are applied after.
void apply_run_flags(const std::map<std::string, std::string>& v, const std::string& scene,
                     RunConfig& c) {
  auto get = [&](const std::string& k) { // the value given, else the table's default
    auto it = v.find(k);
    return it == v.end() ? find_run_flag(k)->default_text : it->second;
  };
  c.machine = get("machine");
  c.topology = parse_topology(get("topology"));
  c.fidelity = parse_fidelity(get("fidelity"));
  const bool xml = is_platform_file(c.machine);
  c.nodes = v.count("nodes") || !xml ? parse_int(get("nodes"), "nodes") : 0; // 0: the file's
  if (!xml) check_node_count(c.topology, c.nodes);
  if (xml && v.count("topology"))
    throw UsageError("--topology " + v.at("topology") + " with --machine " + c.machine +
                     ": a platform file states its own topology (write one with zcube platform "
                     "--topology " +
                     v.at("topology") + ")");
  c.algorithm = get("algorithm");
  c.scene_path = v.count("scene") ? v.at("scene") : scene;
  if (v.count("size")) {
    const ImageSize s = parse_image_size(v.at("size"));
    c.width = s.width;
    c.height = s.height;
  }
  c.options.frames = parse_int(get("frames"), "frames");
  // Each picture is simulated and rendered again by the sequential renderer for the comparison.
  if (c.options.frames > kMaxFrames)
    throw UsageError("--frames " + v.at("frames") + ": at most " + std::to_string(kMaxFrames) +
                     " pictures (each is simulated and rendered again for the comparison; "
                     "longer camera paths take hours of host time)");
}

// The what-ifs, each parsed by its descriptor; on a built-in machine they are also applied to its
// figures, so a factor that takes a figure out of bounds (or a --per-hop on a store-and-forward
// machine) fails before any run. A platform file's figures are checked when it is loaded.
WhatIfs what_ifs_of(const std::map<std::string, std::string>& v, const RunConfig& c) {
  WhatIfs w;
  for (const auto& spec : what_if_specs())
    if (v.count(spec.flag)) w.set(spec.flag, parse_what_if(spec, v.at(spec.flag)));
  if (!is_platform_file(c.machine) && !w.empty()) {
    MachineFigures f = machine_figures(machine_spec(c.machine), 1);
    apply_what_ifs(w, f);
  }
  return w;
}

} // namespace

const std::vector<RunFlag>& run_flags() {
  static const std::vector<RunFlag> flags = make_flags();
  return flags;
}

const RunFlag* find_run_flag(const std::string& name) {
  for (const auto& f : run_flags())
    if (f.name == name) return &f;
  return nullptr;
}

const std::vector<std::string>& run_flag_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& f : run_flags())
      v.push_back(f.name);
    return v;
  }();
  return names;
}

RunConfig config_from_flags(const std::map<std::string, std::string>& v, const std::string& scene) {
  RunConfig c;
  apply_run_flags(v, scene, c);
  c.what_ifs = what_ifs_of(v, c);
  for (const auto& [s, algos] : run_option_specs())
    if (v.count(s.name)) c.options.values[s.name] = v.at(s.name);
  // The algorithm and its options are checked here, so a bad combination fails only its point.
  validate_options(find_algorithm(c.algorithm), c.options,
                   is_platform_file(c.machine) || c.topology == Topology::Cube);
  return c;
}

std::string run_flags_markdown() {
  std::ostringstream o;
  o << "| flag | values | default | meaning |\n|---|---|---|---|\n";
  for (const auto& f : run_flags()) {
    std::string form = f.value_form;
    std::replace(form.begin(), form.end(), '|', '/'); // a bar would split the table's cell
    o << "| `--" << f.name << "` | " << form << " | " << f.default_text << " | " << f.help
      << " |\n";
  }
  return o.str();
}

} // namespace zc
