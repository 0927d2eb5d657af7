#!/usr/bin/env bash
# Lines of non-test source that decide the actuator kind (issue #28: one abstraction keeps this small).
# Usage: scripts/actuator-sites.sh [REPO_ROOT] — prints file: line: text; pipe to wc -l to count.
# The abstraction itself (model/actuator.rs, solve/actuation.rs) and the servo kind's own
# module (model/rotary.rs) are listed last, after a `-- the abstraction --` line.
cd "${1:-.}"
home='crates/stewart_kinematics/src/(model/actuator|solve/actuation|model/rotary)\.rs'
sites() {
  find crates -name '*.rs' ! -name 'tests.rs' ! -name '*_tests.rs' ! -path '*/tests/*' ! -path '*/benches/*' | sort | while read -r f; do
    awk -v f="$f" '/#\[cfg\(test\)\]/{exit} /\.rotary\(\)|Actuator::(Linear|Rotary)|ActuatorKind::(Linear|Rotary)|\bis_rotary\b/{print f": "FNR": "$0}' "$f"
  done
}
all=$(sites)
grep -Ev "^$home:" <<<"$all"
echo "-- the abstraction --"
grep -E "^$home:" <<<"$all"
