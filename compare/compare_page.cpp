#include "compare/compare_page.h"

#include "compare/heatmap.h"
#include "compare/page_style.h"
#include "scene/errors.h"
#include "scene/image.h"

#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace twr {

namespace {

// ---- pixels.js ----

void appendLittleEndian32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void addPlane(PixelPlanes& planes, const std::string& name, const std::string& type, std::size_t start) {
  planes.planes.push_back({name, type, start, planes.bytes.size() - start});
}

void addRgba(PixelPlanes& planes, const std::string& name, const RenderOutput& out, std::size_t count) {
  const std::size_t start = planes.bytes.size();
  if (out.rgba.size() == count * 4) {
    planes.bytes.insert(planes.bytes.end(), out.rgba.begin(), out.rgba.end());
  } else {
    planes.bytes.resize(start + count * 4, 0);
  }
  addPlane(planes, name, "u8", start);
}

void addDepth(PixelPlanes& planes, const std::string& name, const RenderOutput& out, std::size_t count) {
  const std::size_t start = planes.bytes.size();
  for (std::size_t i = 0; i < count; ++i) {
    const float d = out.depth.size() == count ? out.depth[i] : 1.0f;
    appendLittleEndian32(planes.bytes, std::bit_cast<std::uint32_t>(d));
  }
  addPlane(planes, name, "f32", start);
}

void addTriangles(PixelPlanes& planes, const std::string& name, const RenderOutput& out, std::size_t count) {
  const std::size_t start = planes.bytes.size();
  for (std::size_t i = 0; i < count; ++i) {
    appendLittleEndian32(planes.bytes, out.triangleId.size() == count ? out.triangleId[i] : kNoTriangle);
  }
  addPlane(planes, name, "u32", start);
}

// ---- index.html ----

std::string numberText(const nlohmann::json& value) {
  if (value.is_null()) return "n/a";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
  if (value.is_number_float()) {
    const double v = value.get<double>();
    if (!std::isfinite(v)) return v > 0 ? "inf" : v < 0 ? "-inf" : "nan";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
  }
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

std::string text(const nlohmann::json& metrics, const char* key) {
  return metrics.contains(key) ? escapeHtml(numberText(metrics[key])) : "n/a";
}

// The verdict: pass, fail, or none when no threshold was asked for.
std::string verdictHtml(const nlohmann::json& metrics) {
  const nlohmann::json& t = metrics.value("thresholds", nlohmann::json::object());
  const bool anyLimit = t.contains("limits") && !t["limits"].empty();
  std::ostringstream s;
  if (!anyLimit) {
    s << "<p><span class=\"verdict none\" id=\"verdict\">no targets</span> No threshold was asked for "
         "(<code>--targets</code> or a <code>--max-...</code> option); the metrics below are reported without a "
         "verdict.";
    const nlohmann::json& targets = metrics.value("targets", nlohmann::json::object());
    if (targets.contains("note") && targets["note"].is_string()) {
      s << " " << escapeHtml(targets["note"].get<std::string>());
    }
    s << "</p>\n";
    return s.str();
  }
  if (t.value("passed", false)) {
    s << "<p><span class=\"verdict pass\" id=\"verdict\">within targets</span> Every threshold holds.</p>\n";
    return s.str();
  }
  s << "<p><span class=\"verdict fail\" id=\"verdict\">over the targets</span></p>\n<ul>\n";
  for (const nlohmann::json& v : t.value("violations", nlohmann::json::array())) {
    s << "<li>" << escapeHtml(v.value("message", std::string())) << "</li>\n";
  }
  s << "</ul>\n";
  return s.str();
}

void writeViewer(std::ostringstream& s, int width, int height) {
  s << "<h2>Images</h2>\n<div class=\"toolbar\" role=\"toolbar\">"
       "<span>show</span>";
  const char* modes[][2] = {{"split", "split"},  {"flicker", "flicker"}, {"cpu", "CPU"},
                            {"gl", "GL"},        {"heat", "heat map"},   {"classes", "classes"}};
  for (const auto& mode : modes) {
    s << "<button type=\"button\" data-mode=\"" << mode[0] << "\" aria-pressed=\""
      << (std::strcmp(mode[0], "split") == 0 ? "true" : "false") << "\">" << mode[1] << "</button>";
  }
  s << "<label>split <input type=\"range\" id=\"split\" min=\"0\" max=\"100\" value=\"50\"></label>"
       "<span id=\"flicker-state\"></span><span>zoom</span>";
  for (const int zoom : {1, 2, 4, 8}) {
    s << "<button type=\"button\" data-zoom=\"" << zoom << "\" aria-pressed=\"" << (zoom == 1 ? "true" : "false")
      << "\">" << zoom << "&times;</button>";
  }
  s << "</div>\n<p class=\"small\">Split: the CPU left of the line, GL right of it. Hover for both renderers' values; "
       "click to hold them (click again to follow the pointer).</p>\n";
  s << "<div class=\"viewer\"><div class=\"stage\" id=\"stage\" style=\"width:" << width << "px\">"
    << "<img id=\"base\" src=\"gl.png\" width=\"" << width << "\" height=\"" << height << "\" alt=\"GL frame\">"
    << "<img id=\"top\" class=\"top\" src=\"cpu.png\" width=\"" << width << "\" height=\"" << height
    << "\" alt=\"CPU frame\"><div class=\"split-line\" id=\"split-line\"></div></div></div>\n";
  s << "<div class=\"readout\" id=\"readout\" aria-live=\"polite\">"
       "pixel <span id=\"ro-xy\">-</span>  class <span id=\"ro-class\">-</span>  "
       "difference <span id=\"ro-diff\">-</span> levels (largest RGB channel)\n"
       "cpu  RGBA <span id=\"ro-cpu-rgba\">-</span>  depth <span id=\"ro-cpu-depth\">-</span>  "
       "triangle <span id=\"ro-cpu-triangle\">-</span>\n"
       "gl   RGBA <span id=\"ro-gl-rgba\">-</span>  depth <span id=\"ro-gl-depth\">-</span>  "
       "triangle <span id=\"ro-gl-triangle\">-</span>\n"
       "<span id=\"ro-state\">loading the pixel values (pixels.js)</span></div>\n";
  s << "<p class=\"small\">With their legends: <a href=\"diff.png\">diff.png</a> (the heat map), "
       "<a href=\"classes.png\">classes.png</a> (why pixels differ), <a href=\"side_by_side.png\">side_by_side.png</a>."
       "</p>\n";
}

struct MetricRow {
  const char* key;
  const char* label;
};
constexpr MetricRow kMetricRows[] = {
    {"coverage_mismatch", "coverage mismatch (pixels covered by one renderer only)"},
    {"coverage_mismatch_per_10k", "coverage mismatch per 10,000 covered pixels"},
    {"max_abs_diff", "largest difference, levels"},
    {"mean_abs_diff", "mean difference, levels"},
    {"rmse", "RMSE, levels"},
    {"psnr", "PSNR, dB"},
    {"over_1", "pixels over 1 level"},
    {"over_1_pct", "pixels over 1 level, % of both covered"},
    {"over_3", "pixels over 3 levels"},
    {"over_12", "pixels over 12 levels"},
    {"covered_cpu", "covered by the CPU"},
    {"covered_gl", "covered by GL"},
    {"both_covered", "covered by both"},
    {"background_compared", "sky pixels compared"},
    {"background_max_abs_diff", "sky: largest difference, levels"},
    {"class_coverage", "differing pixels: coverage"},
    {"class_depth", "differing pixels: depth (another surface won)"},
    {"class_shading", "differing pixels: shading"},
    {"class_decision", "differing pixels: a decision parted"},
    {"depth_max_diff", "largest window-depth difference"},
    {"nan_pixels", "CPU pixels with non-finite depth"},
    {"excluded_line_pixels", "TBN line pixels (left out)"},
    {"excluded_line_pct", "TBN line pixels, % of the frame"},
    {"line_mismatch_pct", "line pixels only one renderer drew, %"},
    {"cpu_ms", "CPU frame, ms (median)"},
    {"gl_ms", "GL frame, ms (median)"},
};

void writeMetricsTable(std::ostringstream& s, const nlohmann::json& metrics) {
  const nlohmann::json& t = metrics.value("thresholds", nlohmann::json::object());
  const nlohmann::json limits = t.value("limits", nlohmann::json::object());
  const nlohmann::json violations = t.value("violations", nlohmann::json::array());
  s << "<h2>Metrics</h2>\n<table id=\"metrics\"><thead><tr><th>metric</th><th>key</th><th>value</th>"
       "<th>limit</th><th>verdict</th></tr></thead><tbody>\n";
  for (const MetricRow& row : kMetricRows) {
    if (!metrics.contains(row.key)) continue;
    std::string limitText, verdict;
    for (const auto& [limitKey, limit] : limits.items()) {
      // A limit key is the metric's with max_ or min_ in front, or the metric's own (max_abs_diff).
      if (limitKey == row.key || (limitKey.size() > 4 && limitKey.substr(4) == row.key)) {
        limitText = (limitKey.rfind("min_", 0) == 0 ? "&ge; " : "&le; ") + escapeHtml(numberText(limit));
        verdict = "ok";
        for (const nlohmann::json& v : violations) {
          if (v.value("key", std::string()) == limitKey) verdict = "over";
        }
      }
    }
    s << "<tr data-key=\"" << row.key << "\"><td>" << row.label << "</td><td><code>" << row.key << "</code></td><td>"
      << text(metrics, row.key) << "</td><td>" << limitText << "</td><td" << (verdict == "over" ? " class=\"bad\"" : "")
      << ">" << verdict << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
}

// A row that opens its images below it.
void writeImageRow(std::ostringstream& s, const std::string& name, const std::string& summary,
                   const std::string& verdict, const std::vector<std::pair<std::string, std::string>>& images) {
  if (images.empty()) {  // nothing to open: a buffer neither renderer has
    s << "<tr data-buffer=\"" << escapeHtml(name) << "\"><td>" << escapeHtml(name) << "</td><td style=\"text-align:left\">"
      << escapeHtml(summary) << "</td><td></td></tr>\n";
    return;
  }
  s << "<tr class=\"open\" data-buffer=\"" << escapeHtml(name) << "\" tabindex=\"0\"><td>" << escapeHtml(name)
    << "</td><td style=\"text-align:left\">" << escapeHtml(summary) << "</td><td"
    << (verdict == "over" ? " class=\"bad\"" : "") << ">" << verdict << "</td></tr>\n";
  s << "<tr class=\"images\" hidden><td colspan=\"3\"><div class=\"buffer-images\">";
  for (const auto& [label, file] : images) {
    s << "<figure><img data-src=\"" << escapeHtml(file) << "\" alt=\"" << escapeHtml(name + " " + label)
      << "\"><figcaption class=\"small\"><a href=\"" << escapeHtml(file) << "\">" << escapeHtml(label)
      << "</a></figcaption></figure>";
  }
  s << "</div></td></tr>\n";
}

std::string bufferSummary(const nlohmann::json& row) {
  if (!row.value("available", false)) return "not available: " + row.value("note", std::string());
  const std::string size = numberText(row["width"]) + "x" + numberText(row["height"]);
  if (row.contains("max_abs_diff")) {
    return size + ", largest difference " + numberText(row["max_abs_diff"]) + " levels, over 1 level " +
           numberText(row.value("over_1", nlohmann::json())) + ", coverage mismatch " +
           numberText(row.value("coverage_mismatch", nlohmann::json()));
  }
  const char* maxKey = row.contains("depth_max_diff") ? "depth_max_diff" : "max_diff";
  return size + (row.value("layers", 1) > 1 ? " x " + numberText(row["layers"]) : "") + ", largest difference " +
         numberText(row.value(maxKey, nlohmann::json())) + ", texels over the tolerance " +
         numberText(row.value("over_tolerance", nlohmann::json()));
}

void writeBufferRows(std::ostringstream& s, const nlohmann::json& metrics) {
  const bool buffers = metrics.contains("buffers") && metrics["buffers"].is_array();
  const bool faces = metrics.contains("capture_faces") && !metrics["capture_faces"].is_null();
  const bool reference = metrics.contains("reference") && !metrics["reference"].is_null();
  if (!buffers && !faces && !reference) return;
  s << "<h2>Compared buffers</h2>\n<p class=\"small\">Click a row for its images: the CPU's, GL's and their "
       "difference.</p>\n<table id=\"buffers\"><thead><tr><th>buffer</th><th>measured</th><th>verdict</th></tr>"
       "</thead><tbody>\n";
  if (buffers) {
    for (const nlohmann::json& row : metrics["buffers"]) {
      std::string name = row.value("buffer", std::string());
      std::string stem = "buffer_" + name;
      if (row.contains("light")) {
        name += " (light " + numberText(row["light"]) + ")";
        stem += "_light" + numberText(row["light"]);
      }
      const nlohmann::json& passes = row.value("passes", nlohmann::json());
      const std::string verdict = passes.is_boolean() ? (passes.get<bool>() ? "ok" : "over") : "";
      std::vector<std::pair<std::string, std::string>> images;
      if (row.value("available", false)) {
        images = {{"cpu", stem + "_cpu.png"}, {"gl", stem + "_gl.png"}, {"difference", stem + "_diff.png"}};
      }
      writeImageRow(s, name, bufferSummary(row), verdict, images);
    }
  }
  if (faces) {
    writeImageRow(s, "captured environment", "the six faces each renderer captured its environment from", "",
                  {{"cpu", "capture_cpu.png"}, {"gl", "capture_gl.png"}, {"difference", "capture_diff.png"}});
  }
  if (reference) {
    writeImageRow(s, "ray-traced reference", "both frames against the ray tracer (metrics.json's \"reference\")", "",
                  {{"montage", "reference_raytrace.png"}});
  }
  s << "</tbody></table>\n";
}

// The page's behaviour: modes, zoom, split, flicker, the readout from pixels.js, the buffer rows.
constexpr const char* kScript = R"js(
(function () {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const stage = $('stage'), base = $('base'), top = $('top'), line = $('split-line'), split = $('split');
  const width = base.width, height = base.height;
  let mode = 'split', zoom = 1, flickerTimer = null, held = false, planes = null;

  function press(attr, value) {
    document.querySelectorAll('[' + attr + ']').forEach((b) => b.setAttribute('aria-pressed', String(b.getAttribute(attr) === String(value))));
  }
  function showSplit() {
    const v = Number(split.value);
    top.style.clipPath = 'inset(0 ' + (100 - v) + '% 0 0)';
    line.style.left = v + '%';
  }
  function setMode(next) {
    mode = next;
    press('data-mode', mode);
    clearInterval(flickerTimer);
    flickerTimer = null;
    $('flicker-state').textContent = '';
    top.style.clipPath = 'none';
    line.hidden = mode !== 'split';
    top.hidden = mode !== 'split' && mode !== 'flicker' && mode !== 'cpu';
    const baseSrc = { heat: 'page_heat.png', classes: 'page_classes.png' }[mode] || 'gl.png';
    if (base.getAttribute('src') !== baseSrc) base.setAttribute('src', baseSrc);
    if (mode === 'split') showSplit();
    if (mode === 'flicker') {
      const tick = () => {
        top.hidden = !top.hidden;
        $('flicker-state').textContent = 'showing ' + (top.hidden ? 'GL' : 'CPU');
      };
      tick();
      flickerTimer = setInterval(tick, 500);
    }
  }
  function setZoom(next) {
    zoom = next;
    press('data-zoom', zoom);
    stage.style.width = width * zoom + 'px';
    for (const img of [base, top]) {
      img.style.width = width * zoom + 'px';
      img.style.height = height * zoom + 'px';
    }
  }
  document.querySelectorAll('[data-mode]').forEach((b) => b.addEventListener('click', () => setMode(b.dataset.mode)));
  document.querySelectorAll('[data-zoom]').forEach((b) => b.addEventListener('click', () => setZoom(Number(b.dataset.zoom))));
  split.addEventListener('input', () => { if (mode !== 'split') setMode('split'); else showSplit(); });

  // ---- the readout ----
  async function unpack(p) {
    const packed = Uint8Array.from(atob(p.data), (c) => c.charCodeAt(0));
    const stream = new Blob([packed]).stream().pipeThrough(new DecompressionStream('deflate'));
    const buffer = await new Response(stream).arrayBuffer();
    const out = {};
    for (const plane of p.planes) {
      const Type = { u8: Uint8Array, u32: Uint32Array, f32: Float32Array }[plane.type];
      out[plane.name] = new Type(buffer, plane.offset, plane.bytes / Type.BYTES_PER_ELEMENT);
    }
    return out;
  }
  function rgba(plane, i) { return Array.from(plane.subarray(i * 4, i * 4 + 4)).join(' '); }
  function triangle(id) { return id === window.twrPixels.no_triangle ? 'none' : String(id); }
  // The float widened to a double, printed as JSON prints it (trace --json's "depth").
  function depth(d) { return String(d); }
  function show(x, y) {
    const i = y * width + x;
    $('ro-xy').textContent = '(' + x + ', ' + y + ')';
    $('ro-class').textContent = window.twrPixels.classes[planes['class'][i]];
    $('ro-diff').textContent = String(planes.diff[i]);
    $('ro-cpu-rgba').textContent = rgba(planes.cpu_rgba, i);
    $('ro-gl-rgba').textContent = rgba(planes.gl_rgba, i);
    $('ro-cpu-depth').textContent = depth(planes.cpu_depth[i]);
    $('ro-gl-depth').textContent = depth(planes.gl_depth[i]);
    $('ro-cpu-triangle').textContent = triangle(planes.cpu_triangle[i]);
    $('ro-gl-triangle').textContent = triangle(planes.gl_triangle[i]);
    $('ro-state').textContent = held ? 'held: click the image to follow the pointer again' : '';
  }
  function pixelAt(event) {
    const r = base.getBoundingClientRect();
    const x = Math.floor((event.clientX - r.left) / r.width * width);
    const y = Math.floor((event.clientY - r.top) / r.height * height);
    return x >= 0 && y >= 0 && x < width && y < height ? [x, y] : null;
  }
  stage.addEventListener('mousemove', (e) => { const p = pixelAt(e); if (planes && p && !held) show(p[0], p[1]); });
  stage.addEventListener('click', (e) => { const p = pixelAt(e); if (!planes || !p) return; held = !held; show(p[0], p[1]); });
  if (!window.twrPixels) {
    $('ro-state').textContent = 'pixels.js did not load: the readout needs it beside this page';
  } else {
    unpack(window.twrPixels).then((p) => {
      planes = p;
      document.body.dataset.pixels = 'ready';
      $('ro-state').textContent = 'hover the image';
    }).catch((err) => { $('ro-state').textContent = 'cannot unpack pixels.js: ' + err; });
  }

  // ---- the buffer rows ----
  document.querySelectorAll('tr.open').forEach((row) => {
    const toggle = () => {
      const images = row.nextElementSibling;
      images.hidden = !images.hidden;
      images.querySelectorAll('img[data-src]').forEach((img) => { if (!img.getAttribute('src')) img.src = img.dataset.src; });
    };
    row.addEventListener('click', toggle);
    row.addEventListener('keydown', (e) => { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); toggle(); } });
  });
  setMode('split');
})();
)js";

