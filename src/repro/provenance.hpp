#pragma once
// Where a result came from: the schema of zcube's JSON outputs, the zcube and SimGrid versions,
// the commit and the command line. Every report, sweep.json, golden file and results README
// carries it, so that a comparison across versions can say which versions it compared.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

// The schema of the reports, sweep.json and the golden files: raised when a field is renamed,
// removed or changes meaning (not when one is added). Files without provenance are schema 0.
inline constexpr int kSchemaVersion = 1;

// The command line provenance() records; main() gives it. The program's own path is recorded as
// "zcube", whatever it was started as.
void set_command_line(const std::vector<std::string>& argv);

// Files kept under version control (results/**, tests/golden) are rewritten bit for bit by any
// later commit that changes no number: they carry no commit and no path of this machine.
enum class ProvenanceFor { local_file, committed_file };

// {"schema_version", "zcube_version", "zcube_commit", "simgrid_version", "command_line"}; for a
// committed file without "zcube_commit", with the command line's absolute paths under the working
// directory made relative and --jobs (which changes no result) left out.
nlohmann::json provenance(ProvenanceFor use = ProvenanceFor::local_file);

// The schema of a file that may carry a "provenance" object: 0 when it has none.
int schema_version_of(const nlohmann::json& file);

// One line for people: "zcube 0.9.0 (commit abc), SimGrid 3.32.0, schema 1", or "no provenance
// (schema 0)" for null.
std::string provenance_text(const nlohmann::json& provenance);

// Appends a "Provenance" paragraph (committed_file provenance) to a README reproduce wrote.
void append_provenance(const std::string& readme);

} // namespace zc
