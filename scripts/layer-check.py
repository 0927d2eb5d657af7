#!/usr/bin/env python3
"""The kinematics core's layers as walls: model -> solve -> analysis, io beside.

Every `crate::NAME` a file of one layer names is mapped to the layer NAME lives in (its
folder under crates/stewart_kinematics/src); a name in a higher layer is an import that
goes up a layer: model may name model only; solve model and solve; analysis model, solve
and analysis; io any of them (it reads and writes what the others define). Each such
import is printed with its file and line; `impl Geometry` blocks are refused anywhere but
`model/geometry.rs` (what the platform is) and `solve/queries.rs` (the one file of the
platform's per-pose queries).

The ground (`ground::bounds`, `ground::text`) is below every layer; the exceptions
listed below (docs/modules.md says why) are not counted; nor are tests (`tests.rs`, `tests/`, and what `#[cfg(test)]` guards).
An `impl Geometry` counts in any form, an extension trait's `impl Trait for Geometry` too.

Usage: layer-check.py [--max N]. Exits 1 when the count of upward imports and calls is
over N (default 0, as scripts/check.sh runs it).
"""

import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent / "crates/stewart_kinematics/src"
LAYERS = ["ground", "model", "solve", "analysis", "io"]
# What each layer may name besides itself: the layers below it, and the ground (the
# accepted ranges and the input-text rules) under every one.
ALLOWED = {
    "ground": {"ground"},
    "model": {"ground", "model"},
    "solve": {"ground", "model", "solve"},
    "analysis": {"ground", "model", "solve", "analysis"},
    "io": {"ground", "model", "solve", "analysis", "io"},
}
# The exceptions docs/modules.md lists and says why: (file under src/, module named).
EXCEPTIONS = {
    ("model/trajectory/pose_table.rs", "table"),
    ("analysis/cueing/mod.rs", "table"),
    ("analysis/calibration/apply.rs", "scenario"),
}


def without_tests(text):
    """`text` without what `#[cfg(test)]` guards: an inline `mod tests { … }` (to its
    matching brace) or a one-line item (`mod tests;`); the code around it stays."""
    out = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].strip() != "#[cfg(test)]":
            out.append(lines[i])
            i += 1
            continue
        i += 1
        while i < len(lines) and not lines[i].strip():
            i += 1
        if i < len(lines) and "{" not in lines[i]:
            i += 1
            continue
        depth = 0
        while i < len(lines):
            depth += lines[i].count("{") - lines[i].count("}")
            i += 1
            if depth <= 0:
                break
    return "\n".join(out)


IMPL_GEOMETRY = re.compile(r"\s*impl\b(?:\s*<[^>]*>)?\s+(?:[\w:]+(?:<[^>]*>)?\s+for\s+)?Geometry\b")


def module_layers():
    """Each module name (a file or folder directly in a layer's folder) -> its layer."""
    found = {}
    for layer in LAYERS:
        for entry in (ROOT / layer).iterdir():
            name = entry.stem if entry.suffix == ".rs" else entry.name
            if name != "mod":
                found[name] = layer
    return found


def impl_methods(path):
    """The methods defined in the `impl Geometry` blocks of `path` (brace counting)."""
    names = set()
    depth = None
    for line in without_tests(path.read_text(encoding="utf-8")).splitlines():
        if depth is None:
            if IMPL_GEOMETRY.match(line):
                depth = line.count("{") - line.count("}")
            continue
        if depth == 1:
            m = re.match(r"\s*(?:pub(?:\([a-z]+\))?\s+)?(?:const\s+)?fn\s+([a-z_][a-z0-9_]*)", line)
            if m:
                names.add(m.group(1))
        depth += line.count("{") - line.count("}")
        if depth <= 0:
            depth = None
    return names


def main():
    limit = 0
    if len(sys.argv) == 3 and sys.argv[1] == "--max":
        limit = int(sys.argv[2])
    layers = module_layers()
    name = re.compile(r"\bcrate::(?:(ground|model|solve|analysis|io)::)?([a-z_][a-z0-9_]*)")
    upward = []
    impls = []
    for layer in LAYERS:
        for path in sorted((ROOT / layer).rglob("*.rs")):
            # Tests may use any layer.
            if path.name == "tests.rs" or "tests" in path.relative_to(ROOT).parts[:-1]:
                continue
            here = str(path.relative_to(ROOT))
            text = path.read_text(encoding="utf-8")
            # Tests may reach anywhere: only the code above `#[cfg(test)]` counts.
            code = without_tests(text)
            for number, line in enumerate(code.splitlines(), 1):
                if line.lstrip().startswith("//"):
                    continue
                for m in name.finditer(line):
                    module = m.group(2)
                    if (here, module) in EXCEPTIONS:
                        continue
                    target = m.group(1) or layers.get(module)
                    if target and target not in ALLOWED[layer]:
                        rel = path.relative_to(ROOT.parent.parent.parent)
                        upward.append(f"{rel}:{number}: {layer} names {target} ({m.group(0)})")
                if here != "model/geometry.rs" and IMPL_GEOMETRY.match(line):
                    impls.append(str(path.relative_to(ROOT.parent.parent.parent)))
    # Methods of Geometry by the layer that defines them; a method defined in model too is
    # model's.
    defined = {layer: set() for layer in LAYERS}
    for layer in LAYERS:
        for path in (ROOT / layer).rglob("*.rs"):
            defined[layer] |= impl_methods(path)
    rank = {"ground": -1, "model": 0, "solve": 1, "analysis": 2, "io": 3}
    owner = {}
    for layer in sorted(LAYERS, key=lambda l: -rank[l]):
        for method in defined[layer]:
            owner[method] = layer
    call = re.compile(r"\.([a-z_][a-z0-9_]*)\(")
    for layer in ["model", "solve", "analysis"]:
        for path in sorted((ROOT / layer).rglob("*.rs")):
            code = without_tests(path.read_text(encoding="utf-8"))
            for number, line in enumerate(code.splitlines(), 1):
                if line.lstrip().startswith("//"):
                    continue
                for m in call.finditer(line):
                    target = owner.get(m.group(1))
                    if target and target not in ALLOWED[layer]:
                        rel = path.relative_to(ROOT.parent.parent.parent)
                        upward.append(f"{rel}:{number}: {layer} calls {target}'s Geometry::{m.group(1)}")
    files = sorted(set(impls))
    # Solve gives the platform its per-pose queries (ARCHITECTURE.md says why), all in
    # one file that hands each to the module computing it; no other layer adds methods:
    # analysis and io offer free functions.
    for file in files:
        if not file.endswith("/src/solve/queries.rs"):
            upward.append(f"{file}: `impl Geometry` outside model/geometry.rs and solve/queries.rs")
    for line in upward:
        print(line)
    print(
        f"{len(upward)} imports or calls go up a layer; "
        f"`impl Geometry` outside model/ in {len(files)} files"
    )
    if len(upward) > limit:
        print(
            f"layer-check: {len(upward)} go up a layer, more than the {limit} allowed "
            "(see ARCHITECTURE.md: model -> solve -> analysis, io beside)",
            file=sys.stderr,
        )
        sys.exit(1)


main()
