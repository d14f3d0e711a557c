#!/usr/bin/env bash
# Builds the web version into site/: index.html, the JS glue and the .wasm.
# Needs only the Rust toolchain: it installs the wasm target and a wasm-bindgen-cli whose
# version equals the wasm-bindgen in Cargo.lock (a mismatch fails at bind time).
set -euo pipefail
cd "$(dirname "$0")/../.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/rubber-band-box/target}"
site="${1:-site}"
# The shipped build is `wasm-release` (small over fast: LTO, one codegen unit, its size
# recorded in docs/web.md). CI's browser test builds with `dev` (WEB_PROFILE=dev): the same code
# and the same bits of every step, our crate rebuilt in a fraction of the time, no compression.
profile="${WEB_PROFILE:-wasm-release}"

rustup target add wasm32-unknown-unknown
version=$(grep -A1 '^name = "wasm-bindgen"$' Cargo.lock | sed -n 's/^version = "\(.*\)"$/\1/p')
if ! wasm-bindgen --version 2>/dev/null | grep -qx "wasm-bindgen $version"; then
    cargo install wasm-bindgen-cli --version "$version"
fi

start=$(date +%s)
cargo build --profile "$profile" --target wasm32-unknown-unknown
echo "cargo build ($profile): $(( $(date +%s) - start )) s"
# cargo's folder for the `dev` profile is `debug`.
folder=$profile
if [ "$profile" = dev ]; then folder=debug; fi

rm -rf "$site"
mkdir -p "$site"
wasm-bindgen --target web --out-dir "$site/pkg" --no-typescript \
    --remove-name-section --remove-producers-section \
    "$CARGO_TARGET_DIR/wasm32-unknown-unknown/$folder/rubber_band_box.wasm"
cp assets/web/index.html "$site/"
wasm="$site/pkg/rubber_band_box_bg.wasm"
if [ "$profile" != wasm-release ]; then
    echo "site: $site ($(stat -c %s "$wasm") bytes of wasm, the $profile profile's: not the shipped size)"
    exit 0
fi
# The pre-compressed copies a static server can send instead (docs/web.md).
if command -v node >/dev/null; then
    node .ci/web/compress.mjs "$wasm" "$site/pkg/rubber_band_box.js"
else
    gzip -9 -k "$wasm" "$site/pkg/rubber_band_box.js"
fi
echo "site: $site ($(stat -c %s "$wasm") bytes of wasm, $(stat -c %s "$wasm.gz") gzipped)"
echo "serve it with: python3 -m http.server --directory $site 8000"
