#!/bin/sh
# The figures of docs/performance.md: `twinraster bench --json` at 1280 x 720 on the default
# scene, the 1M-triangle scene, the default scene without maps (lit, and flat in the albedo
# view), every suite scene and the default scene in every debug view, printed as one Markdown
# table row each.
#   bench/performance_table.sh [TWINRASTER] [FRAMES]   (defaults: build/app/twinraster, 9)
# Each row takes (FRAMES + 2 warm-up) CPU frames and as many llvmpipe frames of each kind:
# glrender's full frame (four attachments read back) and the lean one an OpenGL user draws
# (colour + depth, the colour read back), the fair reference. "cpu" is the fast path on the
# best target this CPU runs (named in the cpu target column). The machine's other work moves
# wall times; the process CPU columns move less.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build/app/twinraster}
frames=${2:-9}

row() {  # label, then bench arguments
  label=$1
  shift
  "$exe" bench "$@" --width 1280 --height 720 --frames "$frames" --json | python3 -c '
import json, sys
j = json.load(sys.stdin)
label = sys.argv[1]
print("| %s | %d | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.2f |" % (
    label, j["covered_pixels"], j["cpu_isa"], j["cpu_ms_median"], j["cpu_process_cpu_ms_median"],
    j["gl_ms_median"], j["gl_process_cpu_ms_median"], j["gl_draw_ms_median"], j["gl_readback_ms_median"],
    j["gl_lean_ms_median"], j["ratio_cpu_over_gl"], j["ratio_cpu_over_gl_draw"], j["ratio_cpu_over_gl_lean"]))
' "$label"
}

echo "| scene | covered px | cpu target | cpu ms | cpu process ms | gl ms | gl process ms | gl drawing ms | gl readback ms | gl lean ms | cpu/gl | cpu/gl drawing | cpu/gl lean |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
row "default" "$root/assets/scenes/default.json"
row "bench_1m (1M triangles)" "$root/bench/scenes/bench_1m.json"
# The issue's "plain Phong, no textures" and "flat colour" frames: the default scene without maps.
row "default_untextured (plain Phong)" "$root/bench/scenes/default_untextured.json"
row "default_untextured, view albedo (flat colour)" "$root/bench/scenes/default_untextured.json" --view albedo
for scene in "$root"/assets/scenes/*.json; do
  name=$(basename "$scene" .json)
  [ "$name" = default ] && continue
  row "$name" "$scene"
done
for view in albedo normal tangent bitangent mapped_normal uv depth light_tangent eye_tangent; do
  row "default, view $view" "$root/assets/scenes/default.json" --view "$view"
done
