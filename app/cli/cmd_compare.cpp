// `twinraster compare SCENE --out-dir DIR`: render with both backends at the same size,
// measure the per-pixel difference, write the images and metrics.json, and optionally fail
// (exit 1) over thresholds.
#include "app/cli/commands.h"
#include "scene/json_text.h"
#include "app/cli/common.h"
#include "compare/artifacts.h"
#include "compare/capture_faces.h"
#include "compare/compare_page.h"
#include "compare/decisions.h"
#include "compare/empty_frame.h"
#include "compare/heatmap.h"
#include "compare/metrics.h"
#include "compare/pass_buffers.h"
#include "compare/side_by_side.h"
#include "compare/report_json.h"
#include "compare/thresholds.h"
#include "glrender/gl_renderer.h"
#include "raytrace/ssr_reference_report.h"
#include "scene/errors.h"
#include "scene/statistics.h"
#include "scene/sky_view.h"
#include "softrender/cpu_renderer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace twr::cli {
namespace {

struct CompareArgs {
  RenderRequest request;
  CpuRequest cpu;
  GlRequest gl;
  std::string outDir;
  bool json = false;
  bool html = false;  // --html: DIR/index.html beside the images
  int repeat = 3;
  bool glFastSampling = false;
  bool issueTargets = false;
  Thresholds limits;
  std::string buffer;       // --buffer NAME: that pass buffer's row and images
  bool allBuffers = false;  // --all-buffers: every buffer's row
  std::string reference;      // --reference raytrace: both frames against the ray tracer
  int referenceSamples = -1;  // --reference-samples: its indirect rays per pixel (-1: the frame's)
};

// --reference raytrace's checks, before anything is rendered.
void checkReferenceRequest(const CompareArgs& args, const Scene& scene) {
  if (args.reference.empty()) {
    if (args.referenceSamples >= 0) {
      std::cerr << "twinraster: warning: --reference-samples read and ignored: no --reference asked for\n";
    }
    return;
  }
  if (!rayTracerAvailable()) throw InputError("--reference raytrace: " + rayTracerDescription());
  if (!scene.settings.ssr.enabled) {
    throw InputError("--reference raytrace measures screen-space reflections, and settings.ssr.enabled is false in " +
                     args.request.scenePath + " (--ssr on turns them on)");
  }
  if (scene.settings.view != View::Shaded) {
    throw InputError("--reference raytrace measures the shaded frame, and the view is '" +
                     std::string(toString(scene.settings.view)) + "'");
  }
}

void printReferenceSummary(const SsrReference& ref, const std::vector<SsrReferenceSide>& sides, const std::string& path) {
  std::cout << std::setprecision(1) << "reference: ray traced (" << rayTracerDescription() << "), " << ref.milliseconds
            << " ms, " << ref.indirectSamples << " indirect rays per pixel\n";
  const auto rays = [](const char* what, const std::array<std::uint64_t, kSsrTruthCount>& counts) {
    std::cout << "  " << what << " rays:";
    for (std::size_t t = 1; t < kSsrTruthCount; ++t) {
      std::cout << (t > 1 ? "," : "") << " " << toString(static_cast<SsrTruth>(t)) << " " << counts[t];
    }
    std::cout << "\n";
  };
  rays("mirror", ref.mirrorRays);
  if (ref.indirectSamples > 0) rays("indirect", ref.indirectRays);
  for (const SsrReferenceSide& side : sides) {
    const SsrReferenceError& e = side.error;
    std::cout << std::setprecision(2) << "  " << std::left << std::setw(3) << side.name << std::right
              << " vs reference: mean " << e.all.meanAbs << " levels over " << e.all.pixels
              << " reflecting pixels, max " << e.all.maxAbs << ", over 3: " << e.all.over3 << "\n      by class (mean, share of the error):";
    for (std::size_t c = 0; c < kSsrErrorClassCount; ++c) {
      const SsrErrorRow& row = e.byClass[c];
      if (row.pixels == 0) continue;
      std::cout << " " << toString(static_cast<SsrErrorClass>(c)) << " " << row.meanAbs << " ("
                << std::setprecision(0) << (e.all.sumAbs > 0.0 ? 100.0 * row.sumAbs / e.all.sumAbs : 0.0) << "%)"
                << std::setprecision(2);
    }
    std::cout << "\n";
  }
  std::cout << "wrote " << path << "\n";
}

// Renders `repeat` times and keeps the last output; returns the median wall time in ms.
double renderTimed(Renderer& renderer, const Scene& scene, int width, int height, int repeat, RenderOutput& out) {
  std::vector<double> ms;
  for (int i = 0; i < repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    out = renderer.render(scene, scene.settings, width, height);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return medianOf(ms);
}

void printSummary(const CompareMetrics& m, const nlohmann::json& json, const ArtifactPaths& paths) {
  std::cout << std::fixed << std::setprecision(3);
  std::cout << "compared " << m.width << "x" << m.height << ": covered cpu " << m.coveredCpu << ", gl " << m.coveredGl
            << ", coverage mismatch " << m.coverageMismatch << "\n";
  std::cout << "  max abs diff " << m.maxAbsDiff << " levels";
  if (m.maxAbsDiff > 0) std::cout << " at (" << m.maxAbsDiffX << ", " << m.maxAbsDiffY << ")";
  std::cout << ", mean " << m.meanAbsDiff << ", rmse " << m.rmse << ", psnr " << m.psnr << " dB\n";
  std::cout << "  pixels over 1 / 3 / 12 levels: " << m.over1 << " / " << m.over3 << " / " << m.over12 << "\n";
  if (m.backgroundCompared > 0) {
    std::cout << "  sky box: " << m.backgroundCompared << " pixels compared, max abs diff " << m.backgroundMaxAbsDiff
              << " levels, " << m.backgroundOver1 << " over 1 level\n";
  }
  std::cout << "  differing pixels by cause: coverage " << m.classCoverage << ", depth " << m.classDepth
            << ", shading " << m.classShading << ", decision " << m.classDecision << "; excluded line pixels "
            << m.excludedLinePixels << "\n";
  if (m.excludedLinePixels > 0) {
    std::cout << "  debug lines: " << m.excludedLinePixels << " pixels (" << std::setprecision(2) << m.excludedLinePct()
              << "% of the frame), cpu " << m.linePixelsCpu << ", gl " << m.linePixelsGl << ", drawn by one only "
              << m.lineMismatch << " (" << m.lineMismatchPct() << "%)\n" << std::setprecision(3);
  }
  std::cout << "  depth max diff " << std::setprecision(6) << m.depthMaxDiff << ", NaN pixels " << m.nanPixels
            << "\n";
  std::cout << std::setprecision(2) << "  time: cpu " << json.value("cpu_ms", 0.0) << " ms ("
            << json.value("cpu_path", std::string()) << "), gl "
            << json.value("gl_ms", 0.0) << " ms (median of " << json.value("repeat", 0) << ")\n";
  std::cout << "  gl: " << json.value("gl_renderer", std::string()) << ", " << json.value("gl_version", std::string())
            << ", texture sampling " << json.value("gl_sampling", std::string()) << "\n";
  std::cout << "  gl context: " << json.value("gl_context", std::string()) << "\n";
  std::cout << "wrote " << paths.sideBySide << "\n      " << paths.diff << "\n      " << paths.classes << "\n      "
            << paths.cpu << "\n      " << paths.gl << "\n      " << paths.metrics << "\n";
}

void printCaptureSummary(const CapturedFacesComparison& faces, const RenderOutput& cpu, const RenderOutput& gl,
                         const CaptureArtifactPaths& paths) {
  std::cout << std::setprecision(2) << "captured environment, " << cpu.capturedFaces->faces[0].width << "x"
            << cpu.capturedFaces->faces[0].width << " per face: cpu " << cpu.stats.captureMilliseconds << " ms, gl "
            << gl.stats.captureMilliseconds << " ms of the frame times above\n";
  for (std::size_t f = 0; f < faces.faces.size(); ++f) {
    const CompareMetrics& m = faces.faces[f].metrics;
    std::cout << "  face " << kCubeFaceNames[f] << ": max abs diff " << m.maxAbsDiff << " levels, over 1 level "
              << m.over1 << " pixels, coverage mismatch " << m.coverageMismatch << "\n";
  }
  std::cout << "wrote " << paths.cpu << "\n      " << paths.gl << "\n      " << paths.diff << "\n";
}

// The window depth of a frame, rows bottom first, 1 wherever the two frames do not both have a
// triangle (a coverage difference is the frame's own metric, not the depth buffer's).
std::vector<float> bothCoveredDepth(const RenderOutput& out, const RenderOutput& other) {
  std::vector<float> depth(out.depth.size(), 1.0f);
  if (out.depth.size() != static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height)) return depth;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x);
      if (!coveredAt(out, i) || !coveredAt(other, i)) continue;
      depth[static_cast<std::size_t>(out.height - 1 - y) * static_cast<std::size_t>(out.width) +
            static_cast<std::size_t>(x)] = out.depth[i];
    }
  }
  return depth;
}

