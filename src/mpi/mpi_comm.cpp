#include "mpi/mpi_comm.hpp"

#include <time.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "util/error.hpp"

namespace zc {

namespace {

int byte_count_of(std::size_t n) {
  if (n > std::size_t(INT_MAX))
    throw std::runtime_error("MPI message of " + std::to_string(n) +
                             " bytes: more than one MPI count can carry");
  return int(n);
}
int byte_count(const Bytes& b) {
  return byte_count_of(b.size());
}

// A zcube message on the wire. Its charged size travels as an 8-byte trailer word. A payload of at
// most kInlineMax bytes is copied into one MPI message with the trailer after it; a larger one
// goes as a 16-byte header message (payload size, then the trailer word with kBodyFollows set)
// and the payload itself, sent from the sender's own buffer: appending 8 bytes to a buffer of
// several megabytes would reallocate and copy all of it, a copy no modelled program makes. MPI
// keeps the order of messages from one sender with one tag, so the body is the next message after
// its header.
constexpr std::size_t kInlineMax = 4096;
constexpr std::uint64_t kBodyFollows = std::uint64_t(1) << 63;

class MpiSend final : public SendRequest {
public:
  MpiSend(Payload payload, std::uint64_t charged, int dst, int tag, MPI_Comm comm) {
    const std::size_t n = payload.size();
    if (n <= kInlineMax) {
      head_.resize(n + sizeof charged);
      std::copy(payload.begin(), payload.end(), head_.begin());
      std::memcpy(head_.data() + n, &charged, sizeof charged);
    } else {
      const std::uint64_t word[2] = {n, charged | kBodyFollows};
      head_.resize(sizeof word);
      std::memcpy(head_.data(), word, sizeof word);
      body_ = std::move(payload); // shared with its other holders, never written
    }
    MPI_Isend(head_.data(), byte_count(head_), MPI_BYTE, dst, tag, comm, &req_[0]);
    if (!body_.empty())
      MPI_Isend(body_.data(), byte_count(body_.bytes()), MPI_BYTE, dst, tag, comm, &req_[1]);
  }
  ~MpiSend() override { wait(); } // the buffers must outlive the transfer
  bool done() {
    int flag = 1;
    MPI_Testall(2, req_, &flag, MPI_STATUSES_IGNORE);
    return flag != 0;
  }
  void wait() override { MPI_Waitall(2, req_, MPI_STATUSES_IGNORE); }

private:
  Bytes head_;
  Payload body_;
  MPI_Request req_[2] = {MPI_REQUEST_NULL, MPI_REQUEST_NULL};
};

} // namespace

const char* MpiComm::clock_name() {
  static const char* name = [] {
    const char* e = std::getenv("ZCUBE_MPI_CLOCK");
    const std::string v = e ? e : "wall";
    if (v != "wall" && v != "cpu")
      throw UsageError("ZCUBE_MPI_CLOCK '" + v + "': expected wall or cpu");
    return v == "cpu" ? "cpu" : "wall";
  }();
  return name;
}

double MpiComm::clock() {
  static const bool cpu = std::string(clock_name()) == "cpu";
  if (!cpu) return MPI_Wtime();
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

MpiComm::MpiComm(MPI_Comm world, int nodes, Topology topology, NodeStats& stats)
    : world_(world), nodes_(nodes), topology_(topology), stats_(stats) {
  MPI_Comm_rank(world_, &rank_);
  MPI_Comm_size(world_, &world_size_);
  int* ub = nullptr;
  int flag = 0;
  MPI_Comm_get_attr(world_, MPI_TAG_UB, &ub, &flag);
  if (flag && ub) tag_ub_ = *ub;
  t0_ = clock();
}

void MpiComm::check_peer(int peer, int tag) const {
  if (peer < 0 || peer >= world_size_)
    throw std::runtime_error("rank " + std::to_string(rank_) + ": no MPI rank " +
                             std::to_string(peer));
  if (tag < 0 || tag > tag_ub_)
    throw std::runtime_error("tag " + std::to_string(tag) + " above this MPI's MPI_TAG_UB " +
                             std::to_string(tag_ub_));
}

void MpiComm::send(int dst, int tag, Message m) {
  const double t = clock();
  in_flight_.push_back(isend(dst, tag, std::move(m)));
  reap();
  const double t1 = clock();
  stats_.comm_s += t1 - t;
  if (stats_.log) stats_.log->activity(Activity::Send, t - t0_, t1 - t0_);
}

// Sends complete in the order they were posted (MPI's non-overtaking order per destination, and a
// shared-memory transport drains its queues in order): testing from the oldest and stopping at the
// first one in flight keeps a burst of sends linear (testing them all after every send is
// quadratic in a burst: a Blazek host posting a description per object).
void MpiComm::reap() {
  std::size_t done = 0;
  while (done < in_flight_.size() && static_cast<MpiSend&>(*in_flight_[done]).done())
    ++done;
  in_flight_.erase(in_flight_.begin(), in_flight_.begin() + std::ptrdiff_t(done));
}

void MpiComm::flush() {
  for (auto& h : in_flight_)
    h->wait();
  in_flight_.clear();
}

SendHandle MpiComm::isend(int dst, int tag, Message m) {
  check_peer(dst, tag);
  stats_.count_send(m.payload.size(), m.charged);
  if (stats_.log)
    stats_.log->sends.push_back(
        {dst, tag, m.charged, message_hops(topology_, nodes_, rank_, dst), now()});
  return std::make_unique<MpiSend>(std::move(m.payload), m.charged, dst, tag, world_);
}

// A body of n bytes received into a buffer that is not cleared first. A Bytes (std::vector) cannot
// be sized without writing every byte (a memset of a whole large band before the copy that
// follows, waste no modelled program has): MPI writes into the reserved capacity, and
// the vector then takes those bytes as its elements by inserting them from where they already lie
// (a copy onto itself, which memmove returns from at once: source and destination are equal).
Bytes MpiComm::receive_body(std::size_t n, int from_rank, int tag) {
  Bytes b;
  b.reserve(n);
  MPI_Recv(b.data(), byte_count_of(n), MPI_BYTE, from_rank, tag, world_, MPI_STATUS_IGNORE);
  b.insert(b.end(), b.data(), b.data() + n);
  return b;
}

Message MpiComm::recv_message(int src, int tag, int* from) {
  if (src != kAnySource) check_peer(src, tag);
  const double t = clock();
  MPI_Status st;
  MPI_Probe(src == kAnySource ? MPI_ANY_SOURCE : src, tag, world_, &st);
  int n = 0;
  const double arrived = clock(); // the probe returns once the message is there
  MPI_Get_count(&st, MPI_BYTE, &n);
  const int from_rank = st.MPI_SOURCE;
  Bytes b(static_cast<std::size_t>(n));
  MPI_Recv(b.data(), n, MPI_BYTE, from_rank, tag, world_, MPI_STATUS_IGNORE);
  std::uint64_t charged = 0;
  if (b.size() < sizeof charged) throw std::runtime_error("MPI message without its charged size");
  std::memcpy(&charged, b.data() + b.size() - sizeof charged, sizeof charged);
  b.resize(b.size() - sizeof charged);
  if (charged & kBodyFollows) { // a header: the payload is the next message from its sender
    std::uint64_t size = 0;
    if (b.size() != sizeof size) throw std::runtime_error("MPI message header of a bad size");
    std::memcpy(&size, b.data(), sizeof size);
    charged &= ~kBodyFollows;
    b = receive_body(static_cast<std::size_t>(size), from_rank, tag);
  }
  reap();
  const double t1 = clock();
  stats_.comm_s += t1 - t;
  if (stats_.log) {
    stats_.log->activity(Activity::Wait, t - t0_, t1 - t0_);
    stats_.log->recvs.push_back({from_rank, tag, arrived - t0_, t1 - t0_});
  }
  if (from) *from = from_rank;
  return {std::move(b), std::size_t(charged)};
}

} // namespace zc
