#include "compare/metrics.h"

#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace twr {
namespace {

constexpr int kRgbaChannels = 4;
constexpr int kColourChannels = 3;  // RGB; alpha (the background's where nothing is drawn) is never diffed
constexpr int kOver1Levels = 1, kOver3Levels = 3, kOver12Levels = 12;  // exclusive bounds
constexpr double kPercent = 100.0;
constexpr double kPerTenThousand = 10000.0;
constexpr double kAmplitudeDecibels = 20.0;  // dB per decade of an amplitude ratio (PSNR)

std::string sizeText(const RenderOutput& output) {
  return std::to_string(output.width) + "x" + std::to_string(output.height);
}

// `what` names the buffer ("CPU depth"); optional buffers may be empty.
void checkLength(const std::string& context, std::size_t actual, std::size_t expected, bool mayBeEmpty,
                 const std::string& what) {
  if (actual == expected || (mayBeEmpty && actual == 0)) return;
  throw InputError(context + ": " + what + " buffer has " + std::to_string(actual) + " entries, expected " +
                   (mayBeEmpty ? "0 or " : "") + std::to_string(expected));
}

void validate(const RenderOutput& cpu, const RenderOutput& gl, const CompareOptions& options) {
  if (options.differMinLevels < 0 || options.differMinLevels > int(kMaxChannelLevel)) {
    throw InputError("compare: differ threshold is " + std::to_string(options.differMinLevels) +
                     " levels, expected an integer in [0, 255]");
  }
  if (!std::isfinite(options.depthTolerance) || options.depthTolerance < 0.0) {
    throw InputError("compare: depth tolerance is " + std::to_string(options.depthTolerance) +
                     ", expected a finite window-depth difference >= 0");
  }
  if (cpu.width != gl.width || cpu.height != gl.height) {
    throw InputError("compare: CPU output is " + sizeText(cpu) + " but GL output is " + sizeText(gl) +
                     ", expected the same size");
  }
  if (cpu.width <= 0 || cpu.height <= 0 || cpu.width > kMaxImageSide || cpu.height > kMaxImageSide) {
    throw InputError("compare: output is " + sizeText(cpu) + ", expected each side in [1, " +
                     std::to_string(kMaxImageSide) + "]");
  }
  const std::size_t pixelCount = static_cast<std::size_t>(cpu.width) * cpu.height;
  checkOutputBuffers("compare", cpu, "CPU", pixelCount);
  checkOutputBuffers("compare", gl, "GL", pixelCount);
}

}  // namespace

void checkOutputBuffers(const std::string& context, const RenderOutput& out, const std::string& name,
                        std::size_t pixelCount) {
  checkLength(context, out.rgba.size(), pixelCount * kRgbaChannels, false, name + " rgba");
  checkLength(context, out.depth.size(), pixelCount, true, name + " depth");
  checkLength(context, out.triangleId.size(), pixelCount, true, name + " triangleId");
  checkLength(context, out.lineMask.size(), pixelCount, true, name + " lineMask");
}

double CompareMetrics::over1Pct() const {
  return bothCovered == 0 ? 0.0 : kPercent * static_cast<double>(over1) / static_cast<double>(bothCovered);
}

double CompareMetrics::excludedLinePct() const {
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  return pixels == 0.0 ? 0.0 : kPercent * static_cast<double>(excludedLinePixels) / pixels;
}

double CompareMetrics::lineMismatchPct() const {
  return excludedLinePixels == 0 ? 0.0
                                 : kPercent * static_cast<double>(lineMismatch) / static_cast<double>(excludedLinePixels);
}

double CompareMetrics::backgroundOver1Pct() const {
  return backgroundCompared == 0 ? 0.0
                                 : kPercent * static_cast<double>(backgroundOver1) / static_cast<double>(backgroundCompared);
}

double CompareMetrics::coverageMismatchPer10k() const {
  const std::uint64_t either = coveredEither();
  return either == 0 ? 0.0 : kPerTenThousand * static_cast<double>(coverageMismatch) / static_cast<double>(either);
}

