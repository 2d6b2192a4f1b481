// What compare --reference raytrace writes and prints of an SSR frame against the ray-traced
// reference (raytrace/ssr_reference.h): the JSON block and one labelled picture.
#pragma once

#include "raytrace/ssr_reference.h"
#include "scene/image.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <string>
#include <vector>

namespace twr {

// One renderer's frame measured against the reference.
struct SsrReferenceSide {
  std::string name;  // "cpu", "gl"
  const RenderOutput* frame = nullptr;
  SsrReferenceError error;
};

// {"kind": "raytrace", "tracer": "Embree 3.13.5", "trace_ms", "indirect_samples",
//  "rays": {"mirror": {"sky": n, "visible": n, "off_screen": n, "occluded": n}, "indirect": {...}},
//  "<side>": {"pixels", "mean_abs_diff", "max_abs_diff", "over_3",
//             "classes": {"<class>": {"pixels", "mean_abs_diff", "max_abs_diff", "over_3", "error_share"}}}}
// error_share: the class's part of the side's summed error, in [0, 1].
nlohmann::json ssrReferenceToJson(const SsrReference& reference, const std::vector<SsrReferenceSide>& sides);

// Two rows of tiles: the reference and each side's frame above, the error classes and each
// side's |frame - reference| (largest channel, diff.png's heat ramp) below; a legend of the
// class colours and the ramp under them.
Image ssrReferenceMontage(const SsrReference& reference, const std::vector<SsrReferenceSide>& sides);

}  // namespace twr