// Writes DIR/buffer_<stem>_cpu.png, _gl.png, _diff.png for a depth buffer.
void writeDepthImages(const std::string& dir, const std::string& stem, const std::vector<float>& cpu,
                      const std::vector<float>& gl, int width, int height, int layers) {
  savePng(dir + "/buffer_" + stem + "_cpu.png", depthLayersImage(cpu, width, height, layers));
  savePng(dir + "/buffer_" + stem + "_gl.png", depthLayersImage(gl, width, height, layers));
  savePng(dir + "/buffer_" + stem + "_diff.png", depthDiffImage(cpu, gl, width, height, layers, kDefaultDepthTolerance));
}

// The rows of `buffers` (pass order), rendering the G-buffer views both ways where asked.
std::vector<BufferRow> compareBuffers(const std::vector<PassBuffer>& buffers, const Scene& scene, int width, int height,
                                      Renderer& cpu, Renderer& gl, const RenderOutput& cpuOut,
                                      const RenderOutput& glOut, const CompareResult& frame, const Thresholds& targets,
                                      const std::string& dir) {
  std::vector<BufferRow> rows;
  for (const PassBuffer buffer : buffers) {
    const std::string name(toString(buffer));
    if (buffer == PassBuffer::ShadowMap) {
      bool any = false;
      for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const auto* a = i < cpuOut.shadowMaps.size() ? cpuOut.shadowMaps[i].get() : nullptr;
        const auto* b = i < glOut.shadowMaps.size() ? glOut.shadowMaps[i].get() : nullptr;
        if (!scene.lights[i].shadow) continue;
        any = true;
        BufferRow row;
        row.buffer = buffer;
        row.light = static_cast<int>(i);
        row.depth = true;
        if (!a || !b || a->depth.empty() || b->depth.empty()) {
          row.note = "a renderer drew no map for this light";
          rows.push_back(row);
          continue;
        }
        const ShadowProjection& p = a->projection;
        row.available = true;
        row.depthMetrics = compareDepthBuffers(a->depth, b->depth, p.size, p.size, p.layers, kDefaultDepthTolerance);
        row.passes = row.depthMetrics.overTolerance == 0 && row.depthMetrics.nonFinite == 0;
        writeDepthImages(dir, name + "_light" + std::to_string(i), a->depth, b->depth, p.size, p.size, p.layers);
        rows.push_back(row);
      }
      if (!any) {
        BufferRow row;
        row.buffer = buffer;
        row.depth = true;
        row.note = "no light of the scene has a \"shadow\"";
        rows.push_back(row);
      }
      continue;
    }
    BufferRow row;
    row.buffer = buffer;
    row.available = true;
    if (buffer == PassBuffer::GbufferDepth) {
      row.depth = true;
      const std::vector<float> a = bothCoveredDepth(cpuOut, glOut), b = bothCoveredDepth(glOut, cpuOut);
      row.depthMetrics = compareDepthBuffers(a, b, width, height, 1, kDefaultDepthTolerance);
      row.passes = row.depthMetrics.overTolerance == 0 && row.depthMetrics.nonFinite == 0;
      writeDepthImages(dir, name, a, b, width, height, 1);
      rows.push_back(row);
      continue;
    }
    if (cpuOut.gbuffer && glOut.gbuffer && gbufferTargetOf(*cpuOut.gbuffer, buffer)) {
      // A deferred frame's G-buffer target, channel by channel (x, y, z side by side).
      const std::vector<vec4>& ta = *gbufferTargetOf(*cpuOut.gbuffer, buffer);
      const std::vector<vec4>& tb = *gbufferTargetOf(*glOut.gbuffer, buffer);
      const std::vector<float> a = gbufferPlanes(ta, width, height), b = gbufferPlanes(tb, width, height);
      row.depth = true;
      row.floats = true;
      row.depthMetrics = compareDepthBuffers(a, b, width, height, 3, kGBufferTolerance);
      row.passes = row.depthMetrics.overTolerance == 0 && row.depthMetrics.nonFinite == 0;
      savePng(dir + "/buffer_" + name + "_cpu.png", gbufferImage(ta, width, height, buffer));
      savePng(dir + "/buffer_" + name + "_gl.png", gbufferImage(tb, width, height, buffer));
      savePng(dir + "/buffer_" + name + "_diff.png", depthDiffImage(a, b, width, height, 3, kGBufferTolerance));
      rows.push_back(row);
      continue;
    }
    if (buffer == PassBuffer::GbufferSpecular || buffer == PassBuffer::GbufferEmission ||
        buffer == PassBuffer::GbufferPosition) {
      row.available = false;
      row.depth = true;
      row.note = cpuOut.gbuffer && glOut.gbuffer
                     ? "settings.gbuffer_position depth: the frame rebuilds each position from the depth"
                     : "a forward frame has no G-buffer; settings.pipeline deferred writes one";
      rows.push_back(row);
      continue;
    }
    CompareOptions options;
    options.compareBackground = buffer == PassBuffer::Final && drawsSky(scene, scene.settings);
    // The frame itself, or the scene drawn again in the buffer's view.
    const RenderOutput* a = &cpuOut;
    const RenderOutput* b = &glOut;
    RenderOutput viewCpu, viewGl;
    if (buffer == PassBuffer::GbufferNormal || buffer == PassBuffer::GbufferAlbedo) {
      RenderSettings settings = scene.settings;
      settings.view = viewOfBuffer(buffer, settings.view);
      settings.tbnLines.enabled = false;
      viewCpu = cpu.render(scene, settings, width, height);
      viewGl = gl.render(scene, settings, width, height);
      a = &viewCpu;
      b = &viewGl;
    }
    const CompareResult result = buffer == PassBuffer::Final ? frame : compareDetailed(*a, *b, options);
    row.colourMetrics = result.metrics;
    row.passes = checkThresholds(result.metrics, targets).empty();
    savePng(dir + "/buffer_" + name + "_cpu.png", rawImage(*a));
    savePng(dir + "/buffer_" + name + "_gl.png", rawImage(*b));
    savePng(dir + "/buffer_" + name + "_diff.png", makeHeatMap(result.pixels));
    rows.push_back(row);
  }
  return rows;
}

