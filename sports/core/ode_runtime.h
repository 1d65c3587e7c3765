// ODE's process-wide and per-thread set-up, done once where it is needed.
#pragma once

namespace olympics::core {

// Initialises ODE once per process and allocates ODE's per-thread data for the calling thread.
// ODE aborts when a thread that never did this steps a world or collides geoms, so every entry
// point that touches ODE calls this first; after the first call per thread it is one load.
void ensure_ode_ready_for_this_thread();

}  // namespace olympics::core
