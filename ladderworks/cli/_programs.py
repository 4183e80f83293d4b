"""Reading a program file for a command: its diagnostics on stderr when it does not parse.

`--dialect NAME` (each command that reads a program has it) names the reader and skips the
content sniffing (core/il/reading.py); the command's handler sets it with `use_dialect`.
"""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from ladderworks.core.il import Program, parse_file

if TYPE_CHECKING:
    from ladderworks.core.il.parser import ParseResult

_forced: list[str | None] = [None]  # the command's --dialect
_parsed: dict[tuple[str, str | None], ParseResult] = {}


def add_dialect_option(parser: argparse.ArgumentParser) -> None:
    """Add `--dialect NAME` to a command that reads programs."""
    parser.add_argument("--dialect", metavar="NAME",
                        help="read programs as this dialect (delta, fatek, pmc); "
                             "default: recognised from the content")


def add_every_scan_option(parser: argparse.ArgumentParser) -> None:
    """Add `--every-scan` to a command that runs a program on the virtual clock."""
    parser.add_argument("--every-scan", action="store_true",
                        help="run every scan; by default the scans of a state that repeats "
                             "are skipped, with the same results (docs/engine.md)")


def add_backend_option(parser: argparse.ArgumentParser) -> None:
    """Add `--backend python|native` to a command that runs a program."""
    parser.add_argument("--backend", choices=("python", "native"), default=None,
                        help="the scan's code: generated Python (default) or native machine "
                             "code compiled with llvmlite; given, a line on stderr says which "
                             "ran, and why Python ran where native could not (docs/engine.md)")


def backend_note(used: str | None, reason: str | None, asked: str | None) -> str | None:
    """The line saying which scan's code ran (`used`), when --backend was given (`asked`);
    with the reason when native was asked for and the Python scan ran. None: say nothing."""
    if asked is None or used is None:
        return None
    if used == "native":
        return "the native scan runs"
    if asked == "native" and reason:
        return f"the Python scan runs: {reason}"
    return "the Python scan runs"


def use_dialect(args: argparse.Namespace) -> None:
    """Take the command's --dialect for the programs it reads (cli.main, before the command)."""
    _forced[0] = getattr(args, "dialect", None)
    _parsed.clear()


def forced_dialect() -> str | None:
    """The dialect named by --dialect, or None."""
    return _forced[0]


def parsed(name: str) -> ParseResult:
    """The parse of file `name` (read once per command), in the forced dialect if any."""
    key = (name, _forced[0])
    found = _parsed.get(key)
    if found is None:
        found = _parsed[key] = parse_file(name, _forced[0])
    return found


def load_program(name: str) -> Program | None:
    """The program in file `name`, or None after printing why it does not parse."""
    result = parsed(name)
    if not result.ok:
        for diagnostic in result.diagnostics:
            print(diagnostic.located(name), file=sys.stderr)
        return None
    return result.program