void printBufferRows(const std::vector<BufferRow>& rows, const std::string& dir) {
  std::cout << "buffers, in pass order (images: " << dir << "/buffer_<name>_cpu|gl|diff.png):\n";
  for (const BufferRow& row : rows) {
    std::cout << "  " << std::left << std::setw(16) << toString(row.buffer) << std::right;
    if (row.light >= 0) std::cout << " light " << row.light;
    if (!row.available) {
      std::cout << ": not available (" << row.note << ")\n";
      continue;
    }
    std::cout << std::setprecision(9);
    if (row.depth) {
      const DepthBufferMetrics& m = row.depthMetrics;
      std::cout << ": " << m.width << "x" << m.height << (m.layers > 1 ? " x " + std::to_string(m.layers) : "")
                << (row.floats ? " channels, max diff " : ", depth max diff ") << m.maxAbsDiff << ", texels over "
                << m.tolerance << ": " << m.overTolerance;
    } else {
      const CompareMetrics& m = row.colourMetrics;
      std::cout << std::setprecision(3) << ": max abs diff " << m.maxAbsDiff << " levels, over 1 level " << m.over1
                << ", coverage mismatch " << m.coverageMismatch;
    }
    std::cout << (row.passes ? "  ok" : "  OVER THE TARGETS") << "\n";
  }
}