// JSON text safe inside a <script> element.
std::string scriptSafeJson(const nlohmann::json& value) {
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out.flush()) throw InputError(path + ": cannot write");
}

}  // namespace

PixelPlanes pixelPlanesOf(const RenderOutput& cpu, const RenderOutput& gl, const PixelAnalysis& pixels) {
  const std::size_t count = static_cast<std::size_t>(pixels.width) * static_cast<std::size_t>(pixels.height);
  PixelPlanes planes;
  planes.bytes.reserve(count * 26);
  addRgba(planes, "cpu_rgba", cpu, count);
  addRgba(planes, "gl_rgba", gl, count);
  addDepth(planes, "cpu_depth", cpu, count);
  addDepth(planes, "gl_depth", gl, count);
  addTriangles(planes, "cpu_triangle", cpu, count);
  addTriangles(planes, "gl_triangle", gl, count);
  std::size_t start = planes.bytes.size();
  for (std::size_t i = 0; i < count; ++i) {
    planes.bytes.push_back(i < pixels.pixelClass.size() ? static_cast<std::uint8_t>(pixels.pixelClass[i]) : 0);
  }
  addPlane(planes, "class", "u8", start);
  start = planes.bytes.size();
  for (std::size_t i = 0; i < count; ++i) planes.bytes.push_back(i < pixels.diffLevels.size() ? pixels.diffLevels[i] : 0);
  addPlane(planes, "diff", "u8", start);
  return planes;
}

