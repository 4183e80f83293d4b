"""WinProladder's printed mnemonic form (`00001M SET( )   S3`, `T10 .01 R7`, `FUN 08 _.MOV`):
found in a file, and the plain lines of a changed network written in it (docs/dialects.md)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ladderworks.core.dialects.fatek.devices import timer_base_ms
from ladderworks.core.dialects.fatek.rows import BY_FUN

_STEP_RE = re.compile(r"^\s*(\d{3,9})([A-Za-z])\s+\S")
_PRINTED_RE = re.compile(r"(SET|RST)\(\s*\)|FUN\s*\d+\s*[D_]?[P_]?\.|^\s*\d+[A-Za-z]?\s+[TC]\d+\s",
                         re.I)
_FUN_RE = re.compile(r"^FUN (\d+)(D?)(P?)\s+(.*)$")
_CMP_RE = re.compile(r"^(ORG|LD|AND|OR)F (\d+)(D?)\s+\((.*)\)$")
_TMR_RE = re.compile(r"^TMR\s+T(\d+)\s+(\S+)$")
_CTR_RE = re.compile(r"^CTR\s+C(\d+)\s+(\S+)$")
_COIL_RE = re.compile(r"^(OUTS|OUTR|RST)\s+(\S+)$")
_OPERAND_RE = re.compile(r"^\s+([A-Za-z0-9]*)\s*:\s*(.*)$")
WIDTH = 8  # the mnemonic column after the step number


@dataclass(slots=True)
class PrintedStyle:
    """A file in WinProladder's printed form: its program unit letter, and the step number
    each line of a step starts with (a changed network goes on from its first line's)."""

    unit: str = "M"
    steps: dict[int, int] = field(default_factory=dict)  # 1-based line -> its step number

    def first_step(self, line: int) -> int:
        """The step a changed network starts at: its first line's, else the step after the
        nearest one above."""
        if line in self.steps:
            return self.steps[line]
        above = [n for n in self.steps if n < line] if line > 0 else list(self.steps)
        return self.steps[max(above)] + 1 if above else 0  # a new network: after the last


def style_of(lines: list[str]) -> PrintedStyle | None:
    """The printed form's style when the file is written so (a step column with the unit
    letter and WinProladder's spellings), else None (seed 002's plain form)."""
    steps: dict[int, int] = {}
    units: set[str] = set()
    printed = False
    for index, line in enumerate(lines):
        match = _STEP_RE.match(line)
        if match is None:
            continue
        steps[index + 1] = int(match.group(1))
        units.add(match.group(2).upper())
        printed = printed or _PRINTED_RE.search(line) is not None
    if not printed or not steps:
        return None
    return PrintedStyle(sorted(units)[0], steps)


def _forms(double: str, pulse: str) -> str:
    return (double + pulse) or "_"


def printed_line(line: str) -> tuple[str, bool]:
    """One plain line in the printed form, and whether it is a step (not an operand line)."""
    operand = _OPERAND_RE.match(line)
    if operand is not None:
        return f"       {operand.group(1):<2}: {operand.group(2)}", False
    if fun := _FUN_RE.match(line):
        number = int(fun.group(1))
        spec = BY_FUN.get(number)
        has_forms = spec is not None and any(p.name == "mode" for p in spec.params)
        forms = f" {_forms(fun.group(2), fun.group(3))}" if has_forms else ""
        name = spec.text_name if spec is not None else fun.group(4)
        return f"FUN {number:02d}{forms}.{name}", True
    if cmp := _CMP_RE.match(line):
        return f"{cmp.group(1)}F {cmp.group(2)}{cmp.group(3) or '_'}.{cmp.group(4)}", True
    if timer := _TMR_RE.match(line):
        base = f"{timer_base_ms(int(timer.group(1))) / 1000:g}".removeprefix("0")
        return f"T{timer.group(1)} {base} {timer.group(2)}", True
    if counter := _CTR_RE.match(line):
        return f"C{counter.group(1)}  {counter.group(2)}", True
    if coil := _COIL_RE.match(line):
        word = "SET( )" if coil.group(1) == "OUTS" else "RST( )"
        return f"{word:<{WIDTH}} {coil.group(2)}", True
    words = line.split(None, 1)
    if len(words) == 2 and words[0] in ("ORG", "LD", "AND", "OR", "OUT"):
        return f"{words[0]:<{WIDTH}} {words[1].strip()}".rstrip(), True
    return line, True


def printed_lines(plain: list[str], style: PrintedStyle, first_line: int) -> list[str]:
    """A network's plain lines in the printed form, step numbers from its first line's."""
    step = style.first_step(first_line)
    out: list[str] = []
    for line in plain:
        text, is_step = printed_line(line)
        if is_step:
            out.append(f"{step:05d}{style.unit} {text}")
            step += 1
        else:
            out.append(text)
    return out