void runCompare(CompareArgs& args) {
  validateThresholds(args.limits);
  std::vector<PassBuffer> buffers;
  if (args.allBuffers) {
    buffers.assign(std::begin(kAllPassBuffers), std::end(kAllPassBuffers));
  } else if (!args.buffer.empty()) {
    PassBuffer one{};
    if (!parse(args.buffer, one)) {
      throw InputError("--buffer: expected one of " + allPassBufferNames() + ", got '" + args.buffer + "'");
    }
    buffers.push_back(one);
  }
  if (args.repeat < 1) throw InputError("--repeat: expected an integer >= 1");
  const CpuOptions cpuOptions = requestedCpuOptions(args.cpu);
  GlOptions glOptions = requestedGlOptions(args.gl);
  const Scene scene = loadRequestedScene(args.request);
  const int width = requestedWidth(args.request, scene);
  const int height = requestedHeight(args.request, scene);

  checkReferenceRequest(args, scene);
  glOptions.verbose = args.request.verbose;
  glOptions.fastSampling = args.glFastSampling;
  std::unique_ptr<Renderer> gl = makeGlRenderer(glOptions);
  std::unique_ptr<Renderer> cpu = makeCpuRenderer(cpuOptions);

  RenderOutput glOut, cpuOut;
  CompareRunInfo info;
  info.glMs = renderTimed(*gl, scene, width, height, args.repeat, glOut);
  info.cpuMs = renderTimed(*cpu, scene, width, height, args.repeat, cpuOut);
  info.repeat = args.repeat;
  info.glRenderer = glRendererString();
  info.glVersion = glVersionString();
  // GALLIVM_PERF is llvmpipe's: any other driver filters textures its own way.
  const bool llvmpipe = isLlvmpipe(info.glRenderer);
  info.glSampling = llvmpipe ? glSamplingMode() : "driver";

  // Under a sky box the pixels no triangle covers are compared too.
  CompareOptions options;
  options.compareBackground = drawsSky(scene, scene.settings);
  CompareResult result = compareDetailed(cpuOut, glOut, options);
  // Differing pixels of the same surface: which of them a decision parted (compare/decisions.h),
  // from the decision views both renderers draw; none drawn when nothing differs.
  std::vector<View> decisionViews;
  if (result.metrics.classShading > 0) {
    decisionViews = decisionViewsFor(scene, scene.settings);
    if (!decisionViews.empty()) {
      const DecisionViews a = renderDecisionViews(*cpu, scene, scene.settings, decisionViews, width, height);
      const DecisionViews b = renderDecisionViews(*gl, scene, scene.settings, decisionViews, width, height);
      classifyDecisions(result, a, b);
    }
  }
  Thresholds limits = args.limits;
  // The targets were measured against llvmpipe; a GPU rasterises with other precision and
  // filters textures differently (docs/gl-path.md), so there they would fail for no fault
  // of either renderer. The metrics are still reported; explicit thresholds still apply.
  std::string targetsSkipped;
  if (args.issueTargets && !llvmpipe) {
    targetsSkipped = "--targets not applied: GL_RENDERER '" + info.glRenderer +
                     "' is not llvmpipe, and the targets hold for CPU vs llvmpipe only (docs/gl-path.md); "
                     "the metrics are reported without their verdicts";
  }
  if (args.issueTargets && llvmpipe) {
    const Thresholds targets = twr::issueTargets(cpuOut.stats.trianglesClipped > 0);
    // Explicit options win over the built-in targets.
    auto fill = [](std::optional<double>& mine, const std::optional<double>& target) {
      if (!mine) mine = target;
    };
    fill(limits.maxOver1Pct, targets.maxOver1Pct);
    fill(limits.maxAbsDiff, targets.maxAbsDiff);
    fill(limits.maxNanPixels, targets.maxNanPixels);
    fill(limits.maxCoverageMismatch, targets.maxCoverageMismatch);
    fill(limits.maxCoverageMismatchPer10k, targets.maxCoverageMismatchPer10k);
    fill(limits.maxExcludedLinePct, targets.maxExcludedLinePct);
    fill(limits.maxLineMismatchPct, targets.maxLineMismatchPct);
  }
  std::vector<ThresholdViolation> violations = checkThresholds(result.metrics, limits);
  // Two empty frames agree perfectly and prove nothing: said, and over the targets unless the
  // scene expects it.
  const std::string emptyReason = result.metrics.coveredEither() == 0 ? emptyFrameReason(scene, cpuOut) : "";
  if (!emptyReason.empty() && !scene.output.expectEmpty) {
    warnIfEmpty(scene, cpuOut, true);
    if (args.issueTargets && llvmpipe) {
      ThresholdViolation v;
      v.key = "covered";
      v.message = "covered: no pixel drawn by either renderer, and the scene does not set output.expect_empty";
      violations.push_back(std::move(v));
    }
  }
  // A captured environment: each renderer drew its own faces; they meet the same limits.
  std::optional<CapturedFacesComparison> faces;
  if (cpuOut.capturedFaces && glOut.capturedFaces) {
    faces = compareCapturedFaces(*cpuOut.capturedFaces, *glOut.capturedFaces);
    for (ThresholdViolation& v : checkCapturedFaces(*faces, limits)) violations.push_back(std::move(v));
  }

  // The pass buffers (pass_buffers.h): each held to the targets' colour limits, or for depth to
  // the classification's depth tolerance, texel by texel.
  std::vector<BufferRow> bufferRows;
  if (!buffers.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.outDir, ec);
    if (!std::filesystem::is_directory(args.outDir)) throw InputError(args.outDir + ": cannot create the output folder");
    Thresholds colourTargets = twr::issueTargets(cpuOut.stats.trianglesClipped > 0);
    bufferRows = compareBuffers(buffers, scene, width, height, *cpu, *gl, cpuOut, glOut, result, colourTargets,
                                args.outDir);
    if (args.issueTargets && llvmpipe) {
      for (const BufferRow& row : bufferRows) {
        if (row.available && !row.passes) {
          ThresholdViolation v;
          v.key = "buffers";
          v.message = "buffer " + std::string(toString(row.buffer)) +
                      (row.light >= 0 ? " (light " + std::to_string(row.light) + ")" : "") + " is over the targets";
          violations.push_back(std::move(v));
        }
      }
    }
  }

  nlohmann::json json = metricsToJson(result.metrics);
  mergeExtraKeys(json, runInfoToJson(info));
  mergeExtraKeys(json, {{"scene", args.request.scenePath},
                        {"view", std::string(toString(scene.settings.view))},
                        {"triangles_clipped_cpu", cpuOut.stats.trianglesClipped},
                        {"cpu_path", cpuPathName(cpuOptions)}});
  // The fast path's target, null for the teaching path (it runs no Highway kernels).
  const std::string isa = resolvedCpuIsaName(cpuOptions);
  mergeExtraKeys(json, {{"cpu_isa", isa.empty() ? nlohmann::json(nullptr) : nlohmann::json(isa)}});
  mergeExtraKeys(json, {{"thresholds", thresholdsToJson(limits, violations)}});
  nlohmann::json decisionViewNames = nlohmann::json::array();
  for (const View v : decisionViews) decisionViewNames.push_back(std::string(toString(v)));
  mergeExtraKeys(json, {{"decision_views", decisionViewNames}});
  mergeExtraKeys(json, {{"empty_frame", emptyReason.empty() ? nlohmann::json(nullptr) : nlohmann::json(emptyReason)},
                        {"expect_empty", scene.output.expectEmpty}});
  mergeExtraKeys(json, {{"gl_context", glContextString()},
                        {"targets", {{"requested", args.issueTargets},
                                     {"applied", args.issueTargets && targetsSkipped.empty()},
                                     {"note", targetsSkipped.empty() ? nlohmann::json(nullptr)
                                                                      : nlohmann::json(targetsSkipped)}}}});
  mergeExtraKeys(json, {{"capture_faces", faces ? capturedFacesToJson(*faces) : nlohmann::json(nullptr)},
                        {"cpu_capture_ms", faces ? nlohmann::json(cpuOut.stats.captureMilliseconds) : nlohmann::json(nullptr)},
                        {"gl_capture_ms", faces ? nlohmann::json(glOut.stats.captureMilliseconds) : nlohmann::json(nullptr)}});
  if (!buffers.empty()) {
    nlohmann::json rows = nlohmann::json::array();
    nlohmann::json firstDiffering = nullptr;
    for (const BufferRow& row : bufferRows) {
      rows.push_back(bufferRowToJson(row));
      if (row.available && !row.passes && firstDiffering.is_null()) firstDiffering = std::string(toString(row.buffer));
    }
    mergeExtraKeys(json, {{"buffers", rows}, {"first_differing_buffer", firstDiffering}});
  }
  mergeExtraKeys(json, {{"cpu_shadow_ms", cpuOut.stats.shadowMilliseconds},
                        {"gl_shadow_ms", glOut.stats.shadowMilliseconds},
                        // The deferred pipeline's passes (0 for a forward frame; docs/deferred.md).
                        {"cpu_gbuffer_ms", cpuOut.stats.gbufferMilliseconds},
                        {"cpu_lighting_ms", cpuOut.stats.lightingMilliseconds},
                        {"cpu_ssr_ms", cpuOut.stats.ssrMilliseconds},
                        {"gl_gbuffer_ms", glOut.stats.gbufferMilliseconds},
                        {"gl_lighting_ms", glOut.stats.lightingMilliseconds},
                        {"gl_ssr_ms", glOut.stats.ssrMilliseconds}});
  // The ray-traced reference: the CPU's lit frame without reflections, the rays traced from it.
  std::optional<SsrReference> traced;
  std::vector<SsrReferenceSide> sides;
  if (!args.reference.empty()) {
    const RenderOutput base = cpu->render(scene, ssrBaseSettings(scene.settings), width, height);
    SsrReferenceOptions options;
    options.indirectSamples = args.referenceSamples;
    traced = traceSsrReference(scene, scene.settings, base, RayScene(scene), options);
    sides.push_back({"cpu", &cpuOut, measureSsrError(*traced, cpuOut)});
    sides.push_back({"gl", &glOut, measureSsrError(*traced, glOut)});
  }
  mergeExtraKeys(json, {{"reference", traced ? ssrReferenceToJson(*traced, sides) : nlohmann::json(nullptr)}});
  const ArtifactPaths paths = writeCompareArtifacts(args.outDir, cpuOut, glOut, result, json);
  const std::string referencePath = args.outDir + "/reference_raytrace.png";
  if (traced) savePng(referencePath, ssrReferenceMontage(*traced, sides));
  std::optional<CaptureArtifactPaths> facePaths;
  if (faces) facePaths = writeCaptureArtifacts(args.outDir, *cpuOut.capturedFaces, *glOut.capturedFaces, *faces);
  std::optional<ComparePagePaths> page;
  if (args.html) page = writeComparePage(args.outDir, cpuOut, glOut, result, json);

  if (args.json) {
    std::cout << jsonText(json, 2) << "\n";
  } else {
    printSummary(result.metrics, json, paths);
    if (faces) printCaptureSummary(*faces, cpuOut, glOut, *facePaths);
    if (!bufferRows.empty()) printBufferRows(bufferRows, args.outDir);
    if (traced) printReferenceSummary(*traced, sides, referencePath);
    if (page) std::cout << "wrote " << page->page << " (open it in a browser; pixels.js beside it)\n";
  }
  if (!targetsSkipped.empty()) std::cerr << "twinraster: note: " << targetsSkipped << "\n";
  for (const ThresholdViolation& v : violations) std::cerr << "twinraster: threshold exceeded: " << v.message << "\n";
  exitCode() = violations.empty() ? kExitOk : kExitThreshold;
}

