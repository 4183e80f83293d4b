"""Read a Delta instruction list (WPLSoft instruction mode, ISPSoft IL for DVP) into a Program.

One instruction a line, operands after it separated by spaces or tabs, an optional leading
step number, pointer lines `P n`, comments after `;` or `//`. A rung (network) starts at each
LD-like instruction that follows an output with no MPS pending, as WPLSoft draws it; pointer
lines, FEND, SRET, MCR and END are networks of their own. Every line keeps its place, so an
unchanged network is saved from its own lines (il/printer.py's faithful save).
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from ladderworks.core.address import Address, AddressError, Area
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.delta import (
    CR,
    DEVICES,
    NAME,
    S_BITS,
    WIDE_COUNTERS,
    csv_form,
    shown,
)
from ladderworks.core.dialects.delta import instructions as rows
from ladderworks.core.dialects.delta import rows_extra as extra
from ladderworks.core.il.program import (
    FileSource,
    Instruction,
    LabelRef,
    Network,
    ParamValue,
    Program,
    ProgramRef,
)
from ladderworks.core.il.textform import TextForm
from ladderworks.core.instructions import Flow, InstructionSpec, lookup

_STEP = re.compile(r"^\d{1,9}$")  # a step number (a longer one is not)
_POINTER = re.compile(r"^[Pp](\d+):?$")
_CONSTANT = re.compile(r"^([KkHh])(-?[0-9A-Fa-f]+)$")
_NEST = re.compile(r"^[Nn](\d)$")
# operands the simulator has no device for: bit groups (K4M0), index registers (E0, F1, D0E0),
# floating-point constants (F1.5): the instruction is kept, not simulated (docs/dialects.md)
_NOT_SIMULATED_OPERAND = re.compile(
    r"^(K[1-8][XYMS]\d+|[EF][0-7]|[A-Z]+\d+[EF][0-7]|F-?\d+\.\d*)$", re.IGNORECASE)
_MNEMONIC = re.compile(r"^[A-Z][A-Z0-9]*[=<>&|^]*$")  # what may be kept as a shown instruction

_BIT_LETTERS = {rows.BIT_IN: "XYMSTC", rows.BIT_OUT: "YMS"}
_WORD_LETTERS = {rows.WORD_IN: "TCD", rows.WORD_OUT: "TCD", rows.TIMER: "T",
                 rows.COUNTER: "C", rows.WIDE_COUNTER: "C", rows.RESET: "TCD",
                 extra.VALUE32: "TCD", extra.WORD_OUT32: "TCD"}
_VALUES = (rows.WORD_IN, extra.VALUE32, extra.MODULE)  # the kinds a K/H constant may be
_EITHER = {extra.DEVICE_OUT: "YMS", extra.DEVICE_IN: "XYMS"}  # a bit device, or T, C, D
_EXPECTED = {  # the spellings an operand of each kind may have, for the message
    rows.BIT_IN: "X, Y, M, S, T, C", rows.BIT_OUT: "Y, M, S", rows.WORD_IN: "K, H, T, C, D",
    rows.WORD_OUT: "T, C, D", rows.TIMER: "T0-T255", rows.COUNTER: "C0-C199",
    rows.WIDE_COUNTER: "C200-C255", rows.RESET: "T, C, D", rows.LABEL: "P0-P255",
    rows.PROGRAM: "P0-P255", rows.NEST: "N0-N7", extra.VALUE32: "K, H, T, C, D",
    extra.WORD_OUT32: "T, C, D", extra.DEVICE_OUT: "Y, M, S, T, C, D",
    extra.DEVICE_IN: "X, Y, M, S, T, C, D", extra.MODULE: "K0-K7", extra.STEP: "S0-S1023",
}


def _split_comment(raw: str) -> tuple[str, str, int]:
    """The code part of a line, its comment text, and the comment's column (0: none)."""
    cut = len(raw)
    for marker in (";", "//"):
        at = raw.find(marker)
        if 0 <= at < cut:
            cut = at
    if cut == len(raw):
        return raw, "", 0
    width = 1 if raw[cut] == ";" else 2
    return raw[:cut], raw[cut + width:].strip(), cut + 1


@dataclass(slots=True)
class _Rung:
    """The network being read: its instructions and what the stack holds."""

    start: int  # index of its first line (comments and blanks before it included)
    head: int = -1  # index of its first instruction line
    instructions: list[Instruction] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)
    depth: int = 0  # values on the stack (an LD makes one, ANB/ORB join two)
    pushed: int = 0  # MPS not yet taken back by MPP
    output: bool = False  # the last instruction was an output


