#!/usr/bin/env python3
"""ARCHITECTURE.md kept true, mechanically.

Checks three things and prints every miss:

1. every path in the tree at the top of ARCHITECTURE.md exists;
2. every module a crate's table or list names (`name`, `folder/`, `parent/child`; in the
   kinematics crate a module is named without its layer) is a file or folder of that
   crate, and every `stewart_<crate>::a::b::C` path the text names leads through modules
   that exist to an item the last of them defines or re-exports;
3. every module declared `pub` or `pub(crate)` in each crate is named: a crate's top-level modules
   (for the kinematics crate each layer's modules) by a row of its table, a module inside
   another by the row of its parent (or an ancestor's) (`child`, `parent/child.rs` or `child/` there).

Exits 1 on any miss; run by scripts/check.sh.
"""

import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "ARCHITECTURE.md"
CRATES = {
    "kinematics": "stewart_kinematics",
    "link": "stewart_link",
    "render": "stewart_render",
    "app": "stewart_app",
}
LAYERS = ["ground", "model", "solve", "analysis", "io"]


def module_file(src, path):
    """The file of module `path` (slash-separated) under `src`, or None."""
    for candidate in (src / f"{path}.rs", src / path / "mod.rs"):
        if candidate.exists():
            return candidate
    return None


def resolve(crate, name):
    """Module `name` as the table names it → its path under src (layer added), or None."""
    src = ROOT / "crates" / crate / "src"
    name = name.rstrip("/")
    if module_file(src, name):
        return name
    if crate == "stewart_kinematics":
        for layer in LAYERS:
            if module_file(src, f"{layer}/{name}"):
                return f"{layer}/{name}"
    return None


def public_modules(crate):
    """Every `pub mod` of `crate`, as slash-separated paths under src."""
    src = ROOT / "crates" / crate / "src"
    found = []
    for f in sorted(src.rglob("*.rs")):
        for m in re.finditer(r"^\s*pub(?:\(crate\))? mod (\w+);", f.read_text(encoding="utf-8"), re.M):
            rel = f.relative_to(src)
            parent = rel.parent if rel.name in ("mod.rs", "lib.rs", "main.rs") else rel.with_suffix("")
            found.append(str(parent / m.group(1)).removeprefix("./"))
    return found


def main():
    text = DOC.read_text(encoding="utf-8")
    misses = []

    # 1. The tree.
    tree = text.split("```")[1]
    for line in tree.splitlines():
        token = line.split()[0] if line.strip() and not line.startswith(" ") else None
        if token and (token.endswith("/") or "." in token):
            path = ROOT / token
            if not path.exists() and token.count("/") == 1:
                # A crate's folder, listed under `crates/`.
                path = ROOT / "crates" / token
            if not path.exists():
                misses.append(f"the tree names {token}, which does not exist")

    # 2 and 3, per crate section.
    sections = re.split(r"^## The (\w+) crate$", text, flags=re.M)
    named_rows = {}
    for k in range(1, len(sections), 2):
        crate = CRATES[sections[k]]
        rows = {}
        for line in sections[k + 1].splitlines():
            if not line.startswith("| `"):
                continue
            first, rest = line[2:].split(" | ", 1)
            for name in re.findall(r"`([a-z_0-9/]+)`", first):
                where = resolve(crate, name)
                if where is None:
                    misses.append(f"the {sections[k]} crate's table names `{name}`, which is not a module")
                else:
                    rows[where] = rest
            # The bullets' modules (`name`, `name/`) are modules of this crate too.
        for line in sections[k + 1].splitlines():
            if not line.lstrip().startswith("- `"):
                continue
            for name in re.findall(r"`([a-z_0-9]+/?)`", line):
                if resolve(crate, name) is None:
                    misses.append(f"the {sections[k]} crate's list names `{name}`, which is not a module")
        named_rows[crate] = rows
    for crate, rows in named_rows.items():
        for module in public_modules(crate):
            parts = module.split("/")
            if crate == "stewart_kinematics" and len(parts) == 1:
                continue  # the layers, named by the section's list
            if module in rows:
                continue
            named = False
            for depth in range(len(parts) - 1, 0, -1):
                ancestor, below = "/".join(parts[:depth]), "/".join(parts[depth:])
                child = re.compile(r"`(?:[a-z_0-9/]*/)?" + below + r"(?:\.rs|/)?`")
                if ancestor in rows and child.search(rows[ancestor]):
                    named = True
                    break
            if named:
                continue
            misses.append(f"{crate}'s public module {module} is not named in ARCHITECTURE.md")

    # `stewart_<crate>::a::b` paths in the text.
    for m in re.finditer(r"\b(stewart_(?:kinematics|link|render|app))((?:::[A-Za-z_0-9]+)+)", text):
        crate, segments = m.group(1), m.group(2).strip(":").split("::")
        src = ROOT / "crates" / crate / "src"
        path, file, rest = "", src / "lib.rs", []
        for k, seg in enumerate(segments):
            found = module_file(src, f"{path}/{seg}".lstrip("/"))
            if found:
                path, file = f"{path}/{seg}".lstrip("/"), found
            else:
                rest = segments[k:]
                break
        if rest:
            # The first segment past the modules is an item the module defines or re-exports.
            source = file.read_text(encoding="utf-8")
            item = re.escape(rest[0])
            defined = re.search(
                rf"\b(?:fn|struct|enum|type|trait|const|static|mod)\s+{item}\b", source
            ) or re.search(rf"^\s*pub use [^;]*\b{item}\b[^;]*;", source, re.M)
            if not defined:
                misses.append(f"`{m.group(0)}`: {crate}::{path.replace('/', '::')} has no item {rest[0]}")

    for miss in misses:
        print(miss)
    if misses:
        print(f"architecture-check: {len(misses)} claims of ARCHITECTURE.md are not true", file=sys.stderr)
        sys.exit(1)
    print("architecture-check: every module ARCHITECTURE.md names exists and every public module is named")


main()
