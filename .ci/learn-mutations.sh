#!/usr/bin/env bash
# Makes each of learn mode's claims false once (docs/learn.md#mutations-tried): applies a
# mutation, runs tests/suite/learn.rs, prints the tests that failed, and puts the file back with
# git checkout (so run it on a clean tree). Run: bash .ci/learn-mutations.sh
set -uo pipefail
cd "$(dirname "$0")/.."
git diff --quiet || { echo "the tree has changes: commit them first"; exit 1; }
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/rubber-band-box/target}"
run() {
  local name="$1" file="$2" from="$3" to="$4"
  python3 - "$file" "$from" "$to" <<'PY'
import sys
p,a,b=sys.argv[1:4]
s=open(p).read()
assert a in s, (p,a)
s=s.replace(a,b,1)
open(p,'w').write(s)
PY
  echo "== $name"
  timeout 900 cargo test --no-fail-fast --test suite learn:: 2>&1 | grep -E "^test .*FAILED|error\[|test result"
  git checkout -q "$file"
}
run "the diagonal pull off the diagonal by 10 px" src/physics/scenes.rs "vec![(0.0, held, DVec2::new(150.0, 150.0))]" "vec![(0.0, held, DVec2::new(150.0, 140.0))]"
run "no angular damping torque" src/physics/forces.rs "torque: -angular_damping * mass.inertia() * state.angular.angular_velocity," "torque: 0.0 * angular_damping * mass.inertia() * state.angular.angular_velocity,"
run "the seed moves x with the old v" src/physics/integrators/seed.rs "    after.linear.velocity += acceleration * dt;
    after.linear.position += after.linear.velocity * dt;" "    after.linear.position += after.linear.velocity * dt;
    after.linear.velocity += acceleration * dt;"
run "the band always takes the first corner" src/physics/body.rs "            if distance < best_distance {" "            if distance < best_distance && distance < 0.0 {"
run "the twin turns with the box" src/game/learn/twin.rs "                angular_velocity: 0.0," "                angular_velocity: state.angular.angular_velocity,"
run "the held corner's experiment says it moved" src/game/learn/experiments.rs "        Some(0),
        format!(
            \"the band held" "        Some(1),
        format!(
            \"the band held"
