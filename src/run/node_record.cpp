#include "run/node_record.hpp"

#include "machine/platform_xml.hpp"

namespace zc {

void to_json(nlohmann::json& j, const Traffic& t) {
  j = {{"charged_bytes", t.charged_bytes},
       {"payload_bytes", t.payload_bytes},
       {"messages", t.messages}};
}

void from_json(const nlohmann::json& j, Traffic& t) {
  t.charged_bytes = j.at("charged_bytes");
  t.payload_bytes = j.at("payload_bytes");
  t.messages = j.at("messages");
}

nlohmann::json rank_json(const Recorder& who) {
  return who.host_computer ? nlohmann::json(kHostComputerName) : nlohmann::json(who.rank);
}

void to_json(nlohmann::json& j, const NodeRecord& r) {
  nlohmann::json work = nlohmann::json::object();
  for (const auto& [n, w] : r.phase_work)
    work[n] = w;
  j = {{"rank", r.who.rank},
       {"host_computer", r.who.host_computer},
       {"busy_s", r.stats.busy_s},
       {"comm_s", r.stats.comm_s},
       {"finish_s", r.stats.finish_s},
       {"bytes_sent", r.stats.bytes_sent},
       {"payload_bytes_sent", r.stats.payload_bytes_sent},
       {"messages", r.stats.messages},
       {"phase_traffic", r.stats.phase_traffic},
       {"peak_memory", r.stats.peak_memory},
       {"timed", r.stats.timed},
       {"timed_start_s", r.stats.timed_start_s},
       {"timed_ended", r.stats.timed_ended},
       {"timed_end_s", r.stats.timed_end_s},
       {"phase_order", r.phase_order},
       {"phase_totals", r.phase_totals},
       {"phase_work", work},
       {"work", r.work},
       {"metrics", r.metrics}};
  if (r.stats.log) j["timeline"] = *r.stats.log;
}

void from_json(const nlohmann::json& j, NodeRecord& r) {
  r.who = {j.at("rank").get<int>(), j.at("host_computer").get<bool>()};
  r.stats.busy_s = j.at("busy_s");
  r.stats.comm_s = j.at("comm_s");
  r.stats.finish_s = j.at("finish_s");
  r.stats.bytes_sent = j.at("bytes_sent");
  r.stats.payload_bytes_sent = j.at("payload_bytes_sent");
  r.stats.messages = j.at("messages");
  r.stats.phase_traffic = j.at("phase_traffic").get<std::map<std::string, Traffic>>();
  r.stats.peak_memory = j.at("peak_memory");
  r.stats.timed = j.value("timed", false);
  r.stats.timed_start_s = j.value("timed_start_s", 0.0);
  r.stats.timed_ended = j.value("timed_ended", false);
  r.stats.timed_end_s = j.value("timed_end_s", 0.0);
  r.phase_order = j.at("phase_order").get<std::vector<std::string>>();
  r.phase_totals = j.at("phase_totals").get<std::map<std::string, double>>();
  r.phase_work.clear();
  for (const auto& [n, w] : j.at("phase_work").items())
    r.phase_work[n] = w.get<Counters>();
  r.work = j.at("work").get<Counters>();
  r.metrics = j.at("metrics");
  r.stats.log = j.contains("timeline")
                    ? std::make_shared<EventLog>(j.at("timeline").get<EventLog>())
                    : nullptr;
}

} // namespace zc
