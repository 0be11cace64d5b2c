#pragma once
// What an algorithm sees of the machine it runs on (docs/architecture.md: no SimGrid or MPI type
// here, so the same algorithm code runs on the simulator and on the MPI backend). One NodeContext
// per node (and one for the host computer, srm, when the algorithm uses it).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "comm/comm.hpp"
#include "raster/framebuffer.hpp"
#include "scene/scene.hpp"
#include "util/counters.hpp"

namespace zc {

// A node ran out of its modelled memory (Kurc et al. mark such runs '*').
class OutOfNodeMemory : public std::runtime_error {
public:
  OutOfNodeMemory(int node, const std::string& what, double needed, double capacity)
      : std::runtime_error("node " + std::to_string(node) + " out of memory: " + what + " needs " +
                           std::to_string(std::int64_t(needed)) + " bytes in all, " +
                           std::to_string(std::int64_t(needed - capacity)) + " over its " +
                           std::to_string(std::int64_t(capacity)) + " bytes"),
        node(node), over_by(needed - capacity) {}
  int node;
  double over_by;
};

struct AlgorithmOptions {
  int frames = 1;
  std::map<std::string, std::string>
      values; // algorithm-specific (--vertices request, --packet 100), as given
  std::map<std::string, std::string> defaults; // the others, filled in by validate_options
  // The value given, else the declared default (validate_options has checked both).
  std::string get(const std::string& key) const {
    auto it = values.find(key);
    if (it != values.end()) return it->second;
    auto d = defaults.find(key);
    return d == defaults.end() ? std::string() : d->second;
  }
};

// One algorithm option (--vertices request): the single declaration zcube run's flag, its --help,
// its default and its validation all come from.
struct OptionSpec {
  enum class Kind { Choice, Integer, SizeList, NodeList };
  std::string name; // flag without dashes
  Kind kind = Kind::Choice;
  std::string default_value;
  std::vector<std::string> choices; // Choice: the allowed values
  long long min = 0, max = 0;       // Integer and each element of SizeList / NodeList
  std::string help;
};

class NodeContext {
public:
  virtual ~NodeContext() = default;

  virtual Comm& comm() = 0;
  int rank() { return comm().rank(); }
  int nodes() { return comm().size(); }

  // The scene as loaded by the host. Algorithms read from it only what the node was sent, or what
  // the host (node 0 for methods without one) is entitled to read: the global view is a
  // convenience of the simulator, not a shared memory of the machine.
  virtual const Scene& scene() const = 0;
  // scene_facts(scene()), worked out once for all the nodes that share the scene.
  virtual const SceneFacts& scene_facts() const = 0;
  virtual const AlgorithmOptions& options() const = 0;

  // Charges the counted operations to this node's CPU: virtual time advances by
  // sum(count x cost) x cpu-scale.
  virtual void charge(const Counters& work) = 0;
  // Charges copying `bytes` into or out of message buffers (the one place packing is priced).
  void charge_packing(std::size_t bytes) {
    Counters c;
    c.bytes_packed = bytes;
    charge(c);
  }

  // Named phase: the time between begin and end is recorded for this node (a phase may be entered
  // several times; the durations add up).
  virtual void phase_begin(const std::string& name) = 0;
  virtual void phase_end() = 0;
  class Phase {
  public:
    Phase(NodeContext& c, const std::string& name) : c_(c) { c_.phase_begin(name); }
    ~Phase() { c_.phase_end(); }
    Phase(const Phase&) = delete;
    Phase& operator=(const Phase&) = delete;

  private:
    NodeContext& c_;
  };
  Phase phase(const std::string& name) { return Phase(*this, name); }

  // The paper's timed region starts here on this node (its timer read once the input is in place,
  // docs/papers.md) and ends at end_timed_region, or when the node finishes if it never calls it
  // (elastic). The report's timed_s is the longest (end - start) over the nodes that started one;
  // without a start the whole run is timed.
  virtual void start_timed_region() = 0;
  virtual void end_timed_region() = 0;

  // Modelled node memory: alloc throws OutOfNodeMemory when the node's capacity is exceeded.
  virtual void alloc(double bytes, const std::string& what) = 0;
  virtual void release(double bytes) = 0;

  // The node holding the final picture of a frame hands it over (a full-screen frame buffer).
  virtual void deliver_image(int frame, Framebuffer image) = 0;
  // A node writing its own rows straight to the output device hands them over; the rows every node
  // delivered for a frame make its picture (rows nobody delivers stay background). Costs nothing:
  // the device is outside the modelled machine, as in Charles et al. §4 ("write the image to an
  // output device").
  virtual void deliver_rows(int frame, Framebuffer rows) = 0;

  // Algorithm-specific figures for the report (merged into its top level, e.g. "load_imbalance",
  // "communication": {"concurrent_volume_bytes": ...}). Node 0's are used.
  virtual nlohmann::json& metrics() = 0;
};

struct Algorithm {
  std::string name;
  std::string summary;
  bool uses_host = false; // a host-computer actor runs `host`
  std::function<void(NodeContext&)> node;
  std::function<void(NodeContext&)> host;
  std::vector<OptionSpec> options; // the algorithm-specific flags it takes
  bool renders_frames = false;     // draws --frames K pictures of the camera path
  bool draws_picture = true;       // hands over a picture (--image, --depth; not a benchmark)
  bool needs_cube = false;         // runs on hypercubes only (--topology cube)
  bool untextured = false;         // renders untextured scenes only
  // The one-node run its paper's speed-ups divide by (docs/papers.md): sequential for Charles et
  // al., scanline for Kurc et al., node-initiated for Blazek. An algorithm that names itself is a
  // reference: on one node, without options, it is a sweep's baseline.
  std::string reference = "sequential";
  // Checks of its options against the node count, once the platform is known and before the
  // simulation starts (UsageError), e.g. pingpong's --from and --to.
  std::function<void(const AlgorithmOptions&, int nodes)> check_nodes;
  // The node whose metrics (NodeContext::metrics) are the run's, at the report's top level; null:
  // node 0. Each node keeps its own in the report's per_node entries.
  std::function<int(const AlgorithmOptions&)> metrics_node;
};

const std::vector<Algorithm>& algorithms();

// Checks the options given to `a` before any simulation: each is one of its declared options
// with an allowed value, --frames only for algorithms that render frames, the topology it needs;
// fills in the declared defaults. UsageError naming the flag otherwise.
void validate_options(const Algorithm& a, AlgorithmOptions& o, bool cube);
// Every algorithm option of every algorithm, once per name (zcube run's flags), with the names of
// the algorithms that take it.
std::vector<std::pair<OptionSpec, std::string>> all_option_specs();
const Algorithm& find_algorithm(const std::string& name); // UsageError when unknown

} // namespace zc
