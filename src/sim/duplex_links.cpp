#include "sim/duplex_links.hpp"

#include <algorithm>
#include <set>

namespace zc {

double DuplexLinks::per_byte(const std::vector<Link>& links) const {
  double s = one_way_;
  for (const Link& l : links) {
    auto r = busy_.find({l.second, l.first});
    if (r != busy_.end() && !r->second.empty()) s = std::max(s, both_busy_);
  }
  return s;
}

void DuplexLinks::rerate_reverse(const std::vector<Link>& links, double t, std::uint64_t skip,
                                 std::vector<Change>& out) {
  std::set<std::uint64_t> touched;
  for (const Link& l : links) {
    auto r = busy_.find({l.second, l.first});
    if (r == busy_.end()) continue;
    touched.insert(r->second.begin(), r->second.end());
  }
  touched.erase(skip);
  for (std::uint64_t id : touched) {
    Flow& f = flows_.at(id);
    const double s = per_byte(f.links);
    if (s == f.per_byte) continue;
    f.remaining = std::max(0.0, f.remaining - (t - f.since) / f.per_byte);
    f.since = t;
    f.per_byte = s;
    f.version = ++last_version_;
    out.push_back({f.m, t + f.remaining * s, f.version});
  }
}

void DuplexLinks::begin(const TransitPtr& m, const std::vector<Link>& links, double bytes, double t,
                        std::vector<Change>& out) {
  const std::uint64_t id = next_id_++;
  id_[m.get()] = id;
  for (const Link& l : links)
    busy_[l].push_back(id);
  Flow& f = flows_[id];
  f.m = m;
  f.links = links;
  f.remaining = bytes;
  f.per_byte = per_byte(links);
  f.since = t;
  f.version = ++last_version_;
  out.push_back({m, t + bytes * f.per_byte, f.version});
  rerate_reverse(links, t, id, out);
}

void DuplexLinks::end(const Transit& m, double t, std::vector<Change>& out) {
  auto it = id_.find(&m);
  if (it == id_.end()) return;
  const std::uint64_t id = it->second;
  id_.erase(it);
  const std::vector<Link> links = std::move(flows_.at(id).links);
  flows_.erase(id);
  for (const Link& l : links) {
    auto& v = busy_[l];
    v.erase(std::find(v.begin(), v.end(), id));
    if (v.empty()) busy_.erase(l);
  }
  rerate_reverse(links, t, id, out);
}

bool DuplexLinks::current(const Transit& m, std::uint64_t version) const {
  auto it = id_.find(&m);
  return it != id_.end() && flows_.at(it->second).version == version;
}

} // namespace zc
