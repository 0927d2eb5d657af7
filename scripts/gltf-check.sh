#!/usr/bin/env bash
# Every preset's trajectory and the CAD examples exported as animated glTF (GLB, and one
# .gltf with its .bin), each checked by the Khronos glTF-Validator (0 errors required).
#   bash scripts/gltf-check.sh [--debug]     (the debug binary, as check.sh runs it)
set -euo pipefail
cd "$(dirname "$0")/.."
profile=release
[ "${1:-}" = "--debug" ] && profile=debug
if [ "$profile" = release ]; then cargo build --release -q -p stewart_app; fi
stewart="target/$profile/stewart"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
presets=$("$stewart" render --help | sed -n 's/.*A shipped preset: \(.*\)$/\1/p' | tr -d ',')
[ -n "$presets" ] || { echo "gltf-check: no presets found in stewart render --help" >&2; exit 1; }
files=()
for p in $presets; do
  "$stewart" render --preset "$p" --out "$out/$p.glb" 2>/dev/null
  files+=("$out/$p.glb")
done
"$stewart" render --preset servo-desk --theme light --out "$out/servo desk.gltf" 2>/dev/null
"$stewart" render --scenario examples/cad/seed-cad.toml --out "$out/seed-cad.glb" 2>/dev/null
"$stewart" render --scenario examples/cad/servo-cad.toml --out "$out/servo-cad.glb" 2>/dev/null
files+=("$out/servo desk.gltf" "$out/seed-cad.glb" "$out/servo-cad.glb")
echo "gltf-check: ${#files[@]} exports"
bash scripts/gltf-validate.sh "${files[@]}"
