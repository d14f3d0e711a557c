#!/usr/bin/env bash
# Retakes every screenshot README and docs/ show, from the game as it now is:
# - natively, the desktop build under Xvfb on Mesa's llvmpipe, at the game's own 960 x 720 and
#   resized to a phone held upright (390 x 844): the tutorial's scripted pull with the ghosts
#   and the plot on (keys 1 and P);
# - in the browser, the pictures the browser test takes (headless Chromium, software WebGL2),
#   at a desktop's and a phone's viewport, and learn mode's eight chapters at the desktop's.
# Needs Debian's xvfb, mesa-vulkan-drivers, xdotool and imagemagick (installed if missing) and
# what .ci/web/run.sh needs. Run: bash .ci/screenshots.sh
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/rubber-band-box/target}"

source .ci/xvfb.sh
install_missing Xvfb:xvfb xdotool:xdotool import:imagemagick

cargo build --quiet --bin rubber_band_box
game="$CARGO_TARGET_DIR/debug/rubber_band_box"

start_xvfb :97

# Plays the game at a window size, opens the energy card where a wide window shows its title
# (the cards start folded), starts the tutorial's scripted pull (1) with the plot (P), and
# takes the window during the pull: name, width, height.
native() {
    local name=$1 width=$2 height=$3
    "$game" play >/tmp/rubber-band-box-shot.log 2>&1 &
    local pid=$!
    local window=""
    for _ in $(seq 60); do
        window=$(xdotool search --pid "$pid" 2>/dev/null | head -n 1 || true)
        [ -n "$window" ] && break
        sleep 1
    done
    [ -n "$window" ] || { echo "no window"; kill "$pid"; exit 1; }
    xdotool windowsize "$window" "$width" "$height"
    xdotool windowfocus "$window"
    # The software renderer's first frames are slow.
    sleep 8
    if [ "$width" -ge "$height" ]; then
        # The third title of the folded dock: Energy.
        xdotool mousemove --window "$window" $((width - 60)) 82 click 1
        sleep 1
    fi
    xdotool mousemove --window "$window" 5 "$((height / 2))"
    xdotool key 1
    sleep 0.3
    xdotool key p
    sleep 1.6
    import -window "$window" "assets/$name.png"
    kill "$pid"
    wait "$pid" 2>/dev/null || true
    echo "assets/$name.png"
}
native screenshot 960 720
native screenshot-phone 390 844

# The browser's pictures: the browser test takes them.
bash .ci/web/run.sh
cp site/screens/desktop-lab.png assets/screenshot-web.png
cp site/screens/phone-390-lab-plot.png assets/screenshot-web-phone.png
echo "assets/screenshot-web.png assets/screenshot-web-phone.png"
# Learn mode's chapters, at the desktop's size (docs/learn.md), in 128 colours (a third the
# bytes, no visible loss on the UI's flat colours).
mkdir -p assets/learn
for chapter in 1 2 3 4 5 6 7 8; do
    convert "site/screens/desktop-learn-$chapter.png" -colors 128 "PNG8:assets/learn/chapter-$chapter.png"
done
echo "assets/learn/chapter-1.png ... chapter-8.png"
# The band by keyboard alone (docs/accessibility.md): the browser test's keyboard pull.
convert site/screens/keyboard-band.png -colors 128 PNG8:assets/keyboard-band.png
echo "assets/keyboard-band.png"
