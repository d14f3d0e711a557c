#!/usr/bin/env bash
# Frame time of the game under Xvfb (Mesa's llvmpipe), side by side: each binary given plays
# 40 s in turn, twice, at 960 x 720 with the lab on (P, V, T; the tutorial's scripted pull
# started again every 10 s), and Mesa's Vulkan overlay layer logs the frame rate each second;
# the median after the first 10 s is printed. Needs xvfb, mesa-vulkan-drivers and xdotool.
# Run: bash .ci/frame-time.sh OLD_BINARY NEW_BINARY (docs/screen.md)
set -euo pipefail
source "$(dirname "$0")/xvfb.sh"
start_xvfb :98
measure() {
    local binary=$1 csv
    csv=$(mktemp --suffix .csv)
    VK_INSTANCE_LAYERS=VK_LAYER_MESA_overlay \
        VK_LAYER_MESA_OVERLAY_CONFIG="output_file=$csv,fps,no_display" \
        "$binary" play >/dev/null 2>&1 &
    local pid=$!
    sleep 6
    local window
    window=$(xdotool search --pid "$pid" | head -n 1)
    xdotool windowfocus "$window"
    for key in p v t; do xdotool key "$key"; sleep 0.3; done
    for _ in 1 2 3 4; do xdotool key 1; sleep 10; done
    kill "$pid"
    wait "$pid" 2>/dev/null || true
    python3 - "$csv" "$binary" <<'PY'
import statistics, sys
rows = [line.split(",") for line in open(sys.argv[1]).read().strip().splitlines()[1:]]
fps = [float(row[2]) for row in rows][10:]
median = statistics.median(fps)
print(f"{sys.argv[2]}: median {median:.1f} fps, {1000 / median:.1f} ms a frame ({len(fps)} samples)")
PY
}
for round in 1 2; do
    for binary in "$@"; do
        measure "$binary"
    done
done
