#include "mpi/probe.hpp"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>

#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "mpi/mpi_session.hpp"
#include "raster/renderer.hpp"
#include "scene/load.hpp"
#include "util/error.hpp"
#include "util/nnls.hpp"

namespace zc {

namespace {

using Clock = std::chrono::steady_clock;

// Best one-way time (half the round trip) between rank 0 and `peer` for `bytes`.
double pingpong(int rank, int peer, std::size_t bytes, int reps) {
  Bytes buf(std::max<std::size_t>(bytes, 1));
  double best = 1e300;
  for (int i = 0; i < reps; ++i) {
    if (rank == 0) {
      const double t = MPI_Wtime();
      MPI_Send(buf.data(), int(bytes), MPI_BYTE, peer, 7, MPI_COMM_WORLD);
      MPI_Recv(buf.data(), int(bytes), MPI_BYTE, peer, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      best = std::min(best, (MPI_Wtime() - t) / 2);
    } else if (rank == peer) {
      MPI_Recv(buf.data(), int(bytes), MPI_BYTE, 0, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      MPI_Send(buf.data(), int(bytes), MPI_BYTE, 0, 7, MPI_COMM_WORLD);
    }
  }
  return best;
}

struct NetFit {
  double short_s = 0, long_s = 0, per_byte_s = 0;
  nlohmann::json samples = nlohmann::json::array();
};

NetFit measure_network(int rank, int size) {
  const std::size_t sizes[] = {0, 8, 64, 100, 1024, 8192, 65536, 262144, 1048576};
  NetFit f;
  std::vector<double> xs, ys, shorts;
  for (int peer = 1; peer < size; ++peer)
    for (std::size_t m : sizes) {
      const int reps = m <= 8192 ? 200 : m <= 65536 ? 50 : 10;
      pingpong(rank, peer, m, 3); // warm-up: connections, pages
      const double t = pingpong(rank, peer, m, reps);
      if (rank != 0) continue;
      f.samples.push_back({{"peer", peer}, {"bytes", m}, {"one_way_s", t}});
      if (m <= 100)
        shorts.push_back(t);
      else {
        xs.push_back(double(m));
        ys.push_back(t);
      }
    }
  if (rank != 0) return f;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    mx += xs[i];
    my += ys[i];
  }
  mx /= double(xs.size());
  my /= double(ys.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) * (xs[i] - mx);
  }
  f.per_byte_s = std::max(0.0, sxx > 0 ? sxy / sxx : 0.0);
  f.long_s = std::max(0.0, my - f.per_byte_s * mx);
  for (double s : shorts)
    f.short_s += s / double(shorts.size());
  return f;
}

// Seconds per call of fn, repeated for at least `min_s`.
template <class F> double time_per_call(F&& fn, double min_s) {
  int n = 0;
  const auto t0 = Clock::now();
  double el = 0;
  do {
    fn();
    ++n;
    el = std::chrono::duration<double>(Clock::now() - t0).count();
  } while (el < min_s);
  return el / n;
}

// The probe's own grouping of the cost fields, finer than the calibration's where a kernel can
// time a field by itself (the vertex transform apart from the triangle set-up).
const std::vector<CostGroup>& probe_groups() {
  static const std::vector<CostGroup> g = [] {
    std::vector<CostGroup> v;
    for (CostGroup c : cost_groups()) {
      if (c.name != "geometry") {
        v.push_back(std::move(c));
        continue;
      }
      // The calibration's geometry group, with the vertex transform on its own.
      std::erase(c.fields, std::string("vertices_transformed"));
      v.push_back({"vertex", {"vertices_transformed"}});
      v.push_back({"triangle", std::move(c.fields)});
    }
    return v;
  }();
  return g;
}

// This host's cost table: per probe group, a multiplier of the prior 80386 table, fitted (NNLS on
// relative errors, pulled weakly towards one overall ratio) to timed kernels whose operations are
// counted exactly: vertex transforms alone, triangle set-up alone, whole renders, a clear, a
// merge and a memory copy.
CostTable measure_cpu(const ProbeOptions& o, nlohmann::json& log) {
  const CostTable prior = prior_i386_costs();
  const auto& groups = probe_groups();
  const std::size_t G = groups.size();
  Matrix A;
  std::vector<double> b;
  auto add = [&](const std::string& what, const Counters& c, double t) {
    A.push_back(group_seconds(prior, groups, c)); // the groups' operations at prior prices
    b.push_back(t);
    log.push_back({{"case", what}, {"seconds", t}, {"counters", c}});
  };
  struct Case {
    const char* scene;
    int size;
  };
  for (const Case& cs : {Case{"teapot", 64}, Case{"teapot", 256}, Case{"teapot", 768},
                         Case{"bunny", 128}, Case{"bunny", 512}}) {
    LoadOptions lo;
    lo.width = lo.height = cs.size;
    const Scene s = load_scene(o.root + "/scenes/" + cs.scene + ".json", lo);
    const std::string name = std::string(cs.scene) + " " + std::to_string(cs.size);
    Counters c;
    add("render " + name, c, time_per_call([&] { c = render_scene(s, 1).counters; }, o.seconds));
    if (cs.size != 256 && cs.size != 512) continue;
    // The geometry kernels by themselves on this scene.
    const NodeRenderer nr(s);
    std::vector<ProjectedVertex> pv(s.vertices.size());
    Counters cv;
    add("project " + name, cv,
        time_per_call(
            [&] {
              cv = Counters{};
              for (std::size_t i = 0; i < pv.size(); ++i)
                pv[i] = nr.project(s.vertices[i], cv);
            },
            o.seconds));
    TriangleBatch batch;
    Counters ct;
    add("set-up " + name, ct,
        time_per_call(
            [&] {
              ct = Counters{};
              for (std::size_t i = 0; i < s.triangles.size(); ++i) {
                const Triangle& t = s.triangles[i];
                const ProjectedVertex* p3[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
                batch.clear();
                nr.setup(std::uint32_t(i), t, p3, nullptr, batch, ct);
              }
            },
            o.seconds));
  }
  {
    Framebuffer x(1024, RowSet::all(1024), glm::vec3(0)), y(1024, RowSet::all(1024), glm::vec3(0));
    Counters cc;
    cc.pixels_cleared = x.pixel_count();
    add("clear 1024x1024", cc, time_per_call([&] { x.clear(glm::vec3(0.5f)); }, o.seconds));
    for (std::size_t i = 0; i < y.depth().size(); ++i)
      y.depth()[i] = float(i % 7) * 0.1f;
    Counters cm;
    add("merge 1024x1024", cm, time_per_call([&] { cm.merge_ops = x.merge(y); }, o.seconds));
  }
  {
    std::vector<std::uint8_t> src(8u << 20, 1), dst(src.size());
    Counters c;
    c.bytes_packed = src.size();
    add("memcpy 8 MiB", c,
        time_per_call([&] { std::memcpy(dst.data(), src.data(), src.size()); }, o.seconds));
  }
  // Relative errors; a weak pull of every multiplier towards the single overall ratio.
  double ta = 0, tb = 0;
  for (std::size_t r = 0; r < A.size(); ++r) {
    for (double v : A[r])
      ta += v;
    tb += b[r];
  }
  const double k0 = ta > 0 ? tb / ta : 1.0;
  for (std::size_t r = 0; r < A.size(); ++r) {
    for (double& v : A[r])
      v /= b[r];
    b[r] = 1.0;
  }
  for (std::size_t g = 0; g < G; ++g) {
    std::vector<double> line(G, 0.0);
    line[g] = 0.05 / k0;
    A.push_back(line);
    b.push_back(0.05);
  }
  return scale_groups(prior, groups, nnls(A, b));
}

} // namespace

std::vector<std::string> probe_outputs(const ProbeOptions& o, int ranks) {
  if (o.nodes.size() <= 1) return {o.out};
  std::string stem = o.out, ext = ".xml";
  if (stem.ends_with(".xml")) stem.resize(stem.size() - 4);
  std::vector<std::string> v;
  for (int p : o.nodes)
    v.push_back(stem + "-" + std::to_string(p) + ext);
  (void)ranks;
  return v;
}

nlohmann::json probe_cluster(const ProbeOptions& o) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2)
    throw UsageError("probe measures the network between MPI processes: mpirun -np P zcube probe "
                     "(P >= 2)");
  for (int p : o.nodes)
    if (p < 1) throw UsageError("probe --nodes: node counts must be positive");
  const NetFit net = measure_network(rank, size);
  nlohmann::json cpu_log = nlohmann::json::array();
  const CostTable mine_cost = measure_cpu(o, cpu_log);
  nlohmann::json cost_json = nlohmann::json::object();
  {
    CostTable t = mine_cost;
    for (auto& [id, v] : t.fields())
      cost_json[id] = *v;
  }
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  const nlohmann::json mine = {{"host", processor_name()},
                               {"cost", cost_json},
                               {"cpu", cpu_log},
                               {"memory", double(pages) * double(page)}};
  const std::string text = mine.dump();
  const auto all = gather_to_root(Bytes(text.begin(), text.end()));
  if (rank != 0) return nlohmann::json::object();

