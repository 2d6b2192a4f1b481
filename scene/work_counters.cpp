#include "scene/work_counters.h"

namespace twr {

WorkCounters& workCounters() {
  static WorkCounters counters;
  return counters;
}

}  // namespace twr