class _Reader:
    def __init__(self, lines: list[str]) -> None:
        self.lines = lines
        self.form = csv_form.detect(lines[:csv_form.SAMPLE * 2])
        self.step_no = -1  # the last step number read
        self.networks: list[Network] = []
        self.spans: list[tuple[int, int]] = []
        self.heads: list[int] = []
        self.diagnostics: list[Diagnostic] = []
        self.rung = _Rung(0)
        self.after_fend = False
        self.step: Address | None = None  # the S of the step ladder's step being read (STL)
        self.step_read: Address | None = None  # the S of a STL line just read
        self.loops: list[tuple[LabelRef, ParamValue, int, int]] = []  # FORs open: label, count
        self.loop_count = 0  # FOR lines read
        self.pending: list[str] = []  # comment lines not yet given to a network

    def error(self, code: str, line: int, column: int, **args: object) -> None:
        self.diagnostics.append(Diagnostic(code, dict(args), line, column))

    def close(self, stop: int) -> None:
        """End the network being read at line index `stop` (exclusive)."""
        rung = self.rung
        if rung.instructions:
            self.networks.append(Network(rung.instructions, rung.comments))
            self.spans.append((rung.start, stop))
            self.heads.append(rung.head)
            self.rung = _Rung(stop)

    def add(self, index: int, instruction: Instruction) -> None:
        rung = self.rung
        if not rung.instructions:
            rung.head = index
            rung.comments = self.pending
            self.pending = []
        rung.instructions.append(instruction)

    def run(self) -> tuple[list[Network], int]:
        """Read every line; the networks and the index of the line after the last one."""
        last = 0
        for index, raw in enumerate(self.lines):
            number = index + 1
            if self.form is not None and not self.form.comment(raw):
                found = csv_form.fields(raw, self.form.separator)
                words = [text for text, _ in found]
                column = found[0][1] if found else 1
                if csv_form.is_header(self.form, words) and last == 0:  # `Step,Instruction`
                    self.pending.append(", ".join(words))
                    continue
                comment = csv_form.trailing_comment(words)
                if len(found) > 1 and _STEP.match(words[0]):
                    self.step_number(int(words[0]), number, column)
                    words, column = words[1:], found[1][1]
                if not words:
                    continue
            else:
                code, comment, comment_column = _split_comment(raw)
                words = code.split()
                if not words:
                    if comment_column:
                        self.pending.append(comment)
                    continue
                column = len(code) - len(code.lstrip()) + 1
                if len(words) > 1 and _STEP.match(words[0]):
                    self.step_number(int(words[0]), number, column)
                    column = code.index(words[1], column - 1 + len(words[0])) + 1
                    words = words[1:]
            self.line(index, number, column, words, comment)
            last = index + 1
        self.close(last)
        for _label, _count, number, column in self.loops:
            self.error("dvp-for-without-next", number, column)
        return self.networks, last

    def step_number(self, step: int, line: int, column: int) -> None:
        """A line's step number: each after the one before (WPLSoft numbers them so)."""
        if step <= self.step_no:
            self.error("dvp-step-order", line, column, step=step, previous=self.step_no)
        self.step_no = step

    def line(self, index: int, number: int, column: int, words: list[str], comment: str) -> None:
        pointer = _POINTER.match(words[0])
        if pointer is not None and len(words) == 1:
            self.close(index)
            row = rows.SUBROUTINE_ROW if self.after_fend else rows.LABEL_ROW
            ref: ParamValue = (ProgramRef if self.after_fend else LabelRef)(int(pointer.group(1)))
            self.add(index, Instruction(row.name, None, (ref,), comment, (), number, column))
            self.close(index + 1)
            return
        mnemonic = words[0].upper()
        if "" in words:  # an empty field of WPLSoft's export between two others
            self.error("dvp-missing-operand", number, column, name=mnemonic,
                       index=words.index(""))
            return
        spelling = rows.SPELLINGS.get(mnemonic)
        rung = self.rung
        if spelling is not None and any(_NOT_SIMULATED_OPERAND.match(text)
                                        for text in words[1:]):  # K4M0, D0E0: kept as is
            contact = spelling.role in ("load", "contact")
            self.shown(index, number, column,
                       shown.spelling(mnemonic, words[1:], rung.depth > 0, contact), comment)
            return
        if spelling is None:  # kept, drawn and saved, not simulated (the checks warn)
            if not _MNEMONIC.match(mnemonic) or any(" " in text for text in words[1:]):
                self.error("unknown-instruction", number, column, name=words[0][:20])
                return
            spelling = shown.spelling(mnemonic, words[1:], rung.depth > 0)
            self.shown(index, number, column, spelling, comment)
            return
        if spelling.role == "step":
            self.step_line(index, number, column, words, comment)
            return
        if spelling.role == "loop":
            self.loop_line(index, number, column, words, comment)
            return
        if spelling.role in ("output", "contact", "filler"):
            self.after_step(index, number, column)
        self.step_read = None
        role = spelling.role
        if role == "alone" or (role == "load" and rung.output and rung.pushed == 0):
            self.close(index)
            rung = self.rung
        row_name = spelling.row
        if role == "load" and rung.depth > 0:
            row_name = spelling.stk_row
        operands = words[1:]
        kinds: tuple[str, ...]
        if mnemonic == "RST" and operands and operands[0][:1].upper() in "TCD":
            row_name, kinds = rows.RESET_ROW.name, (rows.RESET,)
        else:
            kinds = spelling.operands
        if mnemonic == "FEND":
            self.after_fend = True
        if spec_row_is_return(row_name):
            self.step = None
        if self.step is not None and mnemonic in extra.STEP_MOVE_ROWS and operands \
                and operands[0][:1].upper() == "S":  # a step's SET/OUT Sm: moves on to Sm
            row_name = extra.STEP_MOVE_ROWS[mnemonic]
        spec = lookup(row_name)
        assert spec is not None, row_name
        instruction = self.build(spec, mnemonic, kinds, operands, number, column, comment)
        if spec.name in extra.STEP_MOVE_ROWS.values() and instruction.params \
                and self.step is not None:
            instruction = instruction._replace(params=(*instruction.params, self.step))
        if spec.name in extra.PULSED and instruction.params:
            self.pulsed(index, instruction)
        else:
            self.add(index, instruction)
        if role == "load":
            rung.depth += 1
        elif role == "block":
            rung.depth = max(rung.depth - 1, 0)
        rung.pushed = max(rung.pushed + (spec.pushes if spec.stack else 0), 0)
        if role != "filler":  # NOP leaves the rung as it was
            rung.output = role == "output"
        if role == "alone":
            self.close(index + 1)

    def pulsed(self, index: int, edge: Instruction) -> None:
        """CJP/CALLP Pn: MPS, the edge box, the CJ/CALL it gates, MPP (the rung's value goes on
        to what follows, as after any output)."""
        line, column = edge.line, edge.column
        push, pop = rows.SPELLINGS["MPS"].row, rows.SPELLINGS["MPP"].row
        gated = rows.SPELLINGS[extra.PULSED[edge.name]].row
        self.add(index, Instruction(push, None, (), "", (), line, column))
        self.add(index, edge)
        self.add(index, Instruction(gated, None, edge.params, "", (), line, column))
        self.add(index, Instruction(pop, None, (), "", (), line, column))

    def step_line(self, index: int, number: int, column: int, words: list[str],
                  comment: str) -> None:
        """STL Sn: a network of its own (the step before ends), read as LD Sn, the step's
        COMMON range gated by it, LD Sn again (an output may follow at once)."""
        self.close(index)
        if len(words) != 2:
            self.error("param-count", number, column, name="STL", expected=1,
                       found=len(words) - 1)
            return
        at = self.lines[index].find(words[1], column - 1) + 1 or column
        step = self.operand("STL", 1, rows.BIT_OUT, words[1], number, at)
        if not isinstance(step, Address):
            return
        if step.byte < S_BITS or step.area is not Area.R:  # an S device only
            self.kind_error("STL", 1, extra.STEP, words[1], number, at)
            return
        read = lookup("RD")
        assert read is not None
        if self.step is not None:
            self.add(index, Instruction(extra.STEP_NEXT_ROW.name, None, (), "", (), number,
                                        column))
        self.add(index, Instruction(read.name, step, (), "", (), number, column))
        self.add(index, Instruction(extra.STEP_ROW.name, None, (0, step), comment, (), number,
                                    column))
        self.step = self.step_read = step
        self.rung.output = True  # an LD after it starts the step's first rung

    def after_step(self, index: int, number: int, column: int) -> None:
        """An output or contact right after STL Sn reads Sn (STL is its LD)."""
        step, self.step_read = self.step_read, None
        if step is not None and self.rung.instructions \
                and self.rung.instructions[-1].name == extra.STEP_ROW.name:
            read = lookup("RD")
            assert read is not None
            self.add(index, Instruction(read.name, step, (), "", (), number, column))
            self.rung.depth = 1

    def loop_line(self, index: int, number: int, column: int, words: list[str],
                  comment: str) -> None:
        """FOR n / NEXT: each a network of its own (docs/dialects.md)."""
        self.close(index)
        looping = words[0].upper() == "FOR"
        if len(words) != (2 if looping else 1):
            self.error("param-count", number, column, name=words[0].upper(),
                       expected=1 if looping else 0, found=len(words) - 1)
            return
        if looping:
            at = self.lines[index].find(words[1], column - 1) + 1 or column
            count = self.operand("FOR", 1, rows.WORD_IN, words[1], number, at)
            if count is None:
                return
            label = LabelRef(extra.LOOP_LABELS + self.loop_count)
            self.loop_count += 1
            self.loops.append((label, count, number, column))
            self.add(index, Instruction(extra.LOOP_ROW.name, None, (label, count), comment, (),
                                        number, column))
        elif not self.loops:
            self.error("dvp-next-without-for", number, column)
            return
        else:
            label, count, _line, _column = self.loops.pop()
            self.add(index, Instruction(extra.LOOP_TEST_ROW.name, None, (count,), comment, (),
                                        number, column))
            self.add(index, Instruction(extra.LOOP_BACK_ROW.name, None, (label,), "", (),
                                        number, column))
        self.close(index + 1)

    def shown(self, index: int, number: int, column: int, spelling: rows.Spelling,
              comment: str) -> None:
        """An instruction the simulator does not run, kept with its operands as written."""
        rung = self.rung
        role = spelling.role
        if role == "alone" or (role == "load" and rung.output and rung.pushed == 0):
            self.close(index)
            rung = self.rung
        name = spelling.stk_row if role == "load" and rung.depth > 0 else spelling.row
        self.add(index, Instruction(name, None, (), comment, (), number, column))
        rung.depth += role == "load"
        rung.output = role == "output"
        if role == "alone":
            self.close(index + 1)

    def build(self, spec: InstructionSpec, mnemonic: str, kinds: tuple[str, ...],
              operands: list[str], number: int, column: int, comment: str) -> Instruction:
        """The instruction of row `spec` with its operands read (a diagnostic for each bad one:
        the instruction is kept with the operands that read, and the checks see it)."""
        if spec.flow is Flow.COMMON:  # MC N: its `coils` 0, then the nesting level
            kinds = ("zero", *kinds)
            operands = ["K0", *operands]
        wanted = len(kinds) - (1 if spec.flow is Flow.COMMON else 0)
        given = len(operands) - (1 if spec.flow is Flow.COMMON else 0)
        if given != wanted:
            self.error("param-count", number, column, name=mnemonic, expected=wanted,
                       found=given)
            return Instruction(spec.name, None, (), comment, (), number, column)
        values: list[ParamValue] = []
        line = self.lines[number - 1]
        for index, (kind, text) in enumerate(zip(kinds, operands, strict=True), start=1):
            at = line.find(text, column - 1) + 1 if kind != "zero" else column
            value = self.operand(mnemonic, index, kind, text, number, at or column)
            if value is None:
                return Instruction(spec.name, None, (), comment, (), number, column)
            values.append(value)
        if spec.operand:
            operand = values[0]
            assert isinstance(operand, Address)
            return Instruction(spec.name, operand, (), comment, (), number, column)
        return Instruction(spec.name, None, tuple(values), comment, (), number, column)

    def operand(self, name: str, index: int, kind: str, text: str, line: int,
                column: int) -> ParamValue | None:
        """One operand as read by its kind; None (and a diagnostic) when it is not one."""
        if kind == "zero":
            return 0
        upper = text.upper()
        try:
            if kind not in (rows.LABEL, rows.PROGRAM, rows.NEST) and \
                    _CONSTANT.match(text) is None:
                if upper[:1] in "KH" and kind in _VALUES:
                    self.error("dialect-constant", line, column, text=text)
                    return None
                device, _number = DEVICES.split(text)  # unknown, an 8 in octal, out of range
                if device.letter == CR.letter:  # a module's register: reached by FROM/TO only
                    return self.kind_error(name, index, kind, text, line, column)
            if kind in _EITHER and _CONSTANT.match(text) is None:
                if upper[:1] in _EITHER[kind]:
                    return DEVICES.bit(text)
                if upper[:1] in "TCD":
                    return DEVICES.word(text)[0]
                return self.kind_error(name, index, kind, text, line, column)
            if kind in _BIT_LETTERS:
                if upper[:1] not in _BIT_LETTERS[kind] or (_CONSTANT.match(text) and \
                        upper[:1] in "KH"):
                    return self.kind_error(name, index, kind, text, line, column)
                return DEVICES.bit(text)
            if kind in (rows.LABEL, rows.PROGRAM):
                found = _POINTER.match(text)
                if found is None:
                    return self.kind_error(name, index, kind, text, line, column)
                return (LabelRef if kind == rows.LABEL else ProgramRef)(int(found.group(1)))
            if kind == rows.NEST:
                found = _NEST.match(text)
                if found is None or int(found.group(1)) > 7:
                    return self.kind_error(name, index, kind, text, line, column)
                return int(found.group(1))
            constant = _CONSTANT.match(text)
            if constant is not None:
                if kind not in _VALUES or (kind == extra.MODULE and upper[:1] != "K"):
                    return self.kind_error(name, index, kind, text, line, column)
                return self.constant(constant, text, line, column, kind == extra.VALUE32)
            if upper[:1] not in _WORD_LETTERS.get(kind, ""):
                return self.kind_error(name, index, kind, text, line, column)
            address, _width = DEVICES.word(text)
            if kind in (rows.COUNTER, rows.WIDE_COUNTER):
                _device, number = DEVICES.split(text)
                if (number >= WIDE_COUNTERS) != (kind == rows.WIDE_COUNTER):
                    return self.kind_error(name, index, kind, text, line, column)
            return address
        except AddressError as exc:
            self.error(exc.code, line, column, **exc.args_map)
            return None

    def constant(self, found: re.Match[str], text: str, line: int, column: int,
                 wide: bool = False) -> int | None:
        """A K (decimal) or H (hex) constant (`wide`: of a 32-bit operand)."""
        letter, digits = found.group(1).upper(), found.group(2)
        try:
            value = int(digits, 16 if letter == "H" else 10)
        except ValueError:
            self.error("dialect-constant", line, column, text=text)
            return None
        if letter == "H" and value > 0xFFFF:
            return value - (1 << 32) if value >= 1 << 31 else value
        if letter == "H" and value >= 0x8000 and not wide:
            return value - 0x10000
        return value

    def kind_error(self, name: str, index: int, kind: str, text: str, line: int,
                   column: int) -> ParamValue | None:
        """Report an operand of the wrong kind; None."""
        self.error("dialect-operand", line, column, name=name, index=index,
                   expected=_EXPECTED[kind], text=text)
        return None


