#!/usr/bin/env bash
# Time from launching the game to its first frame with the box drawn, natively under Xvfb
# (docs/measurements.md). The screen is read about every 20 ms at a point of the box, at rest
# at the centre of the 960 x 720 window, until it turns the box's blue; the window's first
# frame is when that point turns from Xvfb's black.
# With WINDOW_ONLY=1 it stops at the window's first frame: for an app that draws no box, such
# as the example `band` (`cargo build --example band`), the empty app it is set beside.
# Usage: bash .ci/first-frame.sh BINARY [RUNS]
set -euo pipefail
binary=${1:?the game binary, e.g. target/release/rubber_band_box}
runs=${2:-3}
for run in $(seq 1 "$runs"); do
    xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
        binary=$1
        pixel() { import -window root -crop 1x1+415+380 -depth 8 txt:- 2>/dev/null | tail -1; }
        start=$(date +%s.%N)
        "$binary" play >/dev/null 2>&1 &
        pid=$!
        window=""
        while :; do
            now=$(date +%s.%N)
            seen=$(pixel)
            # Xvfb starts black; the game clears to its dark background before the box shows.
            if [ -z "$window" ] && [ -n "$seen" ] && ! echo "$seen" | grep -q "#000000"; then
                window=$(echo "$now - $start" | bc)
                if [ -n "${WINDOW_ONLY:-}" ]; then printf "window %.2f s\n" "$window"; break; fi
            fi
            # The box: blue, its red under 80 and blue over 150.
            if echo "$seen" | grep -Eq "\((([0-7]?[0-9]),[0-9]+,(1[5-9][0-9]|2[0-5][0-9]))"; then
                printf "window %.2f s, box %.2f s\n" "${window:-0}" "$(echo "$now - $start" | bc)"
                break
            fi
            if [ "$(echo "$now - $start > 60" | bc)" = 1 ]; then echo "no box in 60 s"; break; fi
            sleep 0.02
        done
        kill "$pid" 2>/dev/null || true
        wait "$pid" 2>/dev/null || true
    ' _ "$binary"
done
