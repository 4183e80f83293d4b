"""A WinProladder mnemonic listing (printed/exported, or seed 002's plain form) as records."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ladderworks.core.diagnostics import Diagnostic

# The instructions of a step line (docs/dialects.md, Fatek, the listing)
CONTACTS = ("ORG", "LD", "AND", "OR")  # 002:90-99
STACK_OPS = ("ANDLD", "ORLD")  # 002:243-301
COILS = ("OUT", "OUTS", "OUTR")  # OUT / OUT NOT / OUT L; OUTS set, OUTR reset
BOXES = ("TMR", "CTR", "RST", "SET")  # timers, counters, SET / RST of a relay (RST of T/C)
MODIFIERS = ("NOT", "TU", "TD")

MAX_STEP_DIGITS = 9  # a longer "step number" is not one (int() refuses thousands of digits)


@dataclass(frozen=True, slots=True)
class OperandLine:
    """A FUN box's operand line (`Sa: R0`, `D : R1`, `: C1`): its label and operand text."""

    line: int
    label: str
    text: str
    column: int = field(default=1, compare=False)  # of the operand text


@dataclass(slots=True)
class Record:
    """One instruction of the listing with what its line (and operand lines) said."""

    line: int  # 1-based line of the step
    mnemonic: str  # ORG LD AND OR ANDLD ORLD OUT OUTS OUTR TMR CTR RST FUN FO END, or ORGF …
    modifier: str = ""  # NOT, TU, TD (contacts); NOT, L (OUT); TR (OUT TR / LD TR)
    operand: str = ""  # the device as written, joined (`X0`, `TR0`), OPEN / SHORT, or ""
    step: int | None = None  # the step number, None in seed 002's plain form
    unit: str = ""  # the program unit's letter after the step number
    fun: int | None = None  # FUN n (and the comparison contacts' number)
    fun_name: str = ""  # MOV, (+), (=) … as written
    pulse: bool = False  # the P form: runs on the input's rising edge
    double: bool = False  # the D form: 32-bit operands
    args: tuple[str, ...] = ()  # further operands on the step line (TMR base and PV, …)
    operands: list[OperandLine] = field(default_factory=list)
    column: int = 1  # of the mnemonic
    printed: bool = False  # in WinProladder's printed form (`SET( )`, `T10 .01 R7`, `FUN 8 _.MOV`)

    @property
    def last_line(self) -> int:
        """The last line that belongs to the record."""
        return self.operands[-1].line if self.operands else self.line


@dataclass(slots=True)
class Listing:
    """The records of a listing, with its page header lines (their line numbers)."""

    records: list[Record]
    headers: list[int]


_HEADER_RE = re.compile(r"^\s*(Printed Item\s*:|Page\s+\d+\b|-\s*\d+\s*-\s*$)", re.I)
_ITEM_RE = re.compile(r"^\s*Printed Item\s*:\s*(\S+)", re.I)
_STEP_RE = re.compile(r"^\s*(\d+)([A-Za-z]?)(?=\s)\s+(.*)$")
_OPERAND_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9]{0,3})?\s*:\s*(\S.*?)\s*$")
# `FUN 11P (+)` (the manual's key-in form), `FUN 08 _.MOV`, `FUN 141.MPARA`, `FUN 11 DP.(+)`
# (WinProladder's printout: D / P or `_` for each form, then a dot before the name)
_FUN_RE = re.compile(r"^FUN\s*(\d+)\s*(?:([D_]?)([P_]?)\.|(D?)\s*(P?)\s*\.?)\s*(.*)$", re.I)
_CMP_RE = re.compile(r"^(ORG|LD|AND|OR)F\s+(?:FUN\s*)?(\d+)\s*(?:([D_]?)([P_]?)\.|(D?)\s*(P?)"
                     r"\s*\.?)\s*(.*)$", re.I)
# WinProladder's printed timer and counter lines: `T10 .01 R7` (base, preset), `C5 10`
_TIMER_RE = re.compile(r"^([TC])\s*(\d+)\s+(?:(\d*\.\d+|\d+)S?\s+)?(\S+)$", re.I)
_FO_RE = re.compile(r"^FO\s*(\d+)$", re.I)
_DEVICE_SPLIT_RE = re.compile(r"^([A-Za-z]{1,3})\s+(\d+)$")
_RST_RE = re.compile(r"^(RST|SET)\s*\(\s*([A-Za-z]*\s*\d*)\s*\)", re.I)
_LONG_NUMBER_RE = re.compile(r"\d{16,}")
_ANNOTATION = "←"  # the seed's margin notes (002:376-402)


