#include "repro/provenance.hpp"

#include <xbt/base.h> // before simgrid/version.h, which uses its macros

#include <simgrid/version.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "repro/build_info.hpp"

namespace zc {

namespace {

std::vector<std::string>& recorded_command_line() {
  static std::vector<std::string> argv;
  return argv;
}

std::string simgrid_version() {
  int major = 0, minor = 0, patch = 0;
  sg_version_get(&major, &minor, &patch); // the library's, which may be newer than its headers
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

// An absolute path under the working directory, relative to it; anything else as given.
std::string relative_if_under_cwd(const std::string& word) {
  namespace fs = std::filesystem;
  if (word.empty() || word[0] != '/') return word;
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (ec) return word;
  const fs::path rel = fs::path(word).lexically_normal().lexically_relative(cwd);
  if (rel.empty() || *rel.begin() == "..") return word;
  return rel.string();
}

// The command line of a committed file: the same for every checkout and every core count.
std::vector<std::string> portable_command_line(const std::vector<std::string>& argv) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& w = argv[i];
    if (w == "--jobs") {
      ++i; // and its value
      continue;
    }
    if (w.starts_with("--jobs=")) continue;
    const auto eq = w.find('=');
    if (w.starts_with("--") && eq != std::string::npos)
      out.push_back(w.substr(0, eq + 1) + relative_if_under_cwd(w.substr(eq + 1)));
    else
      out.push_back(relative_if_under_cwd(w));
  }
  return out;
}

} // namespace

void set_command_line(const std::vector<std::string>& argv) {
  recorded_command_line() = argv;
  if (!argv.empty()) recorded_command_line()[0] = "zcube";
}

nlohmann::json provenance(ProvenanceFor use) {
  const auto& argv = recorded_command_line();
  nlohmann::json p = {{"schema_version", kSchemaVersion},
                      {"zcube_version", build_info::kZcubeVersion},
                      {"simgrid_version", simgrid_version()}};
  if (use == ProvenanceFor::committed_file) {
    p["command_line"] = portable_command_line(argv);
  } else {
    p["zcube_commit"] = build_info::kZcubeCommit;
    p["command_line"] = argv;
  }
  return p;
}

int schema_version_of(const nlohmann::json& file) {
  if (!file.is_object() || !file.contains("provenance")) return 0;
  const auto& p = file["provenance"];
  if (!p.is_object() || !p.contains("schema_version") || !p["schema_version"].is_number_integer())
    return 0;
  return p["schema_version"].get<int>();
}

std::string provenance_text(const nlohmann::json& p) {
  if (!p.is_object()) return "no provenance (schema 0)";
  auto text = [&p](const char* key) {
    return p.contains(key) && p[key].is_string() ? p[key].get<std::string>() : "?";
  };
  std::string s = "zcube " + text("zcube_version");
  if (p.contains("zcube_commit")) s += " (commit " + text("zcube_commit") + ")";
  s += ", SimGrid " + text("simgrid_version");
  s += ", schema " + std::to_string(schema_version_of({{"provenance", p}}));
  return s;
}

void append_provenance(const std::string& readme) {
  const nlohmann::json p = provenance(ProvenanceFor::committed_file);
  std::string command;
  for (const auto& w : p["command_line"]) {
    if (!command.empty()) command += ' ';
    command += w.get<std::string>();
  }
  if (command.empty()) command = "zcube"; // called from a program that recorded no command line
  std::ofstream out(readme, std::ios::app);
  out << "\n## Provenance\n\nWritten by `" << command << "`: " << provenance_text(p)
      << " (the schema of zcube's JSON outputs).\n";
  if (!out.flush()) throw std::runtime_error("cannot write '" + readme + "'");
}

} // namespace zc
