#!/usr/bin/env bash
# Mutation scores (docs/testing.md, "Robustness"): cargo-mutants changes the code one operator
# at a time and runs the tests against each change. Not part of CI (all of src/physics takes
# about an hour and a half on two cores, the game layer about as long). Needs
# `cargo install --locked cargo-mutants --version '^27'`.
#
# Two runs:
# - core (the default): src/physics/ against the core's tests (tests/core.rs,
#   tests/integrators.rs without the soak, tests/cli.rs). Results in mutants.out/.
# - game: the game layer's logic (src/game/input/{controls,pointer,panel}.rs,
#   src/game/simulation.rs, src/game/hud/) against the headless game's tests (controls,
#   panel, hud, schedule, lab, draw, play, replay, signals). Results in mutants-game.out/.
#
# It mutates a throw-away git worktree of HEAD in place, with a target folder of its own:
# cargo names our crate's artifacts the same whatever folder it sits in, so a mutant built in
# a shared target folder could be what another checkout's next test links (seen here). The
# first run builds the dependencies once (about as long as a first `cargo test`), later ones
# reuse them. The working tree is never touched.
#
# Usage: .ci/mutants.sh [core|game] [cargo-mutants options; default: the run's files]
# (`--iterate` skips what the previous run of that kind caught.)
# Never edit this file while it runs: bash reads a script as it goes, and a run's results are
# copied out of its worktree by the last lines (an hour's results were lost that way once).
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${RBB_MUTANTS_TARGET_DIR:-$HOME/.cache/rubber-band-box/mutants-target}"
kind=core
case "${1:-}" in
    core | game)
        kind=$1
        shift
        ;;
esac
if [ "$kind" = core ]; then
    out=mutants.out
    # The targets go to the build as well as the test (-C): building every test target for
    # each mutant would double its time. The soak would multiply it by ten (the invariant
    # tests cover what it checks, over fewer steps).
    targets=(-C --test=core -C --test=integrators -C --test=cli)
    test_args=(-- --skip soak)
    defaults=(--file 'src/physics/**/*.rs')
    timeout=15
else
    out=mutants-game.out
    targets=()
    for test in controls panel hud schedule lab draw play replay signals; do
        targets+=(-C "--test=$test")
    done
    test_args=()
    # The layout (the panel's and the HUD's spawn functions) is the screen's look, not logic.
    defaults=(--file src/game/input/controls.rs --file src/game/input/pointer.rs
        --file src/game/input/panel.rs --file src/game/simulation.rs
        --file 'src/game/hud/*.rs' --exclude-re 'spawn_')
    timeout=60
fi
if [ $# -eq 0 ]; then set -- "${defaults[@]}"; fi
work="$(mktemp -d)/tree"
git worktree add --detach --quiet "$work" HEAD
trap 'git worktree remove --force "$work"' EXIT
# The previous results, so that `--iterate` tests only what they did not catch.
if [ -d "$out" ]; then cp -r "$out" "$work/mutants.out"; fi
(
    cd "$work"
    cargo mutants --in-place --no-shuffle --timeout "$timeout" "${targets[@]}" "$@" \
        -- "${test_args[@]}" || true
)
rm -rf "$out"
cp -r "$work/mutants.out" "$out"
grep -c . "$out"/caught.txt "$out"/missed.txt "$out"/timeout.txt "$out"/unviable.txt \
    2>/dev/null || true
