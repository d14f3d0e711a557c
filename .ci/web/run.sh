#!/usr/bin/env bash
# The browser test from a clean clone: builds the site, installs Debian's Chromium and the two
# npm packages the test uses (never a downloaded browser), then runs it.
set -euo pipefail
cd "$(dirname "$0")/../.."
bash .ci/web/build.sh site
if ! command -v chromium >/dev/null; then
    sudo_if_needed() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }
    sudo_if_needed apt-get update -q
    sudo_if_needed env DEBIAN_FRONTEND=noninteractive apt-get install -y -q chromium
fi
(cd .ci/web && npm install --no-audit --no-fund --silent)
node .ci/web/browser-test.mjs site