CompareResult compareDetailed(const RenderOutput& cpu, const RenderOutput& gl, const CompareOptions& options) {
  validate(cpu, gl, options);
  CompareResult result;
  CompareMetrics& m = result.metrics;
  PixelAnalysis& pixels = result.pixels;
  m.width = pixels.width = cpu.width;
  m.height = pixels.height = cpu.height;
  m.options = options;
  m.depthAvailable = !cpu.depth.empty() && !gl.depth.empty();
  m.triangleIdsAvailable = !cpu.triangleId.empty() && !gl.triangleId.empty();

  const std::size_t pixelCount = static_cast<std::size_t>(cpu.width) * cpu.height;
  pixels.diffLevels.assign(pixelCount, 0);
  pixels.pixelClass.assign(pixelCount, PixelClass::Empty);

  std::uint64_t sumAbs = 0;      // levels, over bothCovered x RGB
  std::uint64_t sumSquares = 0;  // levels^2, same population
  for (std::size_t i = 0; i < pixelCount; ++i) {
    const bool cpuDepthFinite = cpu.depth.empty() || std::isfinite(cpu.depth[i]);
    if (!cpuDepthFinite) ++m.nanPixels;  // counted everywhere, lines included: never acceptable

    const bool cpuLine = lineAt(cpu, i), glLine = lineAt(gl, i);
    m.linePixelsCpu += cpuLine;
    m.linePixelsGl += glLine;
    m.lineMismatch += cpuLine != glLine;
    if (cpuLine || glLine) {
      ++m.excludedLinePixels;
      pixels.pixelClass[i] = PixelClass::ExcludedLine;
      continue;
    }
    ++m.comparedPixels;
    const std::uint8_t* cpuPixel = &cpu.rgba[i * kRgbaChannels];
    const std::uint8_t* glPixel = &gl.rgba[i * kRgbaChannels];
    const bool cpuCovered = coveredAt(cpu, i);
    const bool glCovered = coveredAt(gl, i);
    m.coveredCpu += cpuCovered;
    m.coveredGl += glCovered;
    const bool background = !cpuCovered && !glCovered;
    if (background && !options.compareBackground) continue;  // PixelClass::Empty
    if (cpuCovered != glCovered) {
      pixels.pixelClass[i] = cpuCovered ? PixelClass::CoverageCpu : PixelClass::CoverageGl;
      ++(cpuCovered ? m.coverageCpuOnly : m.coverageGlOnly);
      continue;
    }

    int diff = 0;
    for (int c = 0; c < kColourChannels; ++c) diff = std::max(diff, std::abs(int(cpuPixel[c]) - int(glPixel[c])));
    pixels.diffLevels[i] = static_cast<std::uint8_t>(diff);
    if (background) {
      // The sky box: metrics of its own, the class same or shading (the same "surface").
      ++m.backgroundCompared;
      m.backgroundMaxAbsDiff = std::max(m.backgroundMaxAbsDiff, diff);
      m.backgroundOver1 += diff > kOver1Levels;
      const bool differs = diff > options.differMinLevels;
      pixels.pixelClass[i] = differs ? PixelClass::Shading : PixelClass::Same;
      m.classShading += differs;
      continue;
    }
    ++m.bothCovered;
    for (int c = 0; c < kColourChannels; ++c) {
      const int channelDiff = std::abs(int(cpuPixel[c]) - int(glPixel[c]));
      sumAbs += static_cast<std::uint64_t>(channelDiff);
      sumSquares += static_cast<std::uint64_t>(channelDiff * channelDiff);
    }
    if (diff > m.maxAbsDiff) {  // strict: the first pixel in row-major order keeps the spot
      m.maxAbsDiff = diff;
      m.maxAbsDiffX = static_cast<int>(i % static_cast<std::size_t>(cpu.width));
      m.maxAbsDiffY = static_cast<int>(i / static_cast<std::size_t>(cpu.width));
    }
    m.over1 += diff > kOver1Levels;
    m.over3 += diff > kOver3Levels;
    m.over12 += diff > kOver12Levels;

    const bool depthsFinite = m.depthAvailable && cpuDepthFinite && std::isfinite(gl.depth[i]);
    const double depthDiff = depthsFinite ? std::abs(double(cpu.depth[i]) - double(gl.depth[i])) : 0.0;
    m.depthMaxDiff = std::max(m.depthMaxDiff, depthDiff);

    if (diff <= options.differMinLevels) {
      pixels.pixelClass[i] = PixelClass::Same;
      continue;
    }
    // Triangle ids decide when both sides wrote one; else depth; with neither we cannot tell
    // a different surface from a different colour, and call it shading.
    bool differentSurface = false;
    if (m.triangleIdsAvailable && cpu.triangleId[i] != kNoTriangle && gl.triangleId[i] != kNoTriangle) {
      differentSurface = cpu.triangleId[i] != gl.triangleId[i];
    } else if (depthsFinite) {
      differentSurface = depthDiff > options.depthTolerance;
    }
    pixels.pixelClass[i] = differentSurface ? PixelClass::Depth : PixelClass::Shading;
    ++(differentSurface ? m.classDepth : m.classShading);
  }

  m.coverageMismatch = m.coverageCpuOnly + m.coverageGlOnly;
  m.classCoverage = m.coverageMismatch;
  if (m.bothCovered > 0) {
    const double samples = static_cast<double>(m.bothCovered) * kColourChannels;
    m.meanAbsDiff = static_cast<double>(sumAbs) / samples;
    m.rmse = std::sqrt(static_cast<double>(sumSquares) / samples);
  }
  m.psnr = m.rmse > 0.0 ? std::min(kPsnrCapDb, kAmplitudeDecibels * std::log10(kMaxChannelLevel / m.rmse)) : kPsnrCapDb;
  return result;
}

CompareMetrics compare(const RenderOutput& cpu, const RenderOutput& gl, const CompareOptions& options) {
  return compareDetailed(cpu, gl, options).metrics;
}

std::string_view toString(PixelClass pixelClass) {
  switch (pixelClass) {
    case PixelClass::Empty: return "empty";
    case PixelClass::Same: return "same";
    case PixelClass::CoverageCpu: return "coverage_cpu";
    case PixelClass::CoverageGl: return "coverage_gl";
    case PixelClass::Depth: return "depth";
    case PixelClass::Shading: return "shading";
    case PixelClass::ExcludedLine: return "excluded_line";
    case PixelClass::Decision: return "decision";
  }
  return "unknown";
}

}  // namespace twr