std::string base64Of(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    const std::uint32_t v = (std::uint32_t{bytes[i]} << 16) | (left > 1 ? std::uint32_t{bytes[i + 1]} << 8 : 0u) |
                            (left > 2 ? std::uint32_t{bytes[i + 2]} : 0u);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += left > 1 ? kAlphabet[(v >> 6) & 63] : '=';
    out += left > 2 ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::string pixelScript(const PixelPlanes& planes, int width, int height) {
  nlohmann::json classes = nlohmann::json::array();
  for (int c = 0; c <= static_cast<int>(PixelClass::Decision); ++c) {
    classes.push_back(std::string(toString(static_cast<PixelClass>(c))));
  }
  nlohmann::json planeList = nlohmann::json::array();
  for (const PixelPlane& p : planes.planes) {
    planeList.push_back({{"name", p.name}, {"type", p.type}, {"offset", p.offset}, {"bytes", p.bytes}});
  }
  const nlohmann::json header = {{"width", width},     {"height", height},       {"classes", classes},
                                 {"no_triangle", kNoTriangle}, {"planes", planeList}};
  std::string text = "// twinraster compare: both renderers' values per pixel, for index.html's readout.\n"
                     "window.twrPixels = ";
  std::string headerText = header.dump();
  headerText.pop_back();  // the closing brace: the data follows
  text += headerText + ",\"data\":\"" + base64Of(zlibCompress(planes.bytes.data(), planes.bytes.size())) + "\"};\n";
  return text;
}

std::string comparePageHtml(const nlohmann::json& metrics) {
  const std::string scene = metrics.value("scene", std::string("the scene"));
  const int width = metrics.value("width", 0), height = metrics.value("height", 0);
  std::ostringstream s;
  s << pageHead("twinraster compare: " + scene);
  s << "<h1>CPU against GL: " << escapeHtml(scene) << "</h1>\n<p class=\"meta\">" << width << "x" << height
    << ", view " << text(metrics, "view") << ". CPU: " << text(metrics, "cpu_path") << " path, "
    << text(metrics, "cpu_ms") << " ms. GL: " << text(metrics, "gl_renderer") << ", "
    << text(metrics, "gl_version") << ", texture sampling " << text(metrics, "gl_sampling") << ", "
    << text(metrics, "gl_ms") << " ms. Times are the median of " << text(metrics, "repeat")
    << " frames.</p>\n";
  s << verdictHtml(metrics);
  writeViewer(s, width, height);
  writeMetricsTable(s, metrics);
  writeBufferRows(s, metrics);
  s << "<h2>Files</h2>\n<p class=\"small\">Every number on this page is metrics.json's: <a href=\"metrics.json\">"
       "metrics.json</a>. The readout's values are the renderers' own buffers (pixels.js), the numbers "
       "<code>twinraster trace</code> reports at that pixel; coordinates count from the top-left corner.</p>\n";
  s << "<script type=\"application/json\" id=\"twr-metrics\">" << scriptSafeJson(metrics) << "</script>\n";
  s << "<script src=\"pixels.js\"></script>\n<script>" << kScript << "</script>\n</body></html>\n";
  return s.str();
}

ComparePagePaths writeComparePage(const std::string& dir, const RenderOutput& cpu, const RenderOutput& gl,
                                  const CompareResult& result, const nlohmann::json& metrics) {
  ComparePagePaths paths{dir + "/index.html", dir + "/pixels.js", dir + "/page_heat.png", dir + "/page_classes.png"};
  HeatMapOptions heat;
  heat.legend = false;
  ClassMapOptions classes;
  classes.legend = false;
  savePng(paths.heat, makeHeatMap(result.pixels, heat));
  savePng(paths.classes, makeClassMap(result.pixels, classes));
  writeText(paths.pixels,
            pixelScript(pixelPlanesOf(cpu, gl, result.pixels), result.pixels.width, result.pixels.height));
  writeText(paths.page, comparePageHtml(metrics));
  return paths;
}

}  // namespace twr
