#!/usr/bin/env bash
# The mutation score of the numerical core (docs/testing.md, "Robustness"): cargo-mutants changes
# src/physics/ one operator at a time and runs the core's tests against each change. Not part
# of CI (all of src/physics takes about an hour and a half on two cores). Needs
# `cargo install --locked cargo-mutants --version '^27'`.
#
# It mutates a throw-away git worktree of HEAD in place, with a target folder of its own:
# cargo names our crate's artifacts the same whatever folder it sits in, so a mutant built in
# a shared target folder could be what another checkout's next test links (seen here). The
# first run builds the dependencies once (about as long as a first `cargo test`), later ones
# reuse them. The working tree is never touched. Results: mutants.out/ in the repository
# (caught.txt, missed.txt, ...).
#
# Usage: .ci/mutants.sh [cargo-mutants options; default: --file 'src/physics/**/*.rs']
# (`--iterate` skips what the previous run, in mutants.out/, caught.)
# Never edit this file while it runs: bash reads a script as it goes, and a run's results are
# copied out of its worktree by the last lines (an hour's results were lost that way once).
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${RBB_MUTANTS_TARGET_DIR:-$HOME/.cache/rubber-band-box/mutants-target}"
work="$(mktemp -d)/tree"
git worktree add --detach --quiet "$work" HEAD
trap 'git worktree remove --force "$work"' EXIT
# The previous results, so that `--iterate` tests only what they did not catch.
if [ -d mutants.out ]; then cp -r mutants.out "$work/"; fi
(
    cd "$work"
    # The core's own tests and the CLI's (the binary is linked for any integration test
    # anyway), without the soak (it would multiply the time by ten; the invariant tests
    # cover what it checks, over fewer steps) and the property tests (8 s a run).
    if [ $# -eq 0 ]; then set -- --file 'src/physics/**/*.rs'; fi
    # The targets go to the build as well as the test (-C): building every test target for
    # each mutant would double its time.
    cargo mutants --in-place --no-shuffle --timeout 15 \
        -C --test=core -C --test=integrators -C --test=cli "$@" \
        -- -- --skip soak || true
)
rm -rf mutants.out
cp -r "$work/mutants.out" mutants.out
grep -c . mutants.out/caught.txt mutants.out/missed.txt mutants.out/timeout.txt \
    mutants.out/unviable.txt 2>/dev/null || true