def _strip_note(text: str) -> str:
    """The instruction without a margin note (`LD TR 0 ← 2. sıradan başlar`) or a `;` / `#`
    comment."""
    for mark in (_ANNOTATION, ";", "#"):
        if mark in text:
            text = text[:text.index(mark)]
    return text.strip()


def _device(words: list[str]) -> str:
    """Device words joined: `X 0` (seed 002's columns) and `X0` both give `X0`."""
    text = " ".join(words)
    split = _DEVICE_SPLIT_RE.match(text)
    return split.group(1) + split.group(2) if split else text.replace(" ", "")


def _step_record(text: str, line: int, step: int | None, unit: str, column: int = 1
                 ) -> tuple[Record | None, Diagnostic | None]:
    """The record a step line's instruction part makes, or the diagnostic of a bad one."""
    record, problem = _step_kind(text, line, step, unit)
    if record is not None:
        record.column = column
    if problem is not None:
        problem = Diagnostic(problem.code, problem.args, problem.line, column)
    return record, problem


def _step_kind(text: str, line: int, step: int | None, unit: str
               ) -> tuple[Record | None, Diagnostic | None]:
    """_step_record without the column."""
    fun = _FUN_RE.match(text)
    if fun is not None:
        return _box_record(Record(line, "FUN", step=step, unit=unit, fun=int(fun.group(1))),
                           fun.groups()[1:]), None
    cmp = _CMP_RE.match(text)
    if cmp is not None:
        return _box_record(Record(line, cmp.group(1).upper() + "F", step=step, unit=unit,
                                  fun=int(cmp.group(2))), cmp.groups()[2:]), None
    fo = _FO_RE.match(text)
    if fo is not None:
        return Record(line, "FO", operand=fo.group(1), step=step, unit=unit), None
    timer = _TIMER_RE.match(text)
    if timer is not None:
        kind, number, base, preset = timer.groups()
        args = (f"0{base}S" if base.startswith(".") else f"{base}S", preset) if base else (preset,)
        return Record(line, "TMR" if kind.upper() == "T" else "CTR", operand=kind.upper() + number,
                      step=step, unit=unit, args=args, printed=True), None
    printed = _RST_RE.match(text) is not None
    text = _RST_RE.sub(lambda m: f"{m.group(1)} {m.group(2)}", text)  # `RST( ) C0`, `SET( ) S3`
    words = text.split()
    name = words[0].upper()
    rest = words[1:]
    record = Record(line, name, step=step, unit=unit)
    if name in CONTACTS or name in COILS:
        if rest and rest[0].upper() == "TR" and name in ("LD", "OUT"):
            record.modifier = "TR"
            record.operand = "TR" + "".join(rest[1:])
            return record, None
        first = rest[0].upper() if rest else ""
        latch = name == "OUT" and first == "L" and len(rest) > 1  # `OUT L` alone: no device
        if first in MODIFIERS or latch:
            record.modifier = first
            rest = rest[1:]
        if name in CONTACTS and rest and rest[0].upper() in ("OPEN", "SHORT") and len(rest) == 1:
            record.operand = rest[0].upper()
            return record, None
        record.operand = _device(rest)
        return record, None
    if name in STACK_OPS or name == "END":
        if rest:
            return None, Diagnostic("extra-operand", {"name": name, "text": " ".join(rest)},
                                    line)
        return record, None
    if name in BOXES:
        record.operand = rest[0] if rest else ""
        record.args = tuple(rest[1:])
        record.printed = printed
        return record, None
    return None, Diagnostic("fatek-unknown-instruction", {"name": words[0]}, line)


def _box_record(record: Record, forms: tuple[str | None, ...]) -> Record:
    """A FUN or comparison record with its forms (printed `D`/`P`/`_` before a dot, or the key-in
    `D`/`P` after the number) and its name."""
    printed_d, printed_p, key_d, key_p, name = forms
    record.printed = printed_d is not None
    record.double = (printed_d or key_d or "").upper() == "D"
    record.pulse = (printed_p or key_p or "").upper() == "P"
    record.fun_name = (name or "").strip()
    return record


