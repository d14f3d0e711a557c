#!/usr/bin/env bash
# The browser test from a clean clone: builds the site, installs Debian's Chromium and the two
# npm packages the test uses (never a downloaded browser), then runs it.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash .ci/web/build.sh site

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
if ! command -v chromium >/dev/null; then
    # Without a way to install Chromium the site is still built and bound; say so loudly.
    if ! { as_root apt-get update -q && as_root env DEBIAN_FRONTEND=noninteractive \
            apt-get install -y -q chromium; } >/tmp/rubber-band-box-apt.log 2>&1; then
        echo "SKIPPED the browser test: Chromium could not be installed (see /tmp/rubber-band-box-apt.log)"
        exit 0
    fi
fi
if ! command -v npm >/dev/null; then
    echo "SKIPPED the browser test: no Node.js/npm on this machine"
    exit 0
fi
if ! (cd .ci/web && npm install --no-audit --no-fund --silent); then
    echo "SKIPPED the browser test: the npm packages could not be installed"
    exit 0
fi
start=$(date +%s)
node .ci/web/browser-test.mjs site
echo "browser test: $(( $(date +%s) - start )) s"
