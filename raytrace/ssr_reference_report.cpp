#include "raytrace/ssr_reference_report.h"

#include "compare/colours.h"
#include "compare/draw.h"
#include "compare/montage.h"
#include "compare/side_by_side.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace twr {

namespace {

nlohmann::json rowToJson(const SsrErrorRow& row, double totalError) {
  return {{"pixels", row.pixels},
          {"mean_abs_diff", row.meanAbs},
          {"max_abs_diff", row.maxAbs},
          {"over_3", row.over3},
          {"error_share", totalError > 0.0 ? row.sumAbs / totalError : 0.0}};
}

nlohmann::json raysToJson(const std::array<std::uint64_t, kSsrTruthCount>& counts) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t t = 1; t < kSsrTruthCount; ++t) j[toString(static_cast<SsrTruth>(t))] = counts[t];
  return j;
}

Image imageOf(const std::vector<std::uint8_t>& rgba, int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba = rgba;
  return image;
}

}  // namespace

nlohmann::json ssrReferenceToJson(const SsrReference& reference, const std::vector<SsrReferenceSide>& sides) {
  nlohmann::json j = {{"kind", "raytrace"},
                      {"tracer", rayTracerDescription()},
                      {"trace_ms", reference.milliseconds},
                      {"indirect_samples", reference.indirectSamples},
                      {"rays", {{"mirror", raysToJson(reference.mirrorRays)}, {"indirect", raysToJson(reference.indirectRays)}}}};
  for (const SsrReferenceSide& side : sides) {
    const SsrReferenceError& e = side.error;
    nlohmann::json classes = nlohmann::json::object();
    for (std::size_t c = 0; c < kSsrErrorClassCount; ++c) {
      classes[toString(static_cast<SsrErrorClass>(c))] = rowToJson(e.byClass[c], e.all.sumAbs);
    }
    j[side.name] = {{"pixels", e.all.pixels},
                    {"mean_abs_diff", e.all.meanAbs},
                    {"max_abs_diff", e.all.maxAbs},
                    {"over_3", e.all.over3},
                    {"classes", classes}};
  }
  return j;
}

Image ssrReferenceMontage(const SsrReference& reference, const std::vector<SsrReferenceSide>& sides) {
  const int w = reference.frame.width, h = reference.frame.height;
  // Two rows: the reference and each side's frame; the classes and each side's difference.
  std::vector<MontageTile> tiles;
  tiles.push_back({"ray-traced reference", rawImage(reference.frame)});
  for (const SsrReferenceSide& side : sides) tiles.push_back({side.name + " SSR", rawImage(*side.frame)});
  tiles.push_back({"error classes", imageOf(ssrTruthImage(reference), w, h)});
  const HeatRamp ramp;
  for (const SsrReferenceSide& side : sides) {
    Image heat = makeImage(w, h, 0x000000FFu);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        setPixel(heat, x, y, heatColour(side.error.pixelError[i], ramp));
      }
    }
    tiles.push_back({"|" + side.name + " - reference|", std::move(heat)});
  }
  MontageOptions options;
  options.columns = static_cast<int>(sides.size()) + 1;
  const Image grid = makeMontage(tiles, options);

  // The legend: a swatch and name per class, then the heat ramp's marks.
  const int scale = std::max(1, std::min(2, grid.width / 480));
  const int line = kFontLineHeightUnits * scale, pad = 4 * scale;
  Image out = makeImage(grid.width, grid.height + 2 * line + 3 * pad, 0x181818FFu);
  std::copy(grid.rgba.begin(), grid.rgba.end(), out.rgba.begin());
  int x = pad, y = grid.height + pad;
  for (std::size_t c = 0; c < kSsrErrorClassCount; ++c) {
    const auto colour = ssrErrorClassColour(static_cast<SsrErrorClass>(c));
    const std::string name = toString(static_cast<SsrErrorClass>(c));
    if (x + line + textWidth(name, scale) + pad > out.width) {
      x = pad;
      y += line;
    }
    fillRect(out, x, y, x + line - 2, y + line - 2, Rgb8{colour[0], colour[1], colour[2]});
    drawText(out, x + line + 2, y, name, kColourWhite, scale);
    x += line + 2 + textWidth(name, scale) + 3 * pad;
  }
  x = pad;
  y = std::min(y + line + pad, out.height - line);
  drawText(out, x, y, "difference, levels:", kColourWhite, scale);
  x += textWidth("difference, levels:", scale) + pad;
  for (const int levels : {0, 1, 3, 12, 48, 255}) {
    if (x + line + textWidth("255", scale) + 2 * pad > out.width) break;
    fillRect(out, x, y, x + line - 2, y + line - 2, heatColour(levels, ramp));
    drawText(out, x + line + 2, y, std::to_string(levels), kColourWhite, scale);
    x += line + 2 + textWidth(std::to_string(levels), scale) + 2 * pad;
  }
  return out;
}

}  // namespace twr
