#!/usr/bin/env bash
# Lines of non-test source that decide the actuator kind (issue #28: one abstraction keeps this small).
# Usage: scripts/actuator-sites.sh [REPO_ROOT] — prints file: line: text; pipe to wc -l to count.
cd "${1:-.}"
find crates -name '*.rs' ! -name 'tests.rs' ! -name '*_tests.rs' ! -path '*/tests/*' ! -path '*/benches/*' | sort | while read -r f; do
  awk -v f="$f" '/#\[cfg\(test\)\]/{exit} /\.rotary\(\)|Actuator::(Linear|Rotary)|ActuatorKind::(Linear|Rotary)|\bis_rotary\b/{print f": "FNR": "$0}' "$f"
done