def spec_row_is_return(row_name: str) -> bool:
    """True for the row that ends the step ladder (RET)."""
    return row_name == extra.RETURN_ROW.name


def read(text: str, form: TextForm, lines: list[str],
         ends: list[str]) -> tuple[Program, list[Diagnostic]]:
    """A Delta instruction list as a Program (dialect "delta") and the reader's diagnostics."""
    reader = _Reader(lines)
    networks, last = reader.run()
    program = Program(networks=networks, dialect=NAME)
    program.trailer = list(reader.pending)
    program.source = FileSource(
        form, lines, ends, 0, len(lines), [network.key() for network in networks],
        reader.spans, reader.heads, tuple(program.trailer), (last, len(lines)))
    return program, reader.diagnostics


def read_instructions(instructions: Iterable[tuple[int | None, str, Sequence[str]]]
                      ) -> tuple[Program, list[Diagnostic]]:
    """A program from a list of instructions, each (step or None, mnemonic, operand texts): as
    WPLSoft exports them (`000012,MPS`), read by `read` (the .dvp reader's entry). A
    diagnostic's line is the instruction's place in the list (1-based)."""
    lines = [",".join([*(() if step is None else (f"{step:06d}",)), mnemonic, *operands])
             for step, mnemonic, operands in instructions]
    text = "".join(line + "\n" for line in lines)
    return read(text, TextForm(), lines, ["\n"] * len(lines))
