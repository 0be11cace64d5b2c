#pragma once
// Host threads kept for the renderer's phases and frames: creating a thread costs tens of
// microseconds, and a frame runs three phases (vertices, set-up, bands), each on every thread.
// A host-side speed device only: what the threads compute never depends on it.
#include <functional>

namespace zc {

// Runs f(0), ..., f(n - 1) concurrently, f(0) on the calling thread, and returns when all are
// done. Threads 1 .. n-1 come from a process-wide pool that grows to the largest n asked; a call
// made while another thread is using the pool runs on threads of its own instead.
void run_on_workers(int n, const std::function<void(int)>& f);

} // namespace zc