  // The ranks' tables, averaged field by field.
  CostTable avg;
  for (auto& [id, v] : avg.fields())
    *v = 0;
  std::map<std::string, int> ranks_on;
  std::map<std::string, double> mem_of;
  nlohmann::json per_rank = nlohmann::json::array();
  for (const auto& b : all) {
    const auto j = nlohmann::json::parse(std::string(b.begin(), b.end()));
    for (auto& [id, v] : avg.fields())
      *v += j["cost"][id].get<double>() / double(all.size());
    ++ranks_on[j["host"]];
    mem_of[j["host"]] = j["memory"];
    per_rank.push_back(j);
  }
  double memory = 1e300;
  for (const auto& [h, n] : ranks_on)
    memory = std::min(memory, mem_of[h] / n);

  MachineSpec spec = machine_spec("ipsc860");
  spec.name = "cluster";
  std::string hosts;
  for (const auto& [h, n] : ranks_on)
    hosts += (hosts.empty() ? "" : ", ") + h + " x" + std::to_string(n);
  spec.description = "a cluster measured on " + hosts;
  spec.generated_by = "`mpirun -np " + std::to_string(size) + " zcube probe`";
  spec.memory_bytes = std::floor(memory);
  // A message costs at least its envelope at the measured rate (a fit on a fast, noisy cluster can
  // come out below it, which no platform can express).
  const double envelope_s = kSmpiEnvelopeBytes * net.per_byte_s;
  spec.net.startup_short_s = std::max(net.short_s, envelope_s);
  spec.net.startup_long_s = std::max(net.long_s, envelope_s);
  spec.net.short_max_bytes = 100;
  spec.net.per_byte_s = net.per_byte_s;
  spec.net.per_hop_s = 0;
  spec.net.switching = Switching::Circuit;
  spec.net.host_startup_s = net.short_s;
  spec.net.host_per_byte_s = net.per_byte_s;
  spec.cost = avg;
  spec.cost_calibrated = true;
  const auto outs = probe_outputs(o, size);
  std::vector<int> counts = o.nodes.empty() ? std::vector<int>{size} : o.nodes;
  nlohmann::json written = nlohmann::json::array();
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const int P = counts[i];
    // A power of two is a hypercube (per-hop cost 0, so only contention differs), else a ring.
    const Topology topo = (P & (P - 1)) == 0 ? Topology::Cube : Topology::Ring;
    std::ofstream f(outs[i]);
    f << platform_xml(spec, P, topo);
    if (!f) throw InputError(outs[i], 0, "cannot write the platform file");
    written.push_back({{"file", outs[i]}, {"nodes", P}, {"topology", topology_name(topo)}});
  }
  return {{"network",
           {{"startup_short_s", net.short_s},
            {"startup_long_s", net.long_s},
            {"per_byte_s", net.per_byte_s},
            {"samples", net.samples}}},
          {"cost",
           [&] {
             nlohmann::json c = nlohmann::json::object();
             for (auto& [id, v] : avg.fields())
               c[id] = *v;
             return c;
           }()},
          {"ranks", per_rank},
          {"memory_bytes_per_node", spec.memory_bytes},
          {"platforms", written},
          {"ranks_measured", size}};
}

} // namespace zc
