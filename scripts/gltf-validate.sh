#!/usr/bin/env bash
# Check glTF files (.glb, or .gltf with its .bin beside it) with the Khronos glTF-Validator:
#   bash scripts/gltf-validate.sh FILE...
# One line a file (its numbers of errors, warnings, infos and hints), then a line for each
# error and warning (code, message, JSON pointer). Exits non-zero when a file has an error
# or cannot be read; warnings are printed but allowed.
# Needs Node 18 or newer (scripts/setup.sh installs it). The validator (npm package
# `gltf-validator`, the version below) is fetched once into target/gltf-validator/
# (git-ignored with target/) and used from there on later runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
version=2.0.0-dev.3.10
integrity=sha512-odJ4k0tRkGXiDGn78yDBg+fBbAIvBnXxh3RwAta0emSxGtyagFE8B4xELB1oYe3S5RD8Ci3uZAsZaascH2LAEQ==
cache="$root/target/gltf-validator"
module="$cache/node_modules/gltf-validator"

if [ $# -eq 0 ]; then
  echo "usage: bash scripts/gltf-validate.sh FILE..." >&2
  exit 2
fi
command -v node >/dev/null || { echo "gltf-validate: node not found: run scripts/setup.sh" >&2; exit 1; }

if ! grep -qF "\"version\": \"$version\"" "$module/package.json" 2>/dev/null; then
  echo "gltf-validate: fetching gltf-validator $version into target/gltf-validator/" >&2
  # The package is one file with no dependencies: its tarball is fetched from the npm
  # registry, checked against the registry's published SHA-512 and unpacked beside, then
  # moved into place (an interrupted fetch leaves no half a cache). No npm needed.
  mkdir -p "$root/target"
  tmp=$(mktemp -d "$cache.tmp.XXXXXX")
  trap 'rm -rf "$tmp"' EXIT
  python3 - "$tmp" "$version" "$integrity" <<'PY'
import base64, hashlib, io, sys, tarfile, urllib.request
folder, version, integrity = sys.argv[1:4]
url = f"https://registry.npmjs.org/gltf-validator/-/gltf-validator-{version}.tgz"
data = urllib.request.urlopen(url, timeout=60).read()
digest = "sha512-" + base64.b64encode(hashlib.sha512(data).digest()).decode()
if digest != integrity:
    sys.exit(f"gltf-validate: {url} does not match its published SHA-512")
with tarfile.open(fileobj=io.BytesIO(data)) as tar:
    for member in tar.getmembers():
        if not member.name.startswith("package/") or ".." in member.name or not (member.isfile() or member.isdir()):
            sys.exit(f"gltf-validate: unexpected entry {member.name} in the tarball")
        member.name = "node_modules/gltf-validator/" + member.name[len("package/"):]
        tar.extract(member, folder)
PY
  rm -rf "$cache"
  mv "$tmp" "$cache"
  trap - EXIT
fi

exec node "$root/scripts/gltf-validate.cjs" "$module" "$@"