def read_listing(lines: list[str], first_line: int = 1) -> tuple[Listing, list[Diagnostic]]:
    """The records of a listing's lines (without their line ends); page headers and blank lines
    skipped; an operand line joins the FUN, comparison, TMR or CTR record before it. Seed 002's
    `OUT` / `Y 0` printed over two lines (002:319-326) joins too."""
    records: list[Record] = []
    headers: list[int] = []
    diagnostics: list[Diagnostic] = []
    pending: list[_Pending] = []  # step lines waiting for their operand's line
    mnemonic_pages = any((m := _ITEM_RE.match(raw)) is not None
                         and m.group(1).lower() == "mnemonic" for raw in lines)
    other_item = False  # under a printed item that is not the mnemonic (ladder, comments …)
    for index, raw in enumerate(lines):
        line = first_line + index
        if raw.lstrip().startswith("#"):
            continue  # a comment line
        text = _strip_note(raw)
        if not text:
            continue
        if _HEADER_RE.match(text):
            headers.append(line)
            item = _ITEM_RE.match(text)
            if item is not None:
                other_item = mnemonic_pages and item.group(1).lower() != "mnemonic"
            continue
        if other_item:
            continue
        long = _LONG_NUMBER_RE.search(raw)
        if long is not None:  # no Fatek number has so many digits (and int() refuses 4300+)
            diagnostics.append(Diagnostic("fatek-long-number", {"text": long.group(0)[:12]},
                                          line, long.start() + 1))
            continue
        if pending and _STEP_RE.match(raw) is None and _OPERAND_RE.match(text) is None and \
                pending[0].complete(text, records):
            pending.pop(0)  # the oldest step waiting takes the line (pdftotext's order)
            continue
        operand = _OPERAND_RE.match(text)
        if operand is not None and not _STEP_RE.match(text):
            last = records[-1] if records else None
            if last is None or (last.fun is None and last.mnemonic not in BOXES):
                diagnostics.append(Diagnostic("fatek-stray-operand", {"text": text}, line,
                                              _column(raw, text)))
                continue
            last.operands.append(OperandLine(line, (operand.group(1) or "").strip(),
                                             operand.group(2),
                                             _column(raw, operand.group(2))))
            continue
        step_match = _STEP_RE.match(raw)
        step: int | None = None
        unit = ""
        if step_match is not None and not raw.lstrip()[0].isalpha() \
                and len(step_match.group(1)) <= MAX_STEP_DIGITS:  # int() refuses 4300 digits
            step = int(step_match.group(1))
            unit = step_match.group(2).upper()
            text = _strip_note(step_match.group(3))
            if not text:  # a step number alone (or with a margin note)
                continue
        if records and _continues(records[-1], text):
            records[-1].operand = _device(text.split())
            continue
        record, problem = _step_record(text, line, step, unit, _column(raw, text))
        if step is not None and text.strip().upper() == "FO":  # its number on a later line
            record, problem = Record(line, "FO", step=step, unit=unit,
                                     column=_column(raw, text)), None
        if problem is not None:
            diagnostics.append(problem)
        if record is not None:
            if step is not None and _incomplete(record):
                pending.append(_Pending(len(records), text, record))
            records.append(record)
    return Listing(records, headers), diagnostics


@dataclass(slots=True)
class _Pending:
    """A step line whose operand `pdftotext` (without -layout) put on a later line:
    `00001M SET( )`, a blank line, `S3`; `00079M FO`, `0`. Steps waiting so take the next
    such lines in their order (pdftotext may print two steps before their operands)."""

    index: int  # of its record
    text: str  # its instruction part as printed
    record: Record

    def complete(self, rest: str, records: list[Record]) -> bool:
        """Read the step with `rest` as its operand: True when that makes a whole record."""
        old = self.record
        record, problem = _step_record(f"{self.text} {rest}", old.line, old.step, old.unit,
                                       old.column)
        if record is None or problem is not None or _incomplete(record):
            return False
        records[self.index] = record
        return True


def _incomplete(record: Record) -> bool:
    """A step that names no operand where it needs one: a contact or coil without its device,
    a TR point without its number, `FO` without its number."""
    if record.modifier == "TR":
        return record.operand in ("TR", "")
    return record.mnemonic in (*CONTACTS, *COILS, "SET", "RST", "FO") and not record.operand


def _continues(last: Record, text: str) -> bool:
    """True when `text` is the device of a coil printed alone before it (002:319-326)."""
    return (last.mnemonic in COILS and not last.operand and last.modifier != "TR"
            and _DEVICE_SPLIT_RE.match(text) is not None)


def _column(raw: str, text: str) -> int:
    """1-based column of `text` in the line (1 when it is not found as written)."""
    at = raw.find(text.split()[0]) if text.split() else -1
    if step := _STEP_RE.match(raw):
        found = raw.find(text.split()[0], step.start(3)) if text.split() else -1
        at = found if found >= 0 else at
    return at + 1 if at >= 0 else 1
