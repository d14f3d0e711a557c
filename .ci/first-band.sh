#!/usr/bin/env bash
# Time from launching the game to the first frame at which a press makes a band, natively
# under Xvfb (docs/measurements.md#time-to-the-first-frame). The mouse is pressed and held
# about every 30 ms at a point right of the box (at rest at the centre of the 960 x 720
# window) until the band's pin, drawn where the pointer holds it, shows there; the
# time of that press is given, with the first frame with the box drawn for comparison. The
# pin is yellow (theme.rs PIN_FILL, 255 217 51).
# Usage: bash .ci/first-band.sh BINARY [RUNS] [ARGS...] (ARGS default to `play`).
set -euo pipefail
binary=${1:?the game binary, e.g. target/release/rubber_band_box}
runs=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
[ $# -gt 0 ] || set -- play
for run in $(seq 1 "$runs"); do
    xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
        binary=$1
        shift
        pixel() { import -window root -crop 1x1+$1+$2 -depth 8 txt:- 2>/dev/null | tail -1; }
        start=$(date +%s.%N)
        "$binary" "$@" >/dev/null 2>&1 &
        pid=$!
        box=""
        while :; do
            now=$(date +%s.%N)
            if [ -z "$box" ]; then
                # The box: blue, its red under 80 and blue over 150.
                if pixel 415 380 | grep -Eq "\((([0-7]?[0-9]),[0-9]+,(1[5-9][0-9]|2[0-5][0-9]))"; then
                    box=$(echo "$now - $start" | bc)
                fi
            fi
            xdotool mousemove 540 380 mousedown 1 2>/dev/null || true
            sleep 0.03
            # The pin: red over 230, green over 180, blue under 100.
            if pixel 540 380 | grep -Eq "\((2[3-5][0-9]),(1[89][0-9]|2[0-5][0-9]),([0-9]?[0-9])\)"; then
                printf "box %.2f s, a press made a band %.2f s\n" "${box:-0}" "$(echo "$now - $start" | bc)"
                break
            fi
            xdotool mouseup 1 2>/dev/null || true
            if [ "$(echo "$now - $start > 60" | bc)" = 1 ]; then echo "no band in 60 s"; break; fi
        done
        kill "$pid" 2>/dev/null || true
        wait "$pid" 2>/dev/null || true
    ' _ "$binary" "$@"
done
