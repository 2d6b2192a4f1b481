// One pixel's SSR march (scene/ssr_trace.h) as `twinraster trace` prints it: a text table of
// both renderers' steps side by side, and JSON.
#pragma once

#include "scene/ssr_trace.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <string>

namespace twr {

// {"marched", "origin": [x, y, z], "direction": [...], "steps": [{"kind", "pixel": [x, y],
//  "ray_distance", "surface_distance", "level", "along"}, ...]}
nlohmann::json ssrMarchTraceToJson(const SsrMarchTrace& trace);

// Step by step, `a` and `b` side by side under their names, the first step where they part
// marked with '*' and named in the last line. `b` may be null (one column).
std::string formatSsrMarchTraces(const std::string& nameA, const SsrMarchTrace& a, const std::string& nameB,
                                 const SsrMarchTrace* b);

}  // namespace twr
