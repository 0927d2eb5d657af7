#!/usr/bin/env python3
"""Run every command README.md and the user guide (docs/guide/*.md) show.

Each ```sh block is run by bash (`set -euo pipefail`: a command that fails inside a pipe
fails the block) as a reader would type it, from a scratch
folder that holds links to the repository's `examples/`, `crates/` and `docs/` (so the
paths the docs name resolve and nothing is written into the tree), with the release
`stewart` (or the debug one) first on PATH. The blocks of one file share their folder, in order (a later
block may read what an earlier one wrote). A block is skipped only when an HTML comment
on the line before it says `not run: <why>` (an interactive window, hardware, a network
peer), or when it is the README's two commands (setup and this very suite); one marked
`run under Xvfb: <why>` runs inside `xvfb-run` (the viewer's screenshots). Any failing block
fails the run with its file, line and output.

Usage: tests/docs/commands.py [--list] [--debug]   (needs `cargo build [--release]` first: --debug
runs target/debug/stewart, as scripts/check.sh does after the tests built it)
"""

import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
BLOCK = re.compile(r"(?:<!--\s*((?:not run|run under Xvfb):[^>]*)-->\n)?```sh\n(.*?)```", re.S)
# The README's two commands: the setup, and the suite this script is part of.
SELF = ("scripts/check.sh", "scripts/setup.sh")


def blocks(path):
    text = path.read_text(encoding="utf-8")
    for m in BLOCK.finditer(text):
        line = text.count("\n", 0, m.start()) + 1
        yield line, m.group(1), m.group(2)


def main():
    listing = "--list" in sys.argv
    profile = "debug" if "--debug" in sys.argv else "release"
    binary = ROOT / "target" / profile / "stewart"
    if not listing and not binary.exists():
        sys.exit(f"docs-commands: build {binary} first (cargo build{'' if profile == 'debug' else ' --release'})")
    env = dict(os.environ, PATH=f"{binary.parent}:{os.environ['PATH']}")
    files = [ROOT / "README.md"] + sorted((ROOT / "docs/guide").glob("*.md"))
    ran = skipped = 0
    failures = []
    for path in files:
        with tempfile.TemporaryDirectory(prefix="docs-") as scratch:
            for name in ("examples", "crates", "docs", "assets", "shaders", "tests"):
                os.symlink(ROOT / name, pathlib.Path(scratch) / name)
            for line, skip, body in blocks(path):
                where = f"{path.relative_to(ROOT)}:{line}"
                xvfb = bool(skip) and skip.startswith("run under Xvfb")
                two_commands = path.name == "README.md" and any(s in body for s in SELF)
                if (skip and not xvfb) or two_commands:
                    skipped += 1
                    print(f"skip {where}: {skip or 'the two commands'}")
                    continue
                if listing:
                    print(f"run  {where}:\n{body}")
                    continue
                start = time.monotonic()
                ran += 1
                try:
                    done = subprocess.run(
                        (["xvfb-run", "-a"] if xvfb else [])
                        + ["bash", "-c", "set -euo pipefail\n" + body],
                        cwd=scratch,
                        env=env,
                        capture_output=True,
                        text=True,
                        timeout=900,
                    )
                except (OSError, subprocess.TimeoutExpired) as e:
                    failures.append(f"{where}: {e}\n{body}")
                    print(f"ran  {where}: {e}")
                    continue
                print(f"ran  {where} in {time.monotonic() - start:.1f} s: exit {done.returncode}")
                if done.returncode != 0:
                    output = done.stdout[-2000:] + done.stderr[-2000:]
                    failures.append(f"{where}: exit {done.returncode}\n{body}{output}")
    for failure in failures:
        print(f"\nFAILED {failure}", file=sys.stderr)
    print(f"docs-commands: {ran} blocks ran, {skipped} skipped, {len(failures)} failed")
    sys.exit(1 if failures else 0)


main()