const bool compareRegistered = registerCommand(30, [](CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Render with both backends at the same size and compare per pixel. Writes DIR/cpu.png, gl.png, "
      "side_by_side.png, diff.png (heat map with legend), classes.png (why pixels differ) and metrics.json. "
      "llvmpipe runs in its precise texture-sampling mode unless --gl-fast-sampling. Exit 1 when a threshold "
      "is exceeded, 2 for bad input.");
  addRenderOptions(*cmd, args->request);
  cmd->add_option("--out-dir,-o", args->outDir, "Folder for the images and metrics.json (created)")->required();
  cmd->add_flag("--json", args->json, "Print the metrics JSON object on stdout instead of the summary");
  cmd->add_flag("--html", args->html,
                "Also write DIR/index.html: both images with a split slider, flicker, the heat and class maps, "
                "zoom, both renderers' RGBA, depth, triangle id and class under the pointer, the metrics with "
                "their verdicts and a row per compared buffer (with pixels.js, page_heat.png and "
                "page_classes.png beside it; works from file://, no network)");
  addCpuOptions(*cmd, args->cpu);
  addGlOptions(*cmd, args->gl);
  cmd->add_option("--repeat", args->repeat, "Renders per backend; cpu_ms and gl_ms are their median")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--gl-fast-sampling", args->glFastSampling,
                "Let llvmpipe use its fast texture path (8-bit bilinear weights, one LOD per 2x2 quad) to see "
                "what the shortcut costs");
  cmd->add_option("--buffer", args->buffer,
                  "Also diff one pass buffer: " + allPassBufferNames() +
                      " (docs/compare.md, \"Buffers\"); writes DIR/buffer_<name>_cpu.png, _gl.png, _diff.png and a "
                      "row under metrics.json's \"buffers\"");
  cmd->add_flag("--all-buffers", args->allBuffers,
                "Diff every pass buffer, one row each in pass order under metrics.json's \"buffers\" (and "
                "\"first_differing_buffer\"): where the renderers first part");
  cmd->add_flag("--targets", args->issueTargets,
                "Apply the project's CPU-vs-llvmpipe targets: over_1 <= 0.1%, max_abs_diff <= 3, no NaN, "
                "coverage mismatch 0 (at most 1 per 10,000 covered pixels when triangles are clipped). Only "
                "when GL_RENDERER is llvmpipe: with another driver (a GPU through --gl-context egl) the metrics "
                "are reported without these verdicts and a note says so");
  cmd->add_option("--reference", args->reference,
                  "Also measure both frames against a ground truth. raytrace: the SSR frame's mirror and indirect "
                  "rays traced against the scene's own triangles with Intel Embree, the light they bring added to "
                  "the same lit frame; the error by class (visible, off_screen, occluded, sky, indirect_only; "
                  "docs/ssr.md, \"Against a ray tracer\"). Writes DIR/reference_raytrace.png and metrics.json's "
                  "\"reference\". Needs settings.ssr on and a build with Embree (libembree-dev)")
      ->check(CLI::IsMember({"raytrace"}));
  cmd->add_option("--reference-samples", args->referenceSamples,
                  "Indirect rays per pixel the reference traces (default: the frame's indirect_samples, the very "
                  "rays SSR marches; more converge towards the true indirect light)")
      ->check(CLI::Range(0, kMaxSsrReferenceSamples));
  Thresholds& t = args->limits;
  const auto limit = [cmd](const char* name, std::optional<double>& field, const char* help) {
    cmd->add_option(name, field, help)->group("Thresholds (exit 1 when exceeded; inclusive)");
  };
  limit("--max-over-1-pct", t.maxOver1Pct, "Most pixels differing by more than 1 level, % of pixels both covered");
  limit("--max-over-1", t.maxOver1, "Most pixels differing by more than 1 level");
  limit("--max-over-3", t.maxOver3, "Most pixels differing by more than 3 levels");
  limit("--max-over-12", t.maxOver12, "Most pixels differing by more than 12 levels");
  limit("--max-abs-diff", t.maxAbsDiff, "Largest channel difference, levels 0-255");
  limit("--max-mean-abs-diff", t.maxMeanAbsDiff, "Largest mean channel difference, levels");
  limit("--max-rmse", t.maxRmse, "Largest RMSE, levels");
  limit("--min-psnr", t.minPsnr, "Smallest PSNR, dB");
  limit("--max-coverage-mismatch", t.maxCoverageMismatch, "Most pixels covered by exactly one backend");
  limit("--max-coverage-mismatch-per-10k", t.maxCoverageMismatchPer10k,
        "Most coverage mismatches per 10,000 covered pixels");
  limit("--max-depth-diff", t.maxDepthMaxDiff, "Largest window-depth difference");
  limit("--max-nan-pixels", t.maxNanPixels, "Most CPU pixels with NaN depth");
  limit("--max-depth-class", t.maxClassDepth, "Most pixels where a different surface won the depth test");
  limit("--max-excluded-line-pct", t.maxExcludedLinePct, "Most TBN debug-line pixels (left out of the rest), % of the frame");
  limit("--max-line-mismatch-pct", t.maxLineMismatchPct, "Most line pixels only one backend drew, % of line pixels");
  cmd->callback([args] { runCompare(*args); });
});

}  // namespace
}  // namespace twr::cli
