#!/usr/bin/env python3
"""ARCHITECTURE.md kept true, mechanically.

Checks three things and prints every miss:

1. every path in the tree at the top of ARCHITECTURE.md exists;
2. every module a crate's table or list in docs/modules.md (the module index) names (`name`, `folder/`, `parent/child`; in the
   kinematics crate a module is named without its layer) is a file or folder of that
   crate, and every `stewart_<crate>::a::b::C` path the text names leads through modules
   that exist to an item the last of them defines or re-exports;
3. every module declared `pub` or `pub(crate)` in each crate is named: a crate's top-level modules
   (for the kinematics crate each layer's modules) by a row of its table, a module inside
   another by the row of its parent (or an ancestor's) (`child`, `parent/child.rs` or `child/` there).

and the rules it states, on the code:

4. no two modules of a crate import each other (a crate's top-level modules, and the
   parts of its big folders: the kinematics layers' modules, the app's `viewer/` and
   `commands/`), directly or round a longer circle;
5. nothing in the viewer's state, panels, tools or 3D view imports the window shell
   (`viewer/window`), which hosts them;
6. the top-level folders are reached only by their owners: `shaders/` by the renderer's
   `shaders.rs`, `assets/` by the presets' loader, `tests/` by no crate;
7. the crates' walls: the renderer depends on no UI crate (egui, winit), the link crate
   on no kinematics, the kinematics crate on no GPU, UI or other crate of ours;
8. one module style: no `foo.rs` beside a `foo/` folder (a module with parts is a folder
   with `mod.rs`).

Exits 1 on any miss; run by scripts/check.sh.
"""

import pathlib
import re
import sys
import tomllib

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = ROOT / "ARCHITECTURE.md"
# The module index ARCHITECTURE.md points to: the crates' tables.
INDEX = ROOT / "docs" / "modules.md"
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


# Rule 4: the parts of these folders are the units a circle is looked for between.
FOLDERS_OF_PARTS = {"model", "solve", "analysis", "io", "ground", "viewer", "commands"}
# Rule 5: the shell, and the folders that may not import it.
SHELL = "crate::viewer::window"
BELOW_SHELL = ["viewer/state", "viewer/panels", "viewer/tools", "viewer/view3d"]
# Rule 6: who may reach each top-level folder (paths from the repository's root).
TOP_FOLDER_READERS = {
    "shaders": {"crates/stewart_render/src/shaders.rs"},
    "assets": {"crates/stewart_kinematics/src/io/scenario/presets.rs"},
    "tests": set(),
}
# Rule 7: dependencies a crate may not have.
FORBIDDEN_DEPENDENCIES = {
    "stewart_render": {"egui", "egui-wgpu", "egui_plot", "winit"},
    "stewart_link": {"stewart_kinematics"},
    "stewart_kinematics": {"wgpu", "egui", "winit", "stewart_render", "stewart_link"},
}


def code_of(path):
    """A source file without its tests (`#[cfg(test)] mod … {` to the end), comments and
    documentation-only imports."""
    text = path.read_text(encoding="utf-8")
    m = re.search(r"#\[cfg\(test\)\]\s*mod \w+\s*\{", text)
    if m:
        text = text[: m.start()]
    text = re.sub(r"#\[cfg\(doc\)\]\s*use [^;]*;", "", text)
    return "\n".join(l for l in text.splitlines() if not l.lstrip().startswith("//"))


def unit_of(src, parts):
    """The unit (module, or part of a big folder) a path of module names belongs to."""
    top = parts[0]
    if top in FOLDERS_OF_PARTS and len(parts) > 1 and parts[1] != "mod":
        return f"{top}/{parts[1]}"
    return top


def circles():
    """Rule 4: each crate's circles of imports between its units."""
    misses = []
    for crate in CRATES.values():
        src = ROOT / "crates" / crate / "src"
        imports = {}
        for f in src.rglob("*.rs"):
            rel = f.relative_to(src).with_suffix("").parts
            if rel[-1] == "tests" or "tests" in rel[:-1] or "ui_tests" in rel or rel[0] in ("lib", "main"):
                continue
            here = unit_of(src, rel)
            for m in re.finditer(r"\bcrate::(\w+)(?:::(\w+))?", code_of(f)):
                named = [m.group(1)] + ([m.group(2)] if m.group(2) else [])
                if len(named) == 2 and not module_file(src, "/".join(named)):
                    named = named[:1]
                there = unit_of(src, named)
                if there != here and not here.startswith(there + "/") and not there.startswith(here + "/"):
                    imports.setdefault(here, set()).add(there)
        # Tarjan's strongly connected components.
        index, low, stack, on, order = {}, {}, [], set(), [0]

        def visit(v):
            index[v] = low[v] = order[0]
            order[0] += 1
            stack.append(v)
            on.add(v)
            for w in imports.get(v, ()):
                if w not in index:
                    visit(w)
                    low[v] = min(low[v], low[w])
                elif w in on:
                    low[v] = min(low[v], index[w])
            if low[v] == index[v]:
                component = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    component.append(w)
                    if w == v:
                        break
                if len(component) > 1:
                    misses.append(f"{crate}: {', '.join(sorted(component))} import each other")

        for v in sorted(imports):
            if v not in index:
                visit(v)
    return misses


