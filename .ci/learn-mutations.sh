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
run "the held corner's experiment says it moved" src/game/learn/experiments.rs "let outcome = usize::from(band.local_point != first);" "let outcome = usize::from(band.local_point == first);"
run "the torque's components swapped" src/physics/forces.rs "torque: arm.perp_dot(force)," "torque: force.perp_dot(arm),"
run "the rotation turned the wrong way" src/physics/body.rs "DVec2::new(cos * v.x - sin * v.y, sin * v.x + cos * v.y)" "DVec2::new(cos * v.x + sin * v.y, -sin * v.x + cos * v.y)"
run "I of a square, whatever the box" src/physics/body.rs "let inertia = mass * (size.x * size.x + size.y * size.y) / 12.0;" "let inertia = mass * (2.0 * size.x * size.x) / 12.0;"
run "the seed's damping without the division by m" src/physics/integrators/seed.rs "start.damping.force * mass.inverse_mass()" "start.damping.force"
