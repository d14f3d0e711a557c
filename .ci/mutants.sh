#!/usr/bin/env bash
# The mutation score of the numerical core (README, "Tests that can fail"): cargo-mutants
# changes src/physics/ one operator at a time and runs the core's tests against each change.
# Not part of CI (it takes well over an hour on two cores). Needs `cargo install --locked
# cargo-mutants --version '^27'`.
#
# It mutates a throw-away git worktree of HEAD in place, so that the build reuses the
# dependencies already compiled in the shared target folder and the working tree is never
# touched. Results: mutants.out/ in the repository (caught.txt, missed.txt, ...).
#
# Usage: .ci/mutants.sh [extra cargo-mutants options, e.g. --file src/physics/forces.rs]
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/rubber-band-box/target}"
work="$(mktemp -d)/tree"
git worktree add --detach --quiet "$work" HEAD
trap 'git worktree remove --force "$work"' EXIT
(
    cd "$work"
    # The core's own tests, without the soak (it would multiply the time by ten; the
    # invariant tests cover what it checks, over fewer steps).
    cargo mutants --in-place --no-shuffle --timeout 120 \
        --file 'src/physics/**/*.rs' "$@" \
        -- --test core --test integrators -- --skip soak || true
)
rm -rf mutants.out
cp -r "$work/mutants.out" mutants.out
grep -c . mutants.out/caught.txt mutants.out/missed.txt mutants.out/timeout.txt \
    mutants.out/unviable.txt 2>/dev/null || true
