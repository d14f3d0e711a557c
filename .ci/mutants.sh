#!/usr/bin/env bash
# Mutation scores (docs/testing.md, "Mutation testing"): cargo-mutants changes the code one
# operator at a time and runs the tests against each change. Not part of CI: on the 2-core
# machine a mutant takes 15 to 30 s (our crate rebuilt, the test binary linked), so
# all of src/physics (about 1150 mutants) takes hours and the game layer (about 380) two;
# `--since COMMIT` tries only the functions changed since a run. Needs
# `cargo install --locked cargo-mutants --version '^27'`.
#
# Two runs:
# - core (the default): src/physics/ against the core's tests (tests/suite's core,
#   integrators without the soak, cli and stability). Results in
#   mutants.out/core/.
# - game: the game layer (src/game/input/controls.rs, the panel, src/game/pointer.rs,
#   src/game/simulation.rs, the HUD and the Readouts and Energy cards), each file against the
#   modules of headless tests that drive it (the groups below). Results in mutants-game.out/, a folder a group.
# Each writes summary.csv beside its results (.ci/mutants-summary.sh): a row a group, the
# score of the viable mutants; docs/testing.md shows a committed snapshot of it.
#
# It mutates a throw-away git worktree of HEAD in place, with a target folder of its own:
# cargo names our crate's artifacts the same whatever folder it sits in, so a mutant built in
# a shared target folder could be what another checkout's next test links (seen here). The
# first run builds the dependencies once (about as long as a first `cargo test`), later ones
# reuse them. The working tree is never touched.
#
# Usage: .ci/mutants.sh [core|game] [--since COMMIT] [cargo-mutants options]
# (core's default options: its files; `--iterate` skips what the previous run of that kind
# caught; `--since COMMIT` mutates only what `git diff COMMIT HEAD` touches, `--in-diff`.)
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
since=()
if [ "${1:-}" = --since ]; then
    diff=$(mktemp)
    git diff "$2" HEAD -- src >"$diff"
    since=(--in-diff "$diff")
    shift 2
fi
work="$(mktemp -d)/tree"
git worktree add --detach --quiet "$work" HEAD
trap 'git worktree remove --force "$work"' EXIT
if [ "$kind" = core ]; then
    out=mutants.out
    if [ $# -eq 0 ]; then set -- --file 'src/physics/**/*.rs'; fi
    # The previous results, so that `--iterate` tests only what they did not catch.
    if [ -d "$out/core" ]; then cp -r "$out/core" "$work/mutants.out"; fi
    (
        cd "$work"
        # The target goes to the build as well as the test (-C), the modules to the test
        # binary as filters. The soak would multiply the time by ten (the invariant tests
        # cover what it checks, over fewer steps).
        cargo mutants --in-place --no-shuffle --timeout 15 \
            -C --test=suite "${since[@]}" "$@" \
            -- -- core:: integrators:: cli:: stability:: --skip soak || true
    )
    rm -rf "$out"
    mkdir -p "$out"
    if [ -d "$work/mutants.out" ]; then cp -r "$work/mutants.out" "$out/core"; fi
else
    # Each file against the tests that drive it (building them all for every mutant would
    # triple the time): a group a line, its files then its test targets. The layout (the
    # panel's and the HUD's spawn functions) is tried too, and counted apart (docs/testing.md).
    out=mutants-game.out
    groups=(
        "src/game/input/controls.rs src/game/pointer.rs : controls pointer fixed_step panel"
        "src/game/simulation.rs : fixed_step pointer lab hud replay learn"
        "src/game/input/panel/mod.rs src/game/input/panel/buttons.rs src/game/input/panel/slider.rs : panel"
        "src/game/hud/mod.rs src/game/readouts/mod.rs src/game/energy/lines.rs src/game/energy/history.rs : lib hud controls fixed_step draw"
    )
    # The previous results, so that `--iterate` tests only what they did not catch.
    previous=$(mktemp -d)
    if [ -d "$out" ]; then cp -r "$out"/. "$previous"/; fi
    rm -rf "$out"
    mkdir -p "$out"
    baseline=run
    for group in "${groups[@]}"; do
        files=() targets=() filters=()
        for file in ${group%%:*}; do files+=(--file "$file"); done
        # `lib`: the tests beside the code (`#[cfg(test)]`, all under `game::`), the rest
        # modules of the one test binary, tests/suite (a filter each).
        for test in ${group##*:}; do
            if [ "$test" = lib ]; then
                targets+=(-C --lib)
                filters+=("game::")
            else
                filters+=("$test::")
            fi
        done
        targets+=(-C --test=suite)
        name=$(basename "${group%% *}" .rs)
        if [ "$name" = mod ]; then name=$(basename "$(dirname "${group%% *}")"); fi
        if [ -d "$previous/$name" ]; then
            mkdir -p "$work/$name"
            cp -r "$previous/$name" "$work/$name/mutants.out"
        fi
        (
            cd "$work"
            cargo mutants --in-place --no-shuffle --timeout 60 --baseline "$baseline" \
                "${targets[@]}" "${files[@]}" "${since[@]}" "$@" --output "$work/$name" \
                -- -- "${filters[@]}" || true
        )
        # With `--since`, a group whose files did not change has no mutants and no results.
        if [ -d "$work/$name/mutants.out" ]; then
            # The tree unmutated passed once: the same tree, the same tests.
            baseline=skip
            cp -r "$work/$name/mutants.out" "$out/$name"
        fi
    done
fi
.ci/mutants-summary.sh "$out" | tee "$out/summary.csv"
