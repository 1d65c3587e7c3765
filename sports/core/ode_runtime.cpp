#include "core/ode_runtime.h"

#include <ode/ode.h>

#include <mutex>

namespace olympics::core {

void ensure_ode_ready_for_this_thread() {
  static std::once_flag init_once;
  std::call_once(init_once, [] { dInitODE2(0); });
  thread_local bool thread_ready = false;
  if (!thread_ready) {
    dAllocateODEDataForThread(dAllocateMaskAll);
    thread_ready = true;
  }
}

}  // namespace olympics::core
