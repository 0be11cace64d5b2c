#include "run/call_trace.hpp"

#include "util/record_io.hpp"

namespace zc {

namespace {

void put_string(RecordWriter& w, const std::string& s) {
  w.put_sized(Bytes(s.begin(), s.end()));
}

std::string get_string(RecordReader& r) {
  const Bytes b = r.get_sized();
  return {b.begin(), b.end()};
}

template <class T> void put_vector(RecordWriter& w, const std::vector<T>& v) {
  w.put(std::uint64_t(v.size()));
  w.put(v);
}

template <class T> std::vector<T> get_vector(RecordReader& r) {
  return r.get_vector<T>(std::size_t(r.get<std::uint64_t>()));
}

} // namespace

std::uint32_t CallTrace::string_id(const std::string& s) {
  const auto [it, fresh] = string_ids.emplace(s, std::uint32_t(strings.size()));
  if (fresh) strings.push_back(s);
  return it->second;
}

// The trace travels from the process that recorded it to the one that keeps it (run/batch.hpp):
// plain records, in the host's byte order.
std::vector<std::uint8_t> CallTrace::serialize() const {
  RecordWriter w;
  w.put(std::int32_t(nodes));
  w.put(std::int32_t(topology));
  w.put(std::uint8_t(read_clock));
  put_string(w, nlohmann::json(image).dump());
  w.put(std::uint64_t(ranks.size()));
  for (const auto& r : ranks)
    put_vector(w, r);
  put_vector(w, counters);
  w.put(std::uint64_t(strings.size()));
  for (const auto& s : strings)
    put_string(w, s);
  w.put(std::uint64_t(blocks.size()));
  for (const auto& b : blocks)
    put_vector(w, b);
  w.put(std::uint64_t(metrics.size()));
  for (const auto& m : metrics)
    put_string(w, m);
  return std::move(w).take();
}

CallTrace CallTrace::parse(const std::vector<std::uint8_t>& bytes) {
  RecordReader r(bytes, "call trace");
  CallTrace t;
  t.nodes = r.get<std::int32_t>();
  t.topology = Topology(r.get<std::int32_t>());
  t.read_clock = r.get<std::uint8_t>() != 0;
  t.image = nlohmann::json::parse(get_string(r)).get<ImageVerdict>();
  t.ranks.resize(std::size_t(r.get<std::uint64_t>()));
  for (auto& calls : t.ranks)
    calls = get_vector<Call>(r);
  t.counters = get_vector<Counters>(r);
  t.strings.resize(std::size_t(r.get<std::uint64_t>()));
  for (auto& s : t.strings)
    s = get_string(r);
  t.blocks.resize(std::size_t(r.get<std::uint64_t>()));
  for (auto& b : t.blocks)
    b = get_vector<TracedBlock>(r);
  t.metrics.resize(std::size_t(r.get<std::uint64_t>()));
  for (auto& m : t.metrics)
    m = get_string(r);
  return t;
}

} // namespace zc
