"""Reading a program file for a command: its diagnostics on stderr when it does not parse."""

from __future__ import annotations

import sys

from ladderworks.core.il import Program, parse_file


def load_program(name: str) -> Program | None:
    """The program in file `name`, or None after printing why it does not parse."""
    result = parse_file(name)
    if not result.ok:
        for diagnostic in result.diagnostics:
            print(diagnostic.located(name), file=sys.stderr)
        return None
    return result.program