def shell_imports():
    """Rule 5: imports of the window shell from below it."""
    src = ROOT / "crates" / "stewart_app" / "src"
    misses = []
    for folder in BELOW_SHELL:
        for f in sorted((src / folder).rglob("*.rs")):
            if "ui_tests" in f.parts:
                continue
            for number, line in enumerate(code_of(f).splitlines(), 1):
                if SHELL in line:
                    misses.append(f"{f.relative_to(ROOT)}:{number} imports the window shell")
    return misses


def top_folder_readers():
    """Rule 6: every path into a top-level folder, from any crate's sources."""
    misses = []
    literal = re.compile(r"(?:\.\./)+(shaders|assets|tests)/")
    for f in sorted((ROOT / "crates").rglob("*.rs")):
        if "target" in f.parts:
            continue
        rel = str(f.relative_to(ROOT))
        crate_dir = ROOT / "crates" / f.relative_to(ROOT / "crates").parts[0]
        for m in literal.finditer(code_of(f)):
            folder = m.group(1)
            target = ROOT / folder
            reached = any(
                (base / m.group(0)).resolve() == target.resolve() for base in (f.parent, crate_dir)
            )
            if reached and rel not in TOP_FOLDER_READERS[folder]:
                misses.append(f"{rel} reaches the top-level {folder}/ (only {sorted(TOP_FOLDER_READERS[folder]) or 'no crate'} may)")
    return misses


def walls():
    """Rule 7: the dependencies each crate may not have (read as TOML: `x = …`,
    `x.workspace = true` and `[dependencies.x]` alike)."""
    misses = []
    for crate, forbidden in FORBIDDEN_DEPENDENCIES.items():
        manifest = tomllib.loads((ROOT / "crates" / crate / "Cargo.toml").read_text(encoding="utf-8"))
        for table in ("dependencies", "build-dependencies"):
            for name in manifest.get(table, {}):
                if name in forbidden:
                    misses.append(f"{crate} depends on {name}")
    return misses


def one_module_style():
    """Rule 8: a file `foo.rs` beside a folder `foo/` in any crate's sources."""
    misses = []
    for crate in CRATES.values():
        for f in sorted((ROOT / "crates" / crate / "src").rglob("*.rs")):
            if f.with_suffix("").is_dir():
                misses.append(f"{f.relative_to(ROOT)} sits beside its folder: make it the folder's mod.rs")
    return misses


def main():
    text = DOC.read_text(encoding="utf-8")
    index = INDEX.read_text(encoding="utf-8")
    misses = []

    # 1. The tree.
    tree = text.split("```")[1]
    for line in tree.splitlines():
        # A top-level path at the margin, a crate's folder two spaces in (deeper lines
        # continue a description).
        indent = len(line) - len(line.lstrip())
        token = line.split()[0] if line.strip() and indent <= 2 else None
        if token and (token.endswith("/") or "." in token):
            path = ROOT / token
            if not path.exists() and token.count("/") == 1:
                # A crate's folder, listed under `crates/`.
                path = ROOT / "crates" / token
            if not path.exists():
                misses.append(f"the tree names {token}, which does not exist")

    # 2 and 3, per crate section.
    sections = re.split(r"^## The (\w+) crate$", index, flags=re.M)
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
            misses.append(f"{crate}'s public module {module} is not named in docs/modules.md")

    # `stewart_<crate>::a::b` paths in the text.
    for m in re.finditer(r"\b(stewart_(?:kinematics|link|render|app))((?:::[A-Za-z_0-9]+)+)", text + index):
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

    misses += circles() + shell_imports() + top_folder_readers() + walls() + one_module_style()

    for miss in misses:
        print(miss)
    if misses:
        print(f"architecture-check: {len(misses)} claims of ARCHITECTURE.md are not true", file=sys.stderr)
        sys.exit(1)
    print(
        "architecture-check: the tree of ARCHITECTURE.md and every module docs/modules.md names "
        "exist, every public module is named, and its rules hold (no import circles, the shell "
        "imported only from above, the top-level folders reached by their owners, the crates' "
        "walls, one module style)"
    )


main()
