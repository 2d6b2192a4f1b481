#!/usr/bin/env bash
# The shipped scenes on a real GPU: `twinraster suite` over assets/scenes/ with GL drawn on the
# first EGL device that is not llvmpipe, and a summary table (driver; per scene: coverage
# mismatch, largest difference, over-1 share, pixels by class) for docs/gl-path.md.
#
# A GPU machine may have no package registry, so the build travels:
#   scripts/gpu-suite.sh pack [BUILD_DIR] [PACK_DIR]   here: a stripped twinraster and the
#       shared libraries it loads, but not the C library, nor libEGL and the GL drivers (the GPU
#       machine's own are the point). Without BUILD_DIR it builds one, build-gpu/ (Release, no
#       GUI, no Embree: Embree's 42 MB would double the pack, and the GPU run needs no ray
#       tracer), into gpu-pack/ (about 21 MB).
#   scripts/gpu-suite.sh run [PACK_DIR] [OUT_DIR]      there, in a checkout (for assets/): finds
#       the device (GPU_SUITE_DEVICE=N to name it), runs the suite, writes OUT_DIR/index.html,
#       suite.json, junit.xml and summary.md. Default gpu-pack/ into out/gpu-suite/.
# Exit: the suite's (0 all within the thresholds, 1 any over, 2 any bad input); 3 when no
# EGL device other than llvmpipe is found.
set -euo pipefail
cd "$(dirname "$0")/.."

pack() {
  local build="${1:-}" dest="${2:-gpu-pack}"
  if [ -z "$build" ]; then
    build=build-gpu
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DTWINRASTER_BUILD_GUI=OFF -DTWINRASTER_BUILD_BENCH=OFF \
      -DTWINRASTER_EMBREE=OFF >/dev/null
    cmake --build "$build" --target twinraster -j "$(nproc)"
  fi
  local exe="$build/app/twinraster"
  [ -x "$exe" ] || { echo "gpu-suite: no $exe (make build first)" >&2; exit 2; }
  rm -rf "$dest" && mkdir -p "$dest/bin" "$dest/lib"
  cp "$exe" "$dest/bin/twinraster" && strip "$dest/bin/twinraster"
  # What the GPU machine supplies itself: the C library and loader, and every GL/EGL library
  # (its driver's). Everything else ldd lists travels (Embree, TBB, libstdc++, zlib, ...).
  local skip='^(linux-vdso|ld-linux|libc\.|libm\.|libdl\.|librt\.|libpthread\.|libEGL|libGL|libGLX|libGLdispatch|libOpenGL|libgbm|libdrm)'
  ldd "$dest/bin/twinraster" | awk '$3 ~ /^\// {print $1, $3}' | while read -r name path; do
    if [[ ! "$name" =~ $skip ]]; then cp -L "$path" "$dest/lib/" && strip --strip-unneeded "$dest/lib/$name" 2>/dev/null || true; fi
  done
  echo "gpu-suite: packed $(du -sh "$dest" | cut -f1) into $dest ($(ls "$dest/lib" | wc -l) libraries: $(ls "$dest/lib" | tr '\n' ' '))"
}

# The first EGL device whose GL_RENDERER is not llvmpipe, from `info --gl --json`.
find_device() {
  local exe="$1"
  if [ -n "${GPU_SUITE_DEVICE:-}" ]; then echo "$GPU_SUITE_DEVICE"; return; fi
  "$exe" info --gl --json | python3 -c '
import json, sys
for c in json.load(sys.stdin)["gl_contexts"]:
    if c.get("device") is not None and c.get("error") is None and not c.get("llvmpipe"):
        print(c["device"]); break'
}

summary() {
  local out="$1"
  python3 - "$out" <<'PY'
import json, os, sys
out = sys.argv[1]
suite = json.load(open(os.path.join(out, "suite.json")))
rows, driver = [], ""
for c in suite["cases"]:
    path = os.path.join(out, c["dir"], "metrics.json")
    m = json.load(open(path)) if c["outcome"] != "error" and os.path.exists(path) else {}
    driver = driver or m.get("gl_renderer", "")
    cells = [c["dir"], c["outcome"]] + [str(m.get(k, "n/a")) for k in
             ("coverage_mismatch", "max_abs_diff", "over_1_pct", "class_coverage", "class_depth", "class_shading",
              "class_decision")]
    rows.append("| " + " | ".join(cells) + " |")
with open(os.path.join(out, "summary.md"), "w") as f:
    f.write(f"Driver: {driver}\n\n{suite['passed']} within, {suite['failed']} over, {suite['errors']} bad input, "
            f"{suite['seconds']:.0f} s\n\n")
    f.write("| scene | verdict | coverage mismatch | largest difference | over 1 level, % | coverage | depth | "
            "shading | decision |\n|---|---|---|---|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
print(open(os.path.join(out, "summary.md")).read())
PY
}

run() {
  local packed="${1:-gpu-pack}" out="${2:-out/gpu-suite}"
  [ -d "$packed/bin" ] || { echo "gpu-suite: no $packed/bin (scripts/gpu-suite.sh pack makes it)" >&2; exit 2; }
  packed="$(cd "$packed" && pwd)"
  export LD_LIBRARY_PATH="$packed/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  local exe="$packed/bin/twinraster"
  "$exe" info --gl || true
  local device
  device="$(find_device "$exe")"
  if [ -z "$device" ]; then echo "gpu-suite: no EGL device other than llvmpipe here" >&2; exit 3; fi
  echo "gpu-suite: EGL device $device"
  local code=0
  "$exe" suite assets/scenes --out-dir "$out" --junit "$out/junit.xml" --gl-context egl --gl-device "$device" \
    --targets || code=$?
  summary "$out"
  exit "$code"
}

case "${1:-}" in
  pack) shift; pack "$@" ;;
  run) shift; run "$@" ;;
  *) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
