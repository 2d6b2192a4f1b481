#include "compare/page_style.h"

namespace twr {

namespace {

// The report's rules first (text, tables, charts), then the comparison pages' (verdicts, the
// image viewer, thumbnails). Colours: the CPU blue, GL red, as in every chart.
constexpr std::string_view kStyle =
    R"(body{font:15px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;color:#1d1d24;
max-width:1080px;margin:24px auto;padding:0 18px}h1{font-size:26px;margin-bottom:4px}h2{font-size:20px;
margin-top:38px;border-bottom:1px solid #ddd;padding-bottom:4px}.meta{color:#555;font-size:13px}
.reading{background:#f3f6fb;border-left:4px solid #1f5fa8;padding:8px 12px;margin:10px 0}
table{border-collapse:collapse;font-size:13px;margin:10px 0 4px}th,td{border:1px solid #d5d5dd;padding:3px 7px;
text-align:right}th{background:#eef0f5}td:first-child,th:first-child{text-align:left}td:nth-child(-n+2){white-space:nowrap}td.cpu{color:#1f5fa8;
text-align:left}td.gl{color:#c0392b;text-align:left}td.bad{background:#fbe3e0;font-weight:600}
svg.chart{display:block;max-width:100%;height:auto}svg .tick{font-size:11px;fill:#444}svg .axis{font-size:13px;
fill:#222}svg .label{font-size:11px}svg .legend{font-size:12px;fill:#222}dl{margin:4px 0}dt{font-weight:600}
dd{margin:0 0 6px 16px}.small{font-size:13px;color:#444}ul.summary li{margin-bottom:6px}
.verdict{display:inline-block;padding:1px 8px;border-radius:3px;font-weight:600;font-size:13px}
.verdict.pass{background:#e1f3e4;color:#1b6b2a}.verdict.fail{background:#fbe3e0;color:#a12b1d}
.verdict.error{background:#fdf0d5;color:#8a5a00}.verdict.none{background:#eef0f5;color:#444}
.toolbar{display:flex;flex-wrap:wrap;gap:6px 14px;align-items:center;margin:10px 0;font-size:13px}
.toolbar button{font:inherit;padding:2px 10px;border:1px solid #b9bcc8;background:#f7f7fa;border-radius:3px;cursor:pointer}
.toolbar button[aria-pressed=true]{background:#1f5fa8;color:#fff;border-color:#1f5fa8}
.viewer{overflow:auto;max-height:80vh;width:fit-content;max-width:100%;border:1px solid #d5d5dd;background:repeating-conic-gradient(#ddd 0 25%,#f4f4f4 0 50%) 0 0/16px 16px}
.stage{position:relative;line-height:0}.stage img{display:block;image-rendering:pixelated}
.stage img.top{position:absolute;left:0;top:0}
.split-line{position:absolute;top:0;bottom:0;width:0;border-left:2px solid #fff;box-shadow:0 0 0 1px #000;pointer-events:none}
.readout{font:12px/1.5 ui-monospace,Menlo,Consolas,monospace;background:#f3f6fb;border:1px solid #d5d5dd;
padding:6px 10px;margin:8px 0;min-height:6em;white-space:pre}
tr.open{cursor:pointer}tr.open:hover td{background:#f3f6fb}.buffer-images{display:flex;gap:8px;flex-wrap:wrap}
.buffer-images figure{margin:0}.buffer-images img{max-width:340px;image-rendering:pixelated}
img.thumb{width:160px;image-rendering:auto;display:block}th.sort{cursor:pointer;user-select:none}
th.sort[aria-sort=ascending]::after{content:" \25B2"}th.sort[aria-sort=descending]::after{content:" \25BC"}
td.l{text-align:left;white-space:normal;max-width:300px}th.l{text-align:left}.wrap{overflow-wrap:anywhere})";

}  // namespace

std::string_view pageStyleSheet() { return kStyle; }

std::string pageHead(std::string_view title) {
  std::string s = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>";
  s += escapeHtml(title);
  s += "</title>\n<style>";
  s += kStyle;
  s += "</style></head><body>\n";
  return s;
}

}  // namespace twr
