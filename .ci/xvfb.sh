# Sourced by the scripts that play the game under Xvfb (Mesa's llvmpipe): installs what they
# need if it is missing, and starts a virtual display that ends with the script.

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

# install_missing COMMAND:PACKAGE ...: installs, with mesa-vulkan-drivers, the packages whose
# command is missing (Debian's apt).
install_missing() {
    local pair missing=()
    for pair in "$@"; do
        command -v "${pair%%:*}" >/dev/null || missing+=("${pair#*:}")
    done
    if [ ${#missing[@]} -gt 0 ]; then
        as_root apt-get update -q
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q \
            mesa-vulkan-drivers "${missing[@]}"
    fi
}

# start_xvfb DISPLAY: a 1400 x 1000 screen on DISPLAY, exported, killed when the script exits.
start_xvfb() {
    Xvfb "$1" -screen 0 1400x1000x24 >/dev/null 2>&1 &
    xvfb=$!
    trap 'kill "$xvfb" 2>/dev/null || true' EXIT
    export DISPLAY="$1"
    sleep 2
}
