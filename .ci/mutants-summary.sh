#!/usr/bin/env bash
# Prints a mutation run's score as CSV, a row a group and a row for them all: DIR holds one
# folder a group, each cargo-mutants' output (its caught.txt, missed.txt, timeout.txt and
# unviable.txt). .ci/mutants.sh writes it beside its results as summary.csv; docs/testing.md
# shows the committed snapshot's (docs/snapshots/). A mutant that hangs the tests (a timeout)
# is caught: the score is (caught + timeout) / viable.
# Usage: .ci/mutants-summary.sh DIR
set -euo pipefail
count() { if [ -f "$1" ]; then grep -c . "$1" || true; else echo 0; fi; }
# The percentage of CAUGHT in VIABLE, one decimal.
score() { awk -v c="$1" -v v="$2" 'BEGIN { printf "%.1f", v ? 100 * c / v : 0 }'; }
echo "group,mutants,unviable,viable,caught,missed,timeout,score_percent"
totals=(0 0 0 0 0 0)
for dir in "$1"/*/; do
    [ -f "$dir/caught.txt" ] || continue
    caught=$(count "$dir/caught.txt")
    missed=$(count "$dir/missed.txt")
    timeout=$(count "$dir/timeout.txt")
    unviable=$(count "$dir/unviable.txt")
    viable=$((caught + missed + timeout))
    row=($((viable + unviable)) "$unviable" "$viable" "$caught" "$missed" "$timeout")
    for i in "${!row[@]}"; do totals[i]=$((totals[i] + row[i])); done
    echo "$(basename "$dir"),$(IFS=,; echo "${row[*]}"),$(score $((caught + timeout)) "$viable")"
done
echo "all,$(IFS=,; echo "${totals[*]}"),$(score $((totals[3] + totals[5])) "${totals[2]}")"
