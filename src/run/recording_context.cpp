#include "run/recording_context.hpp"

#include <algorithm>

namespace zc {

const SceneFacts& RecordingContext::scene_facts() const {
  if (facts_) return *facts_;
  if (!own_facts_) own_facts_ = zc::scene_facts(scene_);
  return *own_facts_;
}

void RecordingContext::charge(const Counters& w) {
  work_ += w;
  phase_work_[open_.empty() ? std::string() : open_.back().first] += w;
  spend(w);
}

void RecordingContext::phase_begin(const std::string& name) {
  open_.emplace_back(name, comm_.now());
  stats_.set_phase(name);
  if (std::find(phase_order_.begin(), phase_order_.end(), name) == phase_order_.end())
    phase_order_.push_back(name);
}

void RecordingContext::phase_end() {
  if (open_.empty()) return;
  auto [name, t0] = open_.back();
  open_.pop_back();
  stats_.set_phase(open_.empty() ? std::string() : open_.back().first);
  const double t1 = comm_.now();
  phase_totals_[name] += t1 - t0;
  if (stats_.log) stats_.log->phases.push_back({name, int(open_.size()), t0, t1});
}

void RecordingContext::start_timed_region() {
  stats_.timed_start_s = comm_.now();
  stats_.timed = true;
}

void RecordingContext::end_timed_region() {
  stats_.timed_end_s = comm_.now();
  stats_.timed_ended = true;
}

void RecordingContext::alloc(double bytes, const std::string& what) {
  stats_.memory += bytes;
  stats_.peak_memory = std::max(stats_.peak_memory, stats_.memory);
  if (memory_capacity_ > 0 && stats_.memory > memory_capacity_)
    throw OutOfNodeMemory(comm_.rank(), what, stats_.memory, memory_capacity_);
}

void RecordingContext::release(double bytes) {
  stats_.memory = std::max(0.0, stats_.memory - bytes);
}

void RecordingContext::deliver_image(int frame, Framebuffer image) {
  images_.push_back({frame, std::move(image)});
}

void RecordingContext::deliver_rows(int frame, Framebuffer rows) {
  images_.push_back({frame, std::move(rows), true});
}

NodeRecord RecordingContext::record(Recorder who) const {
  NodeRecord r;
  r.who = who;
  r.stats = stats_;
  r.phase_order = phase_order_;
  r.phase_totals = phase_totals_;
  r.phase_work = phase_work_;
  r.work = work_;
  r.metrics = metrics_;
  return r;
}

} // namespace zc
