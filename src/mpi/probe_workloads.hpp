#pragma once
// The probe's workloads (probe_cpu.hpp): each builder registers the loops of one scene or buffer
// size on the harness (probe_harness.hpp) and times them (Probe::run); probe_workloads.cpp says
// what each loop runs and why.
#include "mpi/probe_harness.hpp"

namespace zc::cpu_probe {

// Projection, set-up, the frame-buffer z-buffer (in file order and scattered), span lists, the
// active z-buffer, the load estimate; with `kurc`, the active merge and the output too.
void render_loops(Probe& p, const ProbeScene& ps, bool kurc);
// Kurc et al.'s active z-buffer on a pair's node's half of the triangles (and all with `whole`).
void active_loops(Probe& p, const ProbeScene& ps, bool whole);
// The frame-buffer z-buffer in a band of rows the recent-lines window holds (no far line).
void near_loops(Probe& p, const ProbeScene& ps);
// Charles et al.'s MultiScatter of triangles among `nodes` nodes.
void multiscatter_loops(Probe& p, const ProbeScene& ps, int nodes);
// Blazek's nodes: spheres tessellated, set up and drawn.
void sphere_loops(Probe& p, const ProbeScene& ps);
// A new frame buffer; with `merges`, locations packed and merged back.
void buffer_loops(Probe& p, int size, bool merges);

} // namespace zc::cpu_probe
