#include "report/reading.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

namespace twr::report {

namespace {

// A shortcut is "invisible" when it changes the image by less than this RMSE (a quarter of one
// 8-bit level averaged over the image) and leaves fewer than kInvisibleOver1Pct % of the pixels
// more than one level off.
constexpr double kNegligibleLevels = 0.25;
constexpr double kInvisibleOver1Pct = 1.0;
// Error differences against the reference below this fraction also count as no difference.
constexpr double kNegligibleFraction = 0.05;
// Up to this time ratio the exact setting is "worth its cost" without qualification.
constexpr double kCheapRatio = 1.5;
// When the shortcut changes the image by less than this fraction of the exact setting's own
// error against the reference, sampling error dominates and the reading says so.
constexpr double kSamplingDominates = 0.5;
// A tessellation is "at the knee" within this fraction of the best error (plus kNegligibleLevels).
constexpr double kKneeFraction = 0.10;

std::string fmt(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}
std::string ms(double value) { return fmt(value < 10.0 ? "%.2f ms" : "%.1f ms", value); }
std::string levels(double value) { return fmt("%.2f", value) + " levels"; }
std::string percent(double fraction) { return fmt("%.0f%%", 100.0 * fraction); }
std::string times(double ratio) { return fmt("%.2fx", ratio); }

std::vector<const ReportPoint*> pointsOf(const KnobResult& knob, const std::string& backend) {
  std::vector<const ReportPoint*> out;
  for (const ReportPoint& p : knob.points)
    if (p.backend == backend) out.push_back(&p);
  return out;
}

const ReportPoint* find(const KnobResult& knob, const std::string& backend, const std::string& setting) {
  for (const ReportPoint& p : knob.points)
    if (p.backend == backend && p.setting == setting) return &p;
  return nullptr;
}

std::string upper(const std::string& backend) {
  std::string s = backend;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

enum class Verdict { Invisible, FreeWin, WorthIt, TradeOff, ShortcutCloser };

// A shortcut setting against the exact one on one backend.
struct TradeOff {
  Verdict verdict = Verdict::Invisible;
  double timeRatio = 1.0;     // exact / shortcut
  double effectRmse = 0.0;    // how much the shortcut alone changes the image, levels
  double effectOver1Pct = 0.0;
  int effectMax = 0;
  bool samplingDominates = false;
  std::string detail;         // the numbers, one paragraph
};

TradeOff weigh(const std::string& who, const ReportPoint& shortcut, const ReportPoint& exact) {
  TradeOff t;
  t.timeRatio = shortcut.msMin > 0.0 ? exact.msMin / shortcut.msMin : 1.0;
  const double gain = shortcut.vsReference.rmse - exact.vsReference.rmse;  // > 0: exact is closer
  const double relative = shortcut.vsReference.rmse > 0.0 ? gain / shortcut.vsReference.rmse : 0.0;
  const bool referenceSeesIt = std::fabs(gain) >= kNegligibleLevels && std::fabs(relative) >= kNegligibleFraction;
  if (shortcut.vsExactSetting) {
    t.effectRmse = shortcut.vsExactSetting->rmse;
    t.effectOver1Pct = shortcut.vsExactSetting->over1Pct();
    t.effectMax = shortcut.vsExactSetting->maxAbsDiff;
  } else {
    t.effectRmse = std::fabs(gain);
  }
  const bool visible = t.effectRmse >= kNegligibleLevels || t.effectOver1Pct >= kInvisibleOver1Pct || referenceSeesIt;
  t.samplingDominates = t.effectRmse < kSamplingDominates * exact.vsReference.rmse;
  if (!visible) {
    t.verdict = Verdict::Invisible;
  } else if (referenceSeesIt && gain < 0.0) {
    t.verdict = Verdict::ShortcutCloser;
  } else if (t.timeRatio <= 1.0) {
    t.verdict = Verdict::FreeWin;
  } else if (t.timeRatio <= kCheapRatio) {
    t.verdict = Verdict::WorthIt;
  } else {
    t.verdict = Verdict::TradeOff;
  }

  std::string& s = t.detail;
  s = who + " (fastest frames): " + exact.setting + " " + ms(exact.msMin) + ", " + shortcut.setting + " " + ms(shortcut.msMin) +
      " (" + times(t.timeRatio) + "); RMSE against the reference " + levels(exact.vsReference.rmse) + " and " +
      levels(shortcut.vsReference.rmse) + ". ";
  if (shortcut.vsExactSetting) {
    s += shortcut.setting + " alone changes the image by " + levels(t.effectRmse) + " RMSE (worst pixel " +
         std::to_string(t.effectMax) + ", " + fmt("%.1f%%", t.effectOver1Pct) + " of pixels over one level). ";
  }
  switch (t.verdict) {
    case Verdict::Invisible:
      s += "The shortcut is invisible here: take the faster (" +
           (t.timeRatio <= 1.0 ? exact.setting : shortcut.setting) + ").";
      break;
    case Verdict::FreeWin:
      s += exact.setting + " is no slower and is the exact one: keep it.";
      break;
    case Verdict::WorthIt:
      s += exact.setting + " costs +" + percent(t.timeRatio - 1.0) + " time for a visible difference: worth its cost.";
      break;
    case Verdict::TradeOff:
      s += exact.setting + " costs " + times(t.timeRatio) + " the time: a real trade-off, worth it where the "
           "difference shows.";
      break;
    case Verdict::ShortcutCloser:
      s += "Here " + shortcut.setting + " measures closer to the reference, by " + levels(-gain) +
           ": look at the images before trusting either.";
      break;
  }
  if (t.verdict != Verdict::Invisible && t.samplingDominates) {
    s += " Both stay about " + levels(exact.vsReference.rmse) + " from the reference: most of that is one sample "
         "per pixel (edges, texture minification without mipmaps), not this knob.";
  }
  return t;
}

const char* verdictText(Verdict v) {
  switch (v) {
    case Verdict::Invisible: return "invisible shortcut, take the faster";
    case Verdict::FreeWin: return "the exact setting costs nothing, keep it";
    case Verdict::WorthIt: return "worth its cost";
    case Verdict::TradeOff: return "a real trade-off";
    case Verdict::ShortcutCloser: return "the shortcut measured closer, check the images";
  }
  return "";
}

// Two settings of one knob: the detailed reading per backend, and a one-line summary.
KnobReading readTwo(const KnobResult& knob, const std::string& shortcut, const std::string& exact) {
  KnobReading r;
  std::string times_;
  std::string effect;
  Verdict worst = Verdict::Invisible;
  bool sampling = false;
  double exactError = 0.0;
  for (const std::string backend : {"cpu", "gl"}) {
    const ReportPoint* a = find(knob, backend, shortcut);
    const ReportPoint* e = find(knob, backend, exact);
    if (!a || !e) continue;
    const TradeOff t = weigh(upper(backend), *a, *e);
    r.detail += t.detail + " ";
    times_ += (times_.empty() ? "" : ", ") + upper(backend) + " " + times(t.timeRatio);
    if (effect.empty()) {
      effect = levels(t.effectRmse) + " RMSE, " + fmt("%.1f%%", t.effectOver1Pct) + " of pixels over one level";
    }
    worst = std::max(worst, t.verdict);
    sampling = sampling || t.samplingDominates;
    exactError = e->vsReference.rmse;
  }
  if (times_.empty()) return r;
  r.summary = exact + " over " + shortcut + ": " + verdictText(worst) + ". Time " + times_ + "; " + shortcut +
              " alone changes the image by " + effect + ".";
  if (sampling && worst != Verdict::Invisible) {
    r.summary += " Against the reference both are about " + levels(exactError) + " off, mostly sampling.";
  }
  return r;
}

KnobReading readTessellation(const KnobResult& knob) {
  KnobReading r;
  std::string knees;
  double bestOverall = 0.0;
  double worstRatio = 1.0;
  double wasted = 0.0;
  for (const std::string backend : {"cpu", "gl"}) {
    const std::vector<const ReportPoint*> points = pointsOf(knob, backend);
    if (points.size() < 2) continue;
    const ReportPoint& first = *points.front();
    const ReportPoint& last = *points.back();
    double best = first.vsReference.rmse;
    for (const ReportPoint* p : points) best = std::min(best, p->vsReference.rmse);
    const ReportPoint* knee = points.back();
    for (const ReportPoint* p : points) {
      if (p->vsReference.rmse <= best * (1.0 + kKneeFraction) + kNegligibleLevels) {
        knee = p;
        break;
      }
    }
    r.detail += upper(backend) + ": from " + first.setting + " to " + last.setting + " the RMSE against the exact "
                "sphere goes from " + levels(first.vsReference.rmse) + " to " + levels(last.vsReference.rmse) +
                " and the silhouette mismatch from " + std::to_string(first.vsReference.coverageMismatch) + " to " +
                std::to_string(last.vsReference.coverageMismatch) + " pixels, while the fastest frame goes from " +
                ms(first.msMin) + " to " + ms(last.msMin) + ". " + knee->setting + " is within " +
                percent(kKneeFraction) + " of the best error at " + ms(knee->msMin);
    if (knee != &last && knee->msMin > 0.0) {
      const double ratio = last.msMin / knee->msMin;
      const double gain = std::max(0.0, knee->vsReference.rmse - best);
      r.detail += "; finer meshes cost up to " + times(ratio) + " that for at most " + levels(gain) + " less";
      worstRatio = std::max(worstRatio, ratio);
      wasted = std::max(wasted, gain);
    }
    r.detail += ". ";
    knees += (knees.empty() ? "" : ", ") + knee->setting + " on the " + upper(backend) + " (" + ms(knee->msMin) + ")";
    bestOverall = best;
  }
  if (knees.empty()) return r;
  if (bestOverall > 1.0) {
    r.detail += "The " + levels(bestOverall) + " left at the finest mesh are not tessellation but one sample per "
                "pixel (silhouette and texture aliasing), which only supersampling removes.";
  }
  r.summary = "Tessellation stops paying at " + knees + ": finer meshes cost up to " + times(worstRatio) +
              " the time for at most " + levels(wasted) + " less error.";
  return r;
}

KnobReading readResolution(const KnobResult& knob) {
  KnobReading r;
  std::string costs;
  std::string errors;
  for (const std::string backend : {"cpu", "gl"}) {
    const std::vector<const ReportPoint*> points = pointsOf(knob, backend);
    if (points.size() < 2) continue;
    const ReportPoint& first = *points.front();
    const ReportPoint& last = *points.back();
    const double pixelRatio = static_cast<double>(last.vsReference.width) * last.vsReference.height /
                              (static_cast<double>(first.vsReference.width) * first.vsReference.height);
    const double timeRatio = first.msMin > 0.0 ? last.msMin / first.msMin : 0.0;
    r.detail += upper(backend) + " (fastest frames): " + times(pixelRatio) + " the pixels (" + first.setting + " to " + last.setting +
                ") cost " + times(timeRatio) + " the time (" + ms(first.msMin) + " to " + ms(last.msMin) + ")";
    r.detail += timeRatio < 0.5 * pixelRatio ? ", well below the pixel ratio: per-frame and per-triangle costs "
                                               "dominate the small images"
                                             : ", close to the pixel ratio: per-pixel work dominates";
    r.detail += "; the RMSE against a same-size reference goes from " + levels(first.vsReference.rmse) + " to " +
                levels(last.vsReference.rmse) + ". ";
    costs += (costs.empty() ? "" : ", ") + upper(backend) + " " + times(timeRatio);
    errors = levels(first.vsReference.rmse) + " to " + levels(last.vsReference.rmse);
    r.summary = times(pixelRatio) + " the pixels cost ";
  }
  if (costs.empty()) return r;
  r.summary += costs + " the time; the per-pixel error against a same-size reference falls from " + errors +
               " (less aliasing per pixel).";
  return r;
}

KnobReading readThreads(const KnobResult& knob) {
  KnobReading r;
  std::string best;
  for (const std::string backend : {"cpu", "gl"}) {
    const std::vector<const ReportPoint*> points = pointsOf(knob, backend);
    if (points.size() < 2) continue;
    const ReportPoint& one = *points.front();
    r.detail += upper(backend) + " (fastest frames): " + one.setting + " " + ms(one.msMin);
    const ReportPoint* fastest = &one;
    for (std::size_t i = 1; i < points.size(); ++i) {
      const double speedup = points[i]->msMin > 0.0 ? one.msMin / points[i]->msMin : 0.0;
      r.detail += ", " + points[i]->setting + " " + ms(points[i]->msMin) + " (" + times(speedup) + ")";
      if (points[i]->msMin < fastest->msMin) fastest = points[i];
    }
    bool sameImage = true;
    for (const ReportPoint* p : points) sameImage = sameImage && p->vsReference.rmse == one.vsReference.rmse;
    r.detail += "; fastest with " + fastest->setting + ". " +
                (sameImage ? "The error is the same at every count, as it must be. "
                           : "The error changes with the count, which it must not: a bug to chase. ");
    best += (best.empty() ? "" : ", ") + upper(backend) + " " + fastest->setting + " (" +
            times(fastest->msMin > 0.0 ? one.msMin / fastest->msMin : 1.0) + " over one)";
  }
  if (!best.empty()) r.summary = "Fastest: " + best + "; the images do not change with the count.";
  return r;
}

KnobReading readPrecision(const KnobResult& knob) {
  KnobReading r;
  const ReportPoint* f = find(knob, "cpu", "float, same loop");
  const ReportPoint* d = find(knob, "cpu", "double, same loop");
  if (f && d) {
    const TradeOff t = weigh("CPU", *f, *d);
    r.detail = t.detail + " ";
    r.summary = t.verdict == Verdict::Invisible
                    ? "Float is enough: double changes the image by " + levels(t.effectRmse) + " (worst pixel " +
                          std::to_string(t.effectMax) + ") and costs " + times(t.timeRatio) + " the time in the same loop."
                    : "Double changes the image visibly (" + levels(t.effectRmse) + ", worst pixel " +
                          std::to_string(t.effectMax) + ") at " + times(t.timeRatio) + " the time: " +
                          verdictText(t.verdict) + ".";
  }
  const ReportPoint* cpu = find(knob, "cpu", "float");
  if (cpu && f) {
    r.detail += "The CPU renderer's own loop draws the float frame in " + ms(cpu->msMin) + " (the simple loop " +
                ms(f->msMin) + ")";
    if (cpu->vsExactSetting) r.detail += " and is " + levels(cpu->vsExactSetting->rmse) + " from the double image";
    r.detail += ". ";
  }
  const ReportPoint* g = find(knob, "gl", "float");
  if (g && cpu) {
    r.detail += "GL (float) is " + levels(g->vsReference.rmse) + " from the reference, the CPU " +
                levels(cpu->vsReference.rmse);
    if (g->cpuVsGl) r.detail += "; the two float pipelines are " + levels(g->cpuVsGl->rmse) + " apart";
    r.detail += ".";
  }
  return r;
}

// Where mipmaps pay: each filter's error against the footprint-averaged reference and its time,
// against bilinear (level 0), per backend.
KnobReading readMinification(const KnobResult& knob) {
  KnobReading r;
  const ReportPoint* bilinear = find(knob, "cpu", "bilinear");
  const ReportPoint* trilinear = find(knob, "cpu", "trilinear");
  const ReportPoint* nearest = find(knob, "cpu", "nearest");
  if (bilinear && trilinear) {
    const double gain = trilinear->vsReference.rmse > 0.0 ? bilinear->vsReference.rmse / trilinear->vsReference.rmse : 0.0;
    r.summary = "Trilinear is " + levels(trilinear->vsReference.rmse) + " from the footprint average where bilinear "
                "is " + levels(bilinear->vsReference.rmse) + " (" + times(gain) + " less error) at " +
                times(trilinear->msMedian / bilinear->msMedian) + " bilinear's CPU time.";
  }
  for (const std::string backend : {"cpu", "gl"}) {
    const ReportPoint* base = find(knob, backend, "bilinear");
    if (!base) continue;
    r.detail += (backend == "cpu" ? "CPU" : "GL") + std::string(":");
    for (const ReportPoint& p : knob.points) {
      if (p.backend != backend) continue;
      r.detail += " " + p.setting + " " + levels(p.vsReference.rmse) + " in " + ms(p.msMedian) +
                  (p.setting == "bilinear" ? "" : " (" + times(p.msMedian / base->msMedian) + ")") + ";";
    }
    r.detail += " ";
  }
  if (nearest && bilinear) {
    r.detail += "Level 0 aliases either way: nearest " + levels(nearest->vsReference.rmse) + ", bilinear " +
                levels(bilinear->vsReference.rmse) + ". The mipmapped filters pay where a pixel covers more than a "
                "texel (the far floor); near the camera they read level 0 like bilinear. ";
  }
  const ReportPoint* aniso2 = find(knob, "cpu", "trilinear_aniso_2x");
  const ReportPoint* aniso16 = find(knob, "cpu", "trilinear_aniso_16x");
  if (aniso16 && trilinear && bilinear) {
    const double gain = aniso16->vsReference.rmse > 0.0 ? bilinear->vsReference.rmse / aniso16->vsReference.rmse : 0.0;
    r.summary += " Anisotropic filtering is " + levels(aniso16->vsReference.rmse) + " from it (" + times(gain) +
                 " less error than bilinear) at " + times(aniso16->msMedian / trilinear->msMedian) +
                 " trilinear's CPU time.";
    if (aniso2) {
      r.detail += aniso2->vsReference.rmse == aniso16->vsReference.rmse
                      ? "Anisotropy 2x and 16x measure the same: llvmpipe's filter ignores the ratio (its clamp of "
                        "the short axis never fires), and the CPU draws what llvmpipe draws. "
                      : "Anisotropy 2x and 16x differ: " + levels(aniso2->vsReference.rmse) + " and " +
                            levels(aniso16->vsReference.rmse) + ". ";
    }
  }
  const ReportPoint* glTrilinear = find(knob, "gl", "trilinear");
  if (glTrilinear && glTrilinear->cpuVsGl) {
    r.detail += "CPU and GL trilinear are " + levels(glTrilinear->cpuVsGl->rmse) + " apart";
    const ReportPoint* glAniso = find(knob, "gl", "trilinear_aniso_16x");
    if (glAniso && glAniso->cpuVsGl) r.detail += ", anisotropic " + levels(glAniso->cpuVsGl->rmse);
    r.detail += ".";
  }
  return r;
}

std::string trimmed(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Drops a trailing "; " (or " ") left by a list built item by item.
std::string trimmedSemicolon(std::string s) {
  s = trimmed(s);
  if (!s.empty() && s.back() == ';') s.pop_back();
  return s;
}

// ---- the height-field section ----

// A method is the pick at a view when it is the fastest whose interior error is within this
// fraction (plus kNegligibleLevels) of the best method's.
constexpr double kHeightPickFraction = 0.10;
// The speed target: parallax_occlusion within this factor of normal_map's frame at 720p.
constexpr double kPomCostTarget = 2.0;

const ReportPoint* heightPoint(const HeightFieldView& view, const std::string& backend, const std::string& method,
                               int layersMin = 0, int layersMax = 0) {
  for (const ReportPoint& p : view.result.points) {
    if (p.backend != backend || !p.heightField || p.heightField->method != method) continue;
    if (layersMin == 0 || (p.heightField->layersMin == layersMin && p.heightField->layersMax == layersMax)) return &p;
  }
  return nullptr;
}

std::string angleText(int degrees) { return std::to_string(degrees) + "\xC2\xB0"; }

// The layer sets the marching methods ran at in this view, in sweep order.
std::vector<std::pair<int, int>> layerSetsOf(const HeightFieldView& view) {
  std::vector<std::pair<int, int>> sets;
  for (const ReportPoint& p : view.result.points) {
    if (p.backend != "cpu" || !p.heightField || p.heightField->method != "parallax_occlusion") continue;
    sets.push_back({p.heightField->layersMin, p.heightField->layersMax});
  }
  return sets;
}

std::string layersText(int lo, int hi) { return std::to_string(lo) + "-" + std::to_string(hi); }

KnobReading readHeightFieldSection(const HeightFieldSection& section) {
  KnobReading r;
  std::vector<std::string> fields;
  for (const HeightFieldView& v : section.views)
    if (std::find(fields.begin(), fields.end(), v.field) == fields.end()) fields.push_back(v.field);

  // 1. Which method is worth its cost at which angle (CPU, fastest frames).
  std::string picks = "Worth its cost, per view (CPU, fastest frames; the fastest method within " +
                      percent(kHeightPickFraction) + " + " + levels(kNegligibleLevels) +
                      " of the best interior error): ";
  std::string pickSummary;
  for (const HeightFieldView& v : section.views) {
    const ReportPoint* best = nullptr;
    const ReportPoint* pick = nullptr;
    for (const ReportPoint& p : v.result.points) {
      if (p.backend != "cpu" || !p.heightField || p.heightField->method == kTrueGeometry) continue;
      if (!best || p.vsReference.rmse < best->vsReference.rmse) best = &p;
    }
    if (!best) continue;
    for (const ReportPoint& p : v.result.points) {
      if (p.backend != "cpu" || !p.heightField || p.heightField->method == kTrueGeometry) continue;
      if (p.vsReference.rmse <= best->vsReference.rmse * (1.0 + kHeightPickFraction) + kNegligibleLevels &&
          (!pick || p.msMin < pick->msMin)) {
        pick = &p;
      }
    }
    const ReportPoint* base = heightPoint(v, "cpu", "normal_map");
    picks += v.field + " " + angleText(v.angleDeg) + ": " + pick->setting + " (" + levels(pick->vsReference.rmse) +
             ", " + ms(pick->msMin);
    if (best != pick) picks += "; best " + best->setting + " " + levels(best->vsReference.rmse) + " at " + ms(best->msMin);
    if (base && base != pick) picks += "; normal_map " + levels(base->vsReference.rmse) + " at " + ms(base->msMin);
    picks += "). ";
    if (v.angleDeg > 0) {
      pickSummary += (pickSummary.empty() ? "" : ", ") + v.field + " " + angleText(v.angleDeg) + " " + pick->setting;
    }
  }

  // 2. POM against plain parallax at 45 degrees and beyond, default layers (8-32).
  std::string pomText = "parallax_occlusion 8-32 against plain parallax at 45\xC2\xB0 and beyond (interior RMSE, CPU): ";
  int pomLower = 0, pomCompared = 0;
  std::string pomMisses;
  for (const HeightFieldView& v : section.views) {
    if (v.angleDeg < 45) continue;
    const ReportPoint* pom = heightPoint(v, "cpu", "parallax_occlusion", 8, 32);
    const ReportPoint* plain = heightPoint(v, "cpu", "parallax");
    if (!pom || !plain) continue;
    ++pomCompared;
    const bool lower = pom->vsReference.rmse < plain->vsReference.rmse;
    if (lower) ++pomLower;
    else pomMisses += (pomMisses.empty() ? "" : ", ") + v.field + " " + angleText(v.angleDeg);
    pomText += v.field + " " + angleText(v.angleDeg) + " " + fmt("%.2f", pom->vsReference.rmse) + " vs " +
               fmt("%.2f", plain->vsReference.rmse) + (lower ? "" : " (not lower)") + "; ";
    const ReportPoint* glPom = heightPoint(v, "gl", "parallax_occlusion", 8, 32);
    const ReportPoint* glPlain = heightPoint(v, "gl", "parallax");
    if (glPom && glPlain && (glPom->vsReference.rmse < glPlain->vsReference.rmse) != lower) {
      pomText += "(GL disagrees there: " + fmt("%.2f", glPom->vsReference.rmse) + " vs " +
                 fmt("%.2f", glPlain->vsReference.rmse) + ") ";
    }
  }
  if (pomCompared > 0) {
    pomText = trimmedSemicolon(pomText) + ". POM is lower in " + std::to_string(pomLower) + " of " +
              std::to_string(pomCompared) + " views" + (pomMisses.empty() ? "." : "; not at " + pomMisses + ".");
  }

  // 3. Steep parallax's stair-steps: what POM's interpolation between the last two layers
  // removes, i.e. steep's error above POM's at the same layers.
  std::string stairs = "Stair-steps: steep_parallax's interior error minus parallax_occlusion's at the same layers "
                       "(positive: what steep's stair-steps cost; negative: POM's line between the last two layers "
                       "misses by more than the step it replaces), CPU: ";
  std::string stairsSummary;
  for (const std::string& field : fields) {
    std::string shown;
    double largest = 0.0;
    std::string largestAt;
    for (const HeightFieldView& v : section.views) {
      if (v.field != field) continue;
      std::string perLayers;
      for (const auto& [lo, hi] : layerSetsOf(v)) {
        const ReportPoint* steep = heightPoint(v, "cpu", "steep_parallax", lo, hi);
        const ReportPoint* pom = heightPoint(v, "cpu", "parallax_occlusion", lo, hi);
        if (!steep || !pom) continue;
        const double excess = steep->vsReference.rmse - pom->vsReference.rmse;
        if (!perLayers.empty()) perLayers += "/";
        perLayers += fmt("%+.2f", excess);
        if (excess > largest) {
          largest = excess;
          largestAt = angleText(v.angleDeg) + " " + layersText(lo, hi);
        }
        if (excess >= kNegligibleLevels && shown.find(angleText(v.angleDeg)) == std::string::npos) {
          shown += (shown.empty() ? "" : ", ") + angleText(v.angleDeg);
        }
      }
      if (!perLayers.empty()) stairs += field + " " + angleText(v.angleDeg) + " " + perLayers + "; ";
    }
    stairsSummary += (stairsSummary.empty() ? "" : "; ") + field + ": " +
                     (shown.empty() ? std::string("nowhere above ") + levels(kNegligibleLevels)
                                    : "at " + shown + " (most: " + levels(largest) + " at " + largestAt + ")");
  }
  std::string layerList;
  if (!section.views.empty()) {
    for (const auto& [lo, hi] : layerSetsOf(section.views.front()))
      layerList += (layerList.empty() ? "" : "/") + layersText(lo, hi);
  }
  stairs = trimmedSemicolon(stairs) + " (levels, layers " + layerList + "). Stair-steps cost more than " +
           levels(kNegligibleLevels) + ": " + stairsSummary + ".";

  // 4. How many layers POM needs to beat relief (relief at its default 8-32 layers).
  std::string beat = "Layers parallax_occlusion needs to match and to beat relief 8-32 (relief's binary search adds "
                     "5 steps to its layers), CPU: ";
  for (const HeightFieldView& v : section.views) {
    if (v.angleDeg == 0) continue;
    const ReportPoint* relief = heightPoint(v, "cpu", "relief", 8, 32);
    if (!relief) continue;
    const ReportPoint* matches = nullptr;  // within kNegligibleLevels
    const ReportPoint* beats = nullptr;    // at or below
    for (const auto& [lo, hi] : layerSetsOf(v)) {
      const ReportPoint* pom = heightPoint(v, "cpu", "parallax_occlusion", lo, hi);
      if (!pom) continue;
      if (!matches && pom->vsReference.rmse <= relief->vsReference.rmse + kNegligibleLevels) matches = pom;
      if (!beats && pom->vsReference.rmse <= relief->vsReference.rmse) beats = pom;
    }
    const auto layersOf = [](const ReportPoint* p) { return p->setting.substr(p->setting.find(' ') + 1); };
    beat += v.field + " " + angleText(v.angleDeg) + " (relief " + levels(relief->vsReference.rmse) + ", " +
            ms(relief->msMin) + "): ";
    if (matches && matches != beats) {
      beat += "within " + levels(kNegligibleLevels) + " at " + layersOf(matches) + " (" +
              levels(matches->vsReference.rmse) + ", " + ms(matches->msMin) + "), ";
    }
    if (beats) {
      beat += "below it at " + layersOf(beats) + " (" + levels(beats->vsReference.rmse) + ", " + ms(beats->msMin) + "); ";
    } else {
      const std::vector<std::pair<int, int>> sets = layerSetsOf(v);
      beat += "not below it up to " + (sets.empty() ? std::string("?") : layersText(sets.back().first, sets.back().second)) + "; ";
    }
  }
  beat = trimmedSemicolon(beat) + ".";

  // 5. The floor and the silhouettes.
  std::string floor = "The displaced mesh itself, drawn with one sample per pixel, is ";
  std::string silhouettes;
  for (const HeightFieldView& v : section.views) {
    const ReportPoint* mesh = heightPoint(v, "cpu", kTrueGeometry);
    const ReportPoint* base = heightPoint(v, "cpu", "normal_map");
    if (mesh) floor += v.field + " " + angleText(v.angleDeg) + " " + fmt("%.2f", mesh->vsReference.rmse) + " (" + ms(mesh->msMin) + "), ";
    if (base && base->heightField) {
      const HeightFieldPointInfo& h = *base->heightField;
      silhouettes += v.field + " " + angleText(v.angleDeg) + " " + std::to_string(h.silhouetteApproxOnly) + "/" +
                     std::to_string(h.silhouetteReferenceOnly) + " (interior " + std::to_string(h.interiorPixels) +
                     "), ";
    }
  }
  if (floor.back() == ' ') {
    floor.resize(floor.size() - 2);
    floor += section.referenceSamplesPerAxis > 1
                 ? " levels from the reference (CPU, fastest frame): what one sample per pixel costs on the true "
                   "surface, the floor under every method."
                 : " levels from the reference (CPU, fastest frame); with one reference sample per pixel this is "
                   "float against double only, not the one-sample floor.";
  } else {
    floor.clear();
  }
  if (!silhouettes.empty()) {
    silhouettes.resize(silhouettes.size() - 2);
    silhouettes = "Parallax does not move silhouettes: every method draws the flat plane's outline, where the mesh's "
                  "border lies lower and its walls stand out, so the pixels only the plane covers / only the mesh "
                  "covers are the same for every method at a view: " + silhouettes +
                  ". They are counted apart, not put in the error.";
  }

  // 6. GL against CPU.
  double worstCpuGl = 0.0;
  std::string worstCpuGlAt;
  for (const HeightFieldView& v : section.views) {
    for (const ReportPoint& p : v.result.points) {
      if (p.cpuVsGl && p.cpuVsGl->rmse > worstCpuGl) {
        worstCpuGl = p.cpuVsGl->rmse;
        worstCpuGlAt = p.setting + " on " + v.field + " at " + angleText(v.angleDeg);
      }
    }
  }
  const std::string gl = worstCpuGlAt.empty() ? std::string()
                                              : "CPU and GL images are at most " + levels(worstCpuGl) +
                                                    " RMSE apart (" + worstCpuGlAt + "), so GL reads the same.";

  // 7. The 720p cost line.
  std::string cost;
  const HeightFieldCost& c = section.cost720p;
  double ratio = 0.0;
  if (c.measured && c.normalMapMs > 0.0) {
    ratio = c.pomMs / c.normalMapMs;
    cost = "Cost at 1280x720 on the CPU (" + c.cpuPath + "), " + c.scene + ": " + c.pomSetting + " takes " + ms(c.pomMs) +
           " against normal_map's " + ms(c.normalMapMs) + " (fastest of " + std::to_string(c.frames) +
           " frames each, the two timed in turn; medians " + ms(c.pomMsMedian) + " and " + ms(c.normalMapMsMedian) + "): " + times(ratio) + ", " +
           (ratio <= kPomCostTarget ? "within" : "beyond") + " the issue's " + times(kPomCostTarget) + ".";
  }

  r.detail = picks + "\n" + pomText + "\n" + stairs + "\n" + beat + "\n" + floor + "\n" + silhouettes + "\n" + gl +
             "\n" + cost;
  if (pomCompared > 0) {
    r.summary = "POM 8-32's interior error is below plain parallax's in " + std::to_string(pomLower) + " of " +
                std::to_string(pomCompared) + " views at 45\xC2\xB0 and beyond" +
                (pomMisses.empty() ? "" : " (not at " + pomMisses + ")") + ". ";
  }
  if (!pickSummary.empty()) r.summary += "Worth its cost: " + pickSummary + ". ";
  if (ratio > 0.0) r.summary += "POM at 720p costs " + times(ratio) + " a normal-mapped frame on the CPU.";
  return r;
}

}  // namespace

KnobReading readKnob(const KnobResult& knob) {
  if (!knob.skipped.empty() && knob.points.size() < 2) return {"Not measured: " + knob.skipped, knob.skipped};
  KnobReading r;
  if (knob.id == "tessellation") r = readTessellation(knob);
  else if (knob.id == "texture_filter") r = readTwo(knob, "nearest", "bilinear");
  else if (knob.id == "minification") r = readMinification(knob);
  else if (knob.id == "lighting_space") r = readTwo(knob, "tangent", "world");
  else if (knob.id == "tangent_transform") r = readTwo(knob, "inverse_transpose", "model");
  else if (knob.id == "gl_sampling") r = readTwo(knob, "fast", "precise");
  else if (knob.id == "resolution") r = readResolution(knob);
  else if (knob.id == "threads") r = readThreads(knob);
  else if (knob.id == "precision") r = readPrecision(knob);
  if (!knob.skipped.empty()) r.detail += " (Part of this knob was not measured: " + knob.skipped + ")";
  r.summary = trimmed(r.summary);
  r.detail = trimmed(r.detail);
  return r;
}

KnobReading readBases(const std::vector<BasisRow>& rows) {
  const BasisRow* duff = nullptr;
  const BasisRow* frisvad = nullptr;
  const BasisRow* fixed = nullptr;
  const BasisRow* best = nullptr;
  for (const BasisRow& r : rows) {
    if (r.method == BasisMethod::Duff2017) duff = &r;
    if (r.method == BasisMethod::Frisvad2012) frisvad = &r;
    if (r.method == BasisMethod::NaiveFixedHelper) fixed = &r;
    if (r.method == BasisMethod::NaiveBestHelper) best = &r;
  }
  if (!duff || !frisvad || !fixed || !best) return {};
  std::string s = "Duff et al. 2017 stays at " + fmt("%.1e", duff->stats.maxError) + " over every direction (" +
                  fmt("%.1f", duff->nsPerBasis) + " ns a basis). Frisvad 2012 is as good for n.z > 0 (" +
                  fmt("%.1e", frisvad->stats.maxErrorAwayFromMinusZ) + ") but reaches " +
                  fmt("%.1e", frisvad->stats.maxErrorNearMinusZ) +
                  " within 1e-3 rad of -Z, where 1 + n.z cancels in float: ";
  s += frisvad->stats.maxErrorNearMinusZ > 100.0 * duff->stats.maxError
           ? "a visible failure, for " + fmt("%.1f", frisvad->nsPerBasis) + " ns. "
           : "not a visible failure on this run. ";
  s += "The naive cross product with a fixed helper axis gives " + std::to_string(fixed->stats.nonFinite) +
       " non-finite bases (n parallel to the helper); choosing the helper per normal fixes that (" +
       fmt("%.1e", best->stats.maxError) + ") at " + fmt("%.1f", best->nsPerBasis) + " ns against Duff's " +
       fmt("%.1f", duff->nsPerBasis) + " ns. ";
  s += duff->nsPerBasis <= best->nsPerBasis ? "Duff is both the most accurate and the cheapest robust choice."
                                            : "Duff is the accurate branch-free choice; here the naive fix is faster.";
  KnobReading r;
  r.detail = s;
  r.summary = "Duff 2017 is accurate everywhere (" + fmt("%.1e", duff->stats.maxError) + ", " +
              fmt("%.1f", duff->nsPerBasis) + " ns); Frisvad 2012 reaches " +
              fmt("%.1e", frisvad->stats.maxErrorNearMinusZ) + " near -Z; a fixed helper axis gives " +
              std::to_string(fixed->stats.nonFinite) + " NaN bases.";
  return r;
}

KnobReading readParameterizations(const ParameterizationSection& section) {
  if (!section.skipped.empty()) return {"Not measured: " + section.skipped, section.skipped};
  std::vector<const ParameterizationRow*> sphere, paraboloid;
  for (const ParameterizationRow& r : section.rows) {
    (r.kind == EnvironmentParameterization::Sphere ? sphere : paraboloid).push_back(&r);
  }
  if (sphere.empty() || paraboloid.empty() || sphere.size() != paraboloid.size()) return {};
  const auto where = [](const glm::dvec3& r) {
    return r.z < -0.9 ? std::string("within 26 degrees of -Z") : r.z > 0.9 ? std::string("near +Z")
                                                                          : "at z = " + fmt("%.2f", r.z);
  };
  std::string s;
  int paraboloidWins = 0;
  for (std::size_t i = 0; i < sphere.size(); ++i) {
    if (paraboloid[i]->error.rmse < sphere[i]->error.rmse) ++paraboloidWins;
  }
  const ParameterizationRow& s0 = *sphere.front();
  const ParameterizationRow& s1 = *sphere.back();
  const ParameterizationRow& p0 = *paraboloid.front();
  const ParameterizationRow& p1 = *paraboloid.back();
  s += "From " + std::to_string(s0.size) + " to " + std::to_string(s1.size) + " texels the sphere map's RMSE falls from " +
       fmt("%.2f", s0.error.rmse) + " to " + fmt("%.2f", s1.error.rmse) + " levels and the dual paraboloid's from " +
       fmt("%.2f", p0.error.rmse) + " to " + fmt("%.2f", p1.error.rmse) + ". ";
  s += "The dual paraboloid has the lower RMSE at " + std::to_string(paraboloidWins) + " of " +
       std::to_string(sphere.size()) + " sizes. ";
  s += "The sphere map's worst direction at " + std::to_string(s1.size) + " is " + where(s1.error.worstDirection) +
       " (" + fmt("%.1f", s1.error.maxError) + " levels)" +
       (s1.error.worstDirection.z < -0.5 ? std::string(": towards its rim, where one texel spans the most directions "
                                                       "(the error picture). ")
                                         : std::string(". ")) +
       "The paraboloid's worst is " + where(p1.error.worstDirection) + " (" +
       fmt("%.1f", p1.error.maxError) + " levels), its two halves sampled within a factor of 4 in solid angle. ";
  s += "Building costs " + fmt("%.0f", s1.buildMs) + " ms (sphere) and " + fmt("%.0f", p1.buildMs) + " ms (paraboloid) at " +
       std::to_string(s1.size) + ", once at load.";
  KnobReading r;
  r.detail = s;
  r.summary = "At " + std::to_string(s1.size) + " texels: sphere map RMSE " + fmt("%.2f", s1.error.rmse) + ", worst " +
              fmt("%.1f", s1.error.maxError) + " levels " + where(s1.error.worstDirection) + "; dual paraboloid RMSE " +
              fmt("%.2f", p1.error.rmse) + ", worst " + fmt("%.1f", p1.error.maxError) + ".";
  return r;
}

KnobReading readDiffuseLight(const DiffuseLightSection& section) {
  if (!section.skipped.empty()) return {"Not measured: " + section.skipped, section.skipped};
  const DiffuseLightError& e = section.error;
  const auto normal = [](const glm::dvec3& n) {
    return "(" + fmt("%.2f", n.x) + ", " + fmt("%.2f", n.y) + ", " + fmt("%.2f", n.z) + ")";
  };
  const auto resolved = [&](const DiffuseLightComparison& c) {
    return c.rmse < 1.5 * e.referenceNoise ? std::string("within the reference's own noise")
                                            : std::string("above the reference's noise");
  };
  std::string s;
  s += "Against " + std::to_string(e.samples) + " cosine-weighted Monte Carlo samples per normal (" +
       std::to_string(e.normals) + " normals; the estimate's own noise is " + fmt("%.2f", e.referenceNoise) +
       " levels RMS), the irradiance cube is off by " + fmt("%.2f", e.mapVsReference.rmse) + " levels RMS, " +
       resolved(e.mapVsReference) + ", worst " + fmt("%.2f", e.mapVsReference.maxError) + " at " +
       normal(e.mapVsReference.worstNormal) + "; SH9 by " + fmt("%.2f", e.sh9VsReference.rmse) + " RMS, " +
       resolved(e.sh9VsReference) + ", worst " + fmt("%.2f", e.sh9VsReference.maxError) + " at " +
       normal(e.sh9VsReference.worstNormal) + ". ";
  s += "SH9 against the irradiance cube, where neither has noise: " + fmt("%.2f", e.sh9VsMap.rmse) + " levels RMS, 99 % within " +
       fmt("%.2f", e.sh9VsMap.p99) + ", worst " + fmt("%.2f", e.sh9VsMap.maxError) + " at " + normal(e.sh9VsMap.worstNormal) +
       (e.sh9VsMap.maxError > 2.0 ? std::string(": the detail of bands above 2 (a sun, a sharp horizon) that nine "
                                                 "coefficients cannot hold, or their ringing. ")
                                  : std::string(": three bands hold this sky's diffuse light. "));
  s += "Building takes " + fmt("%.0f", section.irradianceMs) + " ms (irradiance cube) and " + fmt("%.0f", section.sh9Ms) +
       " ms (SH9), once at load; a pixel then reads one bilinear texel footprint or evaluates nine terms.";
  KnobReading r;
  r.detail = s;
  r.summary = "Irradiance cube " + fmt("%.2f", e.mapVsReference.rmse) + " and SH9 " + fmt("%.2f", e.sh9VsReference.rmse) +
              " levels RMS from Monte Carlo (noise " + fmt("%.2f", e.referenceNoise) + "); SH9 from the cube: worst " +
              fmt("%.2f", e.sh9VsMap.maxError) + " levels.";
  return r;
}

KnobReading readShadows(const ShadowSection& section) {
  if (!section.skipped.empty()) return {"Not measured: " + section.skipped, section.skipped};
  if (section.rows.empty() || section.measured == 0) return {"Not measured: no pixel faces the light", "nothing measured"};
  // The cheapest setting within 0.1 % wrong pixels, and how the error falls with the side at
  // each kernel.
  const ShadowRow* cheapest = nullptr;
  const ShadowRow* best = &section.rows.front();
  for (const ShadowRow& row : section.rows) {
    if (row.wrongPercent < best->wrongPercent) best = &row;
    if (row.wrongPercent <= 0.1 && (!cheapest || row.msMedian < cheapest->msMedian)) cheapest = &row;
  }
  const auto setting = [](const ShadowRow& r) {
    return std::to_string(r.size) + "\u00b2 PCF " + std::to_string(r.pcf);
  };
  const auto ratio = [&](const ShadowRow& r) { return section.unshadowedMs > 0.0 ? r.msMedian / section.unshadowedMs : 0.0; };
  std::string summary = "Best: " + setting(*best) + ", " + fmt("%.2f", best->wrongPercent) + " % of lit-facing pixels answer "
                        "the other way than the traced shadow";
  summary += cheapest ? "; the cheapest within 0.1 %: " + setting(*cheapest) + " at " +
                            fmt("%.2f", ratio(*cheapest)) + "x the unshadowed frame."
                      : "; no setting stays within 0.1 %.";
  std::string detail = std::to_string(section.measured) + " pixels face the light, " +
                       std::to_string(section.tracedShadowed) + " of them in its traced shadow (tracing them took " +
                       fmt("%.0f", section.traceMs) + " ms, one thread). ";
  for (const int pcf : {1, 3, 5}) {
    std::string line;
    for (const ShadowRow& row : section.rows) {
      if (row.pcf != pcf) continue;
      line += (line.empty() ? "" : ", ") + std::to_string(row.size) + ": " + fmt("%.2f", row.wrongPercent) + " %";
    }
    detail += "PCF " + std::to_string(pcf) + " wrong pixels by side: " + line + ". ";
  }
  detail += "A wider kernel leaves more pixels between lit and shadowed (a soft edge the ray tracer's point light "
            "does not have), which counts as wrong only past half; a larger map moves each edge nearer the truth "
            "and costs the shadow pass its texels.";
  return {summary, detail};
}

KnobReading readSsr(const SsrSection& section) {
  if (!section.skipped.empty()) return {"Not measured: " + section.skipped, section.skipped};
  if (section.steps.empty()) return {"Not measured: no march ran", "nothing measured"};
  // linear_world's best error is the mark; each march's fewest steps within 5 % (+0.05 level) of it.
  double mark = -1.0;
  for (const SsrMarchRow& row : section.steps) {
    if (row.march == "linear_world" && (mark < 0.0 || row.meanAbs < mark)) mark = row.meanAbs;
  }
  if (mark < 0.0) return {"Not measured: linear_world did not run", "no linear_world row"};
  const double within = mark * 1.05 + 0.05;
  const auto reach = [&](const std::string& march) -> const SsrMarchRow* {
    const SsrMarchRow* found = nullptr;
    for (const SsrMarchRow& row : section.steps) {
      if (row.march == march && row.meanAbs <= within && (!found || row.maxSteps < found->maxSteps)) found = &row;
    }
    return found;
  };
  const auto reachText = [&](const std::string& march) {
    const SsrMarchRow* r = reach(march);
    return r ? march + " " + std::to_string(r->maxSteps) + " steps (" + fmt("%.1f", r->msMedian) + " ms a frame)"
             : march + " not within the steps tried";
  };
  const SsrMarchRow* linear = reach("linear_world");
  const SsrMarchRow* hiz = reach("hiz");
  std::string summary = "Against the ray tracer, linear_world's best error is " + fmt("%.2f", mark) + " levels; ";
  if (hiz && linear) {
    summary += "hiz reaches it in " + std::to_string(hiz->maxSteps) + " steps (" + fmt("%.1f", hiz->msMedian) +
               " ms a frame) where linear_world needs " + std::to_string(linear->maxSteps) + " (" +
               fmt("%.1f", linear->msMedian) + " ms)";
  } else {
    summary += reachText("hiz");
  }
  summary += ". " + fmt("%.0f", 100.0 * section.blindErrorShare) +
             " % of the best march's error sits on surfaces off the screen or hidden, which no screen-space march "
             "can see.";
  std::string detail = std::to_string(section.reflecting) + " pixels reflect; " + std::to_string(section.blindRays) +
                       " of their mirror rays meet a surface off the screen or hidden (the reference traced them in " +
                       fmt("%.0f", section.traceMs) + " ms). Steps to come within 5 % of linear_world's best: " +
                       reachText("linear_world") + ", " + reachText("adaptive_world") + ", " + reachText("dda_screen") +
                       ", " + reachText("hiz") + ". Mean error by steps: ";
  std::string march;
  for (const SsrMarchRow& row : section.steps) {
    if (row.march != march) {
      detail += (march.empty() ? "" : "; ") + row.march + " ";
      march = row.march;
    } else {
      detail += ", ";
    }
    detail += std::to_string(row.maxSteps) + ": " + fmt("%.2f", row.meanAbs);
  }
  detail += ". ";
  if (!section.thickness.empty()) {
    const SsrMarchRow* leak = &section.thickness.front();
    const SsrMarchRow* lost = &section.thickness.front();
    for (const SsrMarchRow& row : section.thickness) {
      if (row.falseHits > leak->falseHits) leak = &row;
      if (row.missedVisible > lost->missedVisible) lost = &row;
    }
    detail += "The thickness threshold leaks where it is thick: " + leak->march + " at " + fmt("%.2f", leak->thickness) +
              " lights " + std::to_string(leak->falseHits) +
              " pixels whose mirror ray meets nothing (more than 3 levels off), and loses where it is thin: " +
              lost->march + " at " + fmt("%.2f", lost->thickness) + " leaves " + std::to_string(lost->missedVisible) +
              " pixels that should show a visible surface more than 3 levels off. ";
  }
  if (section.samples.size() >= 2) {
    const SsrSamplesRow& first = section.samples.front();
    const SsrSamplesRow& last = section.samples.back();
    detail += "Indirect light against " + std::to_string(section.referenceSamples) +
              " traced rays per pixel: " + fmt("%.2f", first.meanAbs) + " levels at " + std::to_string(first.samples) +
              " sample" + (first.samples == 1 ? "" : "s") + " (" + fmt("%.1f", first.msMedian) + " ms), " +
              fmt("%.2f", last.meanAbs) + " at " + std::to_string(last.samples) + " (" + fmt("%.1f", last.msMedian) +
              " ms); ";
    const double ratio = first.meanAbs > 0.0 && last.samples > first.samples
                             ? std::pow(last.meanAbs / first.meanAbs,
                                        1.0 / std::log2(static_cast<double>(last.samples) / first.samples))
                             : 0.0;
    detail += "each doubling of the samples scales the error by " + fmt("%.2f", ratio) +
              " (pure noise: 1/sqrt(2) = 0.71). Against the same rays traced, the march alone is " +
              fmt("%.2f", last.marchMeanAbs) + " levels off at " + std::to_string(last.samples) + " samples.";
  }
  return {summary, detail};
}

KnobReading readGlossy(const GlossySection& section) {
  if (!section.skipped.empty()) return {"Not measured: " + section.skipped, section.skipped};
  const GlossyError& e = section.error;
  if (e.rows.empty()) return {"Not measured: no shininess", "no shininess was measured"};
  // On a level: the shininess is a level's own lobe (an integer LOD); between: a blend of two;
  // sharper than level 0's lobe: level 0 read for it (clamped).
  double worstOn = 0.0, worstBetween = 0.0, worstMirrorRatio = 0.0, worstClamped = 0.0;
  const GlossyRow* worstBetweenRow = nullptr;
  const GlossyRow* sharpest = nullptr;
  const GlossyRow* widest = &e.rows.back();
  for (const GlossyRow& row : e.rows) {
    if (row.prefiltered.rmse > 0.0) worstMirrorRatio = std::max(worstMirrorRatio, row.mirror.rmse / row.prefiltered.rmse);
    if (row.shininess > section.levelZeroExponent) {
      worstClamped = std::max(worstClamped, row.prefiltered.rmse);
      continue;
    }
    if (!sharpest) sharpest = &row;
    const bool onLevel = row.lod == std::floor(row.lod);
    double& worst = onLevel ? worstOn : worstBetween;
    if (row.prefiltered.rmse > worst) {
      worst = row.prefiltered.rmse;
      if (!onLevel) worstBetweenRow = &row;
    }
  }
  if (!sharpest) return {"Not measured: no shininess within the chain", "every shininess was sharper than level 0"};
  const auto noiseWord = [](const GlossyRow& row) {
    return row.prefiltered.rmse < 1.5 * row.referenceNoise ? std::string(" (within the reference's noise)")
                                                            : std::string("");
  };
  std::string s;
  s += "The prefiltered cube (" + std::to_string(section.cubeSize) + " texels, " + std::to_string(section.levels) +
       " levels, a Phong lobe per level) read at each shininess's LOD, against " + std::to_string(e.samples) +
       " Monte Carlo samples of that lobe per direction over " + std::to_string(e.directions) + " directions. ";
  s += "At shininess " + fmt("%.0f", sharpest->shininess) + " (level 0) it is off by " +
       fmt("%.2f", sharpest->prefiltered.rmse) + " levels RMS" + noiseWord(*sharpest) + ", worst " +
       fmt("%.1f", sharpest->prefiltered.maxError) + "; at " + fmt("%.0f", widest->shininess) + " (LOD " +
       fmt("%.1f", widest->lod) + ") by " + fmt("%.2f", widest->prefiltered.rmse) + noiseWord(*widest) + ". ";
  s += "Where the shininess is a level's own lobe the worst RMSE is " + fmt("%.2f", worstOn) + " levels; between two " +
       "levels, where textureLod blends two lobes instead of convolving with the one asked for, it is " +
       fmt("%.2f", worstBetween);
  if (worstBetweenRow) {
    s += " (shininess " + fmt("%.0f", worstBetweenRow->shininess) + ", LOD " + fmt("%.1f", worstBetweenRow->lod) + ")";
  }
  s += worstBetween > 1.5 * worstOn ? ": the blend, not the convolution, is the larger error. "
                                    : ": the blend costs little next to the convolution's own error. ";
  if (worstClamped > 0.0) {
    s += "A shininess sharper than level 0's lobe (e = " + fmt("%.0f", section.levelZeroExponent) +
         ") reads level 0 all the same: up to " + fmt("%.2f", worstClamped) +
         " levels RMS off the lobe asked for; for sharper reflections, environment_specular mirror reads the sky "
         "itself. ";
  }
  s += "Reading the unfiltered sky in the mirror direction instead is up to " + fmt("%.0f", worstMirrorRatio) +
       " times further from the lobe's average: that is what prefiltering buys. Building the cube takes " +
       fmt("%.0f", section.buildMs) + " ms once at load; a pixel then reads two bilinear footprints.";
  KnobReading r;
  r.detail = s;
  r.summary = "Prefiltered: " + fmt("%.2f", worstOn) + " levels RMS at worst on a level's own lobe, " +
              fmt("%.2f", worstBetween) + " between levels; the mirror read instead is up to " +
              fmt("%.0f", worstMirrorRatio) + "x further off.";
  return r;
}

KnobReading readHeightFields(const HeightFieldSection& section) {
  if (!section.measured) return {"Not measured: " + section.skipped, section.skipped};
  KnobReading r = readHeightFieldSection(section);
  if (!section.skipped.empty()) r.detail += "\n(Part of this section was not measured: " + section.skipped + ")";
  r.summary = trimmed(r.summary);
  return r;
}

}  // namespace twr::report
