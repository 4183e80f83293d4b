"""Try the S7 readers on a folder of exports as found: every block file and every folder.

    python benchmarks/s7_real_exports.py FOLDER [--quiet]

For each `.xml` / `.s7dcl` / `.db` file (and each folder holding some) it prints whether it
opened (no crash, no diagnostic that stops the reading), the entry block's networks — lowered
to the engine, shown as SCL/STL/GRAPH text, empty, or left out (LEFT_OUT) — and the diagnostics
counted by code; then the totals. The exports are never copied into the project: point it at
a folder outside (docs/dialects.md, "Real exports tried").
"""

from __future__ import annotations

import argparse
import sys
import traceback
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7 import opening

SUFFIXES = (".xml", ".s7dcl", ".db", ".udt", ".scl")
# a diagnostic with one of these codes means the file (or folder) was not read at all
FATAL = frozenset({"s7xml-empty", "s7xml-malformed", "s7xml-dtd", "s7xml-too-large",
                   "s7-syntax", "s7-cut", "s7-too-large", "s7-tags"})
# a diagnostic with one of these codes leaves its network out of the program (whatever its
# severity: an error before, a warning since "Real exports tried"); a shown-only part or call
# (s7-part-unknown, s7-call-unknown) or an undeclared tag leaves the rest of the network running
LEFT_OUT = frozenset({"s7-operand-unknown", "s7-pin-missing", "s7-wire", "s7-label-unknown",
                      "s7-type", "s7-memory-full", "s7xml-wire", "s7xml-loop", "s7xml-namespace",
                      "s7xml-too-many"})


@dataclass(slots=True)
class Tried:
    """What opening one file or folder gave."""

    name: str
    opened: bool = False
    crashed: str = ""
    networks: int = 0
    lowered: int = 0
    drawn: int = 0
    text: int = 0
    empty: int = 0
    failed: int = 0
    codes: Counter[str] = field(default_factory=Counter)


def _network_of(diagnostic: Diagnostic) -> int:
    found = diagnostic.args.get("network")
    return found if isinstance(found, int) else 0


def _drawn(program: object) -> int:
    """How many networks of the entry block draw as LAD (not kept as a listing); 0 where the
    code has no drawing of S7 networks (before s7draw)."""
    model = getattr(program, "model", None)
    draw = getattr(model, "draw", None)
    if draw is None:
        return 0
    return sum(1 for net in draw() if not net.listing and net.cells)


def try_one(path: Path) -> Tried:
    """Open `path` as File › Open would and sum up what came of it."""
    tried = Tried(str(path))
    try:
        program, diagnostics, _encoding = opening.open_path(path, None)
    except Exception as error:
        tried.crashed = f"{type(error).__name__}: {error}"
        traceback.print_exc(limit=3, file=sys.stderr)
        return tried
    tried.codes.update(d.code for d in diagnostics)
    tried.opened = not any(d.code in FATAL and d.severity is Severity.ERROR
                           for d in diagnostics)
    source = program.graph
    block = getattr(source, "block", None)
    if block is None:  # no code block (a DB or tag table alone): nothing to lower
        return tried
    try:
        tried.drawn = _drawn(program)
    except Exception as error:
        tried.crashed = f"drawing: {type(error).__name__}: {error}"
        traceback.print_exc(limit=3, file=sys.stderr)
    failing = {_network_of(d) for d in diagnostics
               if d.code in LEFT_OUT or (d.severity is Severity.ERROR and d.code not in FATAL)}
    for index, network in enumerate(block.networks, start=1):
        tried.networks += 1
        if network.language.upper() not in ("LAD", "FBD"):
            tried.text += 1
        elif not network.parts:
            tried.empty += 1
        elif index in failing:
            tried.failed += 1
        else:
            tried.lowered += 1
    return tried


def targets(root: Path) -> list[Path]:
    """Every export file under `root`, then every folder holding one."""
    files = sorted(p for p in root.rglob("*") if p.is_file() and p.suffix.lower() in SUFFIXES)
    folders = sorted({p.parent for p in files})
    return files + folders


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--quiet", action="store_true", help="totals only")
    args = parser.parse_args(argv)
    total = Tried("TOTAL")
    count = opened = crashed = 0
    for path in targets(args.folder):
        tried = try_one(path)
        count += 1
        opened += tried.opened
        crashed += bool(tried.crashed)
        for name in ("networks", "lowered", "drawn", "text", "empty", "failed"):
            setattr(total, name, getattr(total, name) + getattr(tried, name))
        total.codes.update(tried.codes)
        if not args.quiet:
            state = "CRASH " + tried.crashed if tried.crashed else \
                "opened" if tried.opened else "NOT OPENED"
            codes = ", ".join(f"{c}×{n}" for c, n in sorted(tried.codes.items()))
            where = path.relative_to(args.folder) if path != args.folder else Path(".")
            print(f"{where}: {state}; networks {tried.networks} (lowered {tried.lowered}, "
                  f"drawn {tried.drawn}, text {tried.text}, empty {tried.empty}, "
                  f"failed {tried.failed}); "
                  f"{codes or 'no diagnostics'}")
    print(f"TOTAL: {count} tried, {opened} opened, {crashed} crashed; networks "
          f"{total.networks} (lowered {total.lowered}, drawn {total.drawn}, text {total.text}, "
          f"empty {total.empty}, failed {total.failed})")
    for code, number in sorted(total.codes.items()):
        print(f"  {code}: {number}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
