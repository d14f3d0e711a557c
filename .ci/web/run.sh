#!/usr/bin/env bash
# The browser test from a clean clone: builds the site, installs Debian's Chromium and the two
# npm packages the test uses (never a downloaded browser), then runs it.
set -euo pipefail
cd "$(dirname "$0")/../.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/rubber-band-box/target}"
bash .ci/web/build.sh site

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
# A skipped browser test is not a pass: under CI (CI=true, as .ci/run sets) it fails.
skip() {
    echo "SKIPPED the browser test: $*"
    if [ "${CI:-}" = true ]; then exit 1; fi
    exit 0
}
if ! command -v chromium >/dev/null; then
    # Without a way to install Chromium the site is still built and bound; say so loudly.
    if ! { as_root apt-get update -q && as_root env DEBIAN_FRONTEND=noninteractive \
            apt-get install -y -q chromium; } >/tmp/rubber-band-box-apt.log 2>&1; then
        skip "Chromium could not be installed (see /tmp/rubber-band-box-apt.log)"
    fi
fi
if ! command -v npm >/dev/null; then
    skip "no Node.js/npm on this machine"
fi
if ! (cd .ci/web && npm install --no-audit --no-fund --silent); then
    skip "the npm packages could not be installed"
fi
# The native build that steps the page's recording (`cargo test` has built it already).
cargo build --quiet --bin rubber_band_box
export NATIVE_BINARY="$CARGO_TARGET_DIR/debug/rubber_band_box"
start=$(date +%s)
node .ci/web/browser-test.mjs site
echo "browser test: $(( $(date +%s) - start )) s"
# The monkey: a minute of random input from a fixed seed (MONKEY_SEED; docs/testing.md).
start=$(date +%s)
node .ci/web/monkey.mjs site
echo "browser monkey: $(( $(date +%s) - start )) s"
