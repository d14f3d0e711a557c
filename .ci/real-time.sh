#!/usr/bin/env bash
# Real time, the lab off and on, natively and in the browser, in one run
# (docs/measurements.md#real-time). The tutorial's scene opened by a link, the lab off
# (`?scene=tutorial`) and on (the same with ghosts, plot, vectors and trail), alternated, two
# rounds each:
# - natively, the dev build (what `cargo run` plays) under Xvfb on Mesa's llvmpipe at its own
#   960 x 720: 30 s a round, the frame rate from Mesa's Vulkan overlay layer each second, the
#   pace from the window title ("behind: runs ×0.42" while the clock falls behind, else 1);
#   the fixed steps a frame are the step rate times the pace over the frame rate;
# - in headless Chromium (SwiftShader) at 960 x 720, the site .ci/web/build.sh made:
#   .ci/web/real-time.mjs counts frames and reads the simulated time off the status line.
# The heaviest settings (issue 51: the stiff scene at k = 1e12, 4096 Hz, ×16, the lab on) are
# measured the same way, natively in the dev and the release build and in the browser, and the
# pause is timed: after Space, the simulated time must stand still from the next frame.
# Needs xvfb, mesa-vulkan-drivers and xdotool (installed if missing) and what .ci/web/run.sh
# needs (the site built, Chromium, the npm packages). Run: bash .ci/real-time.sh
# (REAL_TIME_HEAVIEST_ONLY=1: only the heaviest settings).
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/rubber-band-box/target}"

source .ci/xvfb.sh
install_missing Xvfb:xvfb xdotool:xdotool
cargo build --quiet --bin rubber_band_box
game="$CARGO_TARGET_DIR/debug/rubber_band_box"
cargo build --quiet --release --bin rubber_band_box
release="$CARGO_TARGET_DIR/release/rubber_band_box"
heaviest='?v=1&scene=stiff&k=1e12&rate=4096&time=16&ghosts=on&plot=on&vectors=on&trail=on'
rate=100

start_xvfb :96

native() {
    local mode=$1 link=$2 csv titles
    csv=$(mktemp --suffix .csv)
    titles=$(mktemp)
    VK_INSTANCE_LAYERS=VK_LAYER_MESA_overlay \
        VK_LAYER_MESA_OVERLAY_CONFIG="output_file=$csv,fps,no_display" \
        "${binary:-$game}" play --link "$link" >/dev/null 2>&1 &
    local pid=$! window=""
    for _ in $(seq 60); do
        window=$(xdotool search --pid "$pid" 2>/dev/null | head -n 1 || true)
        [ -n "$window" ] && break
        sleep 1
    done
    # The software renderer's first frames are slow; then 30 s, the title read each second.
    sleep 6
    for _ in $(seq 30); do
        xdotool getwindowname "$window" >>"$titles" 2>/dev/null || true
        sleep 1
    done
    kill "$pid"
    wait "$pid" 2>/dev/null || true
    python3 - "$csv" "$titles" "$mode" "$rate" "${scale:-1}" <<'PY'
import re, statistics, sys
rows = [line.split(",") for line in open(sys.argv[1]).read().strip().splitlines()[1:]]
fps = statistics.median([float(row[2]) for row in rows][7:])
paces = [float(m.group(1)) if (m := re.search(r"behind: runs ×([\d.]+)", t)) else float(sys.argv[5])
         for t in open(sys.argv[2]).read().splitlines()]
pace = statistics.median(paces)
rate = float(sys.argv[4])
print(f"native, {sys.argv[3]}: {1000 / fps:.1f} ms a frame ({fps:.1f} fps), "
      f"{rate * pace / fps:.2f} fixed steps a frame, pace {pace:.2f} (least {min(paces):.2f})")
PY
}

if [ -z "${REAL_TIME_HEAVIEST_ONLY:-}" ]; then
    for round in 1 2; do
        native "lab off, round $round" '?v=1&scene=tutorial'
        native "lab on, round $round" '?v=1&scene=tutorial&ghosts=on&plot=on&vectors=on&trail=on'
    done
fi
# The pace the title shows at ×16 is the rate kept (runs ×0.42), so the steps a frame are the
# step rate times it over the frame rate.
rate=4096
scale=16
for round in 1 2; do
    binary=$game native "heaviest, dev, round $round" "$heaviest"
    binary=$release native "heaviest, release, round $round" "$heaviest"
done
(cd .ci/web && npm install --no-audit --no-fund --silent)
node .ci/web/real-time.mjs site
