#include "scene/ssr_trace.h"

#include "scene/errors.h"
#include "scene/settings.h"

#include <algorithm>
#include <cmath>

namespace twr {

const char* toString(SsrStepKind kind) {
  switch (kind) {
    case SsrStepKind::InFront: return "in_front";
    case SsrStepKind::Hit: return "hit";
    case SsrStepKind::Behind: return "behind";
    case SsrStepKind::OffScreen: return "off_screen";
    case SsrStepKind::Ended: return "ended";
    case SsrStepKind::Refine: return "refine";
    case SsrStepKind::CellSkipped: return "cell_skipped";
    case SsrStepKind::CellDescend: return "cell_descend";
  }
  return "?";
}

bool endsMarch(SsrStepKind kind) {
  return kind == SsrStepKind::Hit || kind == SsrStepKind::Behind || kind == SsrStepKind::OffScreen ||
         kind == SsrStepKind::Ended;
}

void checkSsrRay(const RenderSettings& settings, int ray) {
  const int samples = settings.ssr.indirectSamples;
  if (ray == kSsrMirrorRay) return;
  if (isSsrView(settings.view)) {
    throw InputError("SSR march trace: the " + std::string(toString(settings.view)) +
                     " view marches the mirror ray only (no indirect light is drawn in it)");
  }
  if (ray >= 0 && ray < samples) return;
  throw InputError("SSR march trace: there is no indirect sample " + std::to_string(ray) +
                   ": settings.ssr.indirect_samples is " + std::to_string(samples) +
                   (samples == 0 ? " (the mirror ray is the only one)"
                                 : " (samples 0.." + std::to_string(samples - 1) + ", or the mirror ray)"));
}

std::string ssrRayName(int ray) {
  return ray == kSsrMirrorRay ? "mirror ray" : "indirect sample " + std::to_string(ray);
}

namespace {

bool near(float a, float b, float relativeTolerance) {
  if (a == b) return true;
  return std::abs(a - b) <= relativeTolerance * std::max(std::abs(a), std::abs(b));
}

}  // namespace

std::optional<std::size_t> firstDifferingStep(const SsrMarchTrace& a, const SsrMarchTrace& b, float relativeTolerance) {
  const std::size_t n = std::min(a.steps.size(), b.steps.size());
  for (std::size_t i = 0; i < n; ++i) {
    const SsrMarchStep& s = a.steps[i];
    const SsrMarchStep& t = b.steps[i];
    if (s.kind != t.kind || s.level != t.level || s.pixel != t.pixel || !near(s.rayDistance, t.rayDistance, relativeTolerance) ||
        !near(s.surfaceDistance, t.surfaceDistance, relativeTolerance) || !near(s.along, t.along, relativeTolerance)) {
      return i;
    }
  }
  if (a.steps.size() != b.steps.size()) return n;
  return std::nullopt;
}

}  // namespace twr
