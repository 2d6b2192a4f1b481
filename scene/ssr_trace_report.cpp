#include "scene/ssr_trace_report.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

namespace twr {

nlohmann::json ssrMarchTraceToJson(const SsrMarchTrace& trace) {
  nlohmann::json steps = nlohmann::json::array();
  for (const SsrMarchStep& s : trace.steps) {
    steps.push_back({{"kind", toString(s.kind)},
                     {"pixel", {s.pixel.x, s.pixel.y}},
                     {"ray_distance", s.rayDistance},
                     {"surface_distance", s.surfaceDistance},
                     {"level", s.level},
                     {"along", s.along}});
  }
  return {{"marched", trace.marched},
          {"ray", trace.ray == kSsrMirrorRay ? nlohmann::json("mirror") : nlohmann::json(trace.ray)},
          {"origin", {trace.origin.x, trace.origin.y, trace.origin.z}},
          {"direction", {trace.direction.x, trace.direction.y, trace.direction.z}},
          {"weight", trace.weight},
          {"steps", steps}};
}

namespace {

std::string stepText(const SsrMarchStep* s) {
  if (!s) return "-";
  char buffer[160];
  std::string kind = toString(s->kind);
  if (s->level > 0) kind += " L" + std::to_string(s->level);
  std::snprintf(buffer, sizeof buffer, "%-16s (%4.0f, %4.0f) %10.5f / %10.5f", kind.c_str(),
                static_cast<double>(s->pixel.x), static_cast<double>(s->pixel.y), static_cast<double>(s->rayDistance),
                static_cast<double>(s->surfaceDistance));
  return buffer;
}

}  // namespace

std::string formatSsrMarchTraces(const std::string& nameA, const SsrMarchTrace& a, const std::string& nameB,
                                 const SsrMarchTrace* b) {
  std::ostringstream out;
  if (!a.marched) {
    out << "  nothing drawn at this pixel: no ray to march\n";
    return out.str();
  }
  char line[400];
  std::snprintf(line, sizeof line, "  origin (%.5f, %.5f, %.5f), direction (%.5f, %.5f, %.5f)\n",
                static_cast<double>(a.origin.x), static_cast<double>(a.origin.y), static_cast<double>(a.origin.z),
                static_cast<double>(a.direction.x), static_cast<double>(a.direction.y),
                static_cast<double>(a.direction.z));
  out << line;
  if (a.ray != kSsrMirrorRay) {
    std::snprintf(line, sizeof line, "  sample weight %.5f\n", static_cast<double>(a.weight));
    out << line;
  }
  // The two directions to the last bit where they differ: an ulp here can part the marches later.
  if (b && b->marched && b->direction != a.direction) {
    std::snprintf(line, sizeof line, "  directions differ: %s (%.9g, %.9g, %.9g), %s (%.9g, %.9g, %.9g)\n",
                  nameA.c_str(), static_cast<double>(a.direction.x), static_cast<double>(a.direction.y),
                  static_cast<double>(a.direction.z), nameB.c_str(), static_cast<double>(b->direction.x),
                  static_cast<double>(b->direction.y), static_cast<double>(b->direction.z));
    out << line;
  }
  std::snprintf(line, sizeof line, "   step  %-58s  %s\n", (nameA + ": kind, pixel, ray / surface distance").c_str(),
                b ? nameB.c_str() : "");
  out << line;
  const std::size_t rows = std::max(a.steps.size(), b ? b->steps.size() : std::size_t{0});
  // A plain index (rows = none) rather than the optional: GCC's -O2 flow analysis takes the
  // optional's payload for uninitialized when it is read in the loop below.
  std::size_t parted = rows;
  if (b) {
    const std::optional<std::size_t> first = firstDifferingStep(a, *b);
    if (first) parted = *first;
  }
  for (std::size_t k = 0; k < rows; ++k) {
    const std::string left = stepText(k < a.steps.size() ? &a.steps[k] : nullptr);
    const std::string right = b ? stepText(k < b->steps.size() ? &b->steps[k] : nullptr) : "";
    std::snprintf(line, sizeof line, "  %c%4zu  %-58s  %s\n", parted == k ? '*' : ' ', k + 1, left.c_str(),
                  right.c_str());
    out << line;
  }
  if (b) {
    if (parted < rows) {
      out << "  " << nameA << " and " << nameB << " part at step " << parted + 1 << "\n";
    } else {
      out << "  " << nameA << " and " << nameB << " take the same " << a.steps.size() << " steps\n";
    }
  }
  if (!a.steps.empty() && !endsMarch(a.steps.back().kind)) out << "  (max_steps ran out: a miss)\n";
  return out.str();
}

}  // namespace twr
