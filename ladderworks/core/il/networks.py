"""The ladder section read into networks: each distinct line text scanned and built once
(`LadderReader`), the instructions grouped into networks (`NetworkBuilder`) with the source
lines each came from."""

from __future__ import annotations

from typing import cast

from ladderworks.core import instructions as _table
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.line_scan import (
    ADDRESS_SHAPE,
    BAD,
    BLANK,
    Line,
    Made,
    Token,
    flow,
    scan_common,
    scan_line,
    syntax_error,
)
from ladderworks.core.il.params import ParamReader, shape, small_int, table_size
from ladderworks.core.il.program import Instruction, Network, ParamValue, new_instruction
from ladderworks.core.instructions import (
    BY_MNEMONIC,
    BY_SUB,
    SUB_KEYWORD,
    InstructionSpec,
    Kind,
    lookup,
    spec_for,
)


class LadderReader:
    """Reads the lines of one ladder section into networks, in the program's dialect; its
    diagnostics are the parse's (appended to); `labels` tells a LADDER-III label was read."""

    def __init__(self, diagnostics: list[Diagnostic], dialect: str) -> None:
        self.diagnostics = diagnostics
        self.labels = False
        self.params = ParamReader(diagnostics, dialect)

    def read(self, body: list[str], start: int) -> NetworkBuilder:
        """The networks of the section's lines `body` (line `start` + 1 is the first)."""
        # many lines repeat ("RD X21.7"): each text is scanned once, and what it makes is
        # built once; the lines that repeat it share its Line (or its Made)
        texts = list(dict.fromkeys(body))
        seen = cast("dict[str, Line | Made]", dict(zip(texts, scan_common(texts),
                                                        strict=True)))
        bad = False
        for text in [text for text, item in seen.items() if item is None]:
            item = scan_line(text, 0)
            if isinstance(item, Diagnostic):
                item = BAD
                bad = True
            seen[text] = item
        if bad:  # a syntax error is reported at each line that has it, in order
            for number, text in enumerate(body, start + 1):
                if seen[text] is BAD:
                    self.diagnostics.append(syntax_error(text, number))
        recs = list(map(seen.__getitem__, body))  # line start + 1 + k is recs[k]
        base = start + 1
        builder = NetworkBuilder(start)
        self._build_ladder(recs, base, builder)
        return builder

    def _build_ladder(self, recs: list[Line | Made], base: int,
                      builder: NetworkBuilder) -> None:
        """Read the ladder's lines into the builder's networks."""
        # the builder's state for the common line (an instruction its text alone makes, in
        # the current network) is kept in locals, and written back before any other line
        current = builder.current
        closed = builder.closed
        pending = builder.pending
        pending_label = builder.pending_label
        last = 0  # the last line added here since the builder was told (0: none)
        skip = 0  # the lines before this number were read with a line before them
        for number, rec in enumerate(recs, base):  # line `number` is recs[number - base]
            if number < skip:
                continue
            made = rec if rec.__class__ is tuple else rec.made  # type: ignore[union-attr]
            if made is not None:
                _spec, name, operand, params, comment, column, starts, ends = made
                instruction = new_instruction(name, operand, params, comment, (), number,
                                              column)
                if current is not None and not pending and not (
                        closed and (starts or pending_label)):
                    current.append(instruction)  # the common case of builder.add, inline
                    last = number
                    if ends:
                        closed = True
                    continue
            elif rec.kind == "label" and not pending_label:  # type: ignore[union-attr]
                self.labels = True  # builder.label, inline: one a network in LADDER-III text
                pending_label = builder.pending_label = rec.words[0].text  # type: ignore
                closed = True
                continue
            if last:
                builder.lasts[-1] = builder.cursor = last
                last = 0
            builder.closed = closed
            if made is not None:
                builder.add(instruction, number, starts, ends)
            else:
                assert isinstance(rec, Line)
                kind = rec.kind
                if kind == "label":
                    self.labels = True
                    builder.label(rec.words[0].text)
                elif kind != "blank" and kind != "bad":
                    skip = base + self._line(recs, base, number - base, builder)
            current = builder.current
            closed = builder.closed
            pending = builder.pending
            pending_label = builder.pending_label
        if last:
            builder.lasts[-1] = builder.cursor = last
        builder.closed = closed

    def _line(self, recs: list[Line | Made], base: int, k: int,
              builder: NetworkBuilder) -> int:
        """Read line `recs[k]` (number `base + k`, with the parameter lines it takes); returns
        the next index."""
        line = recs[k]
        assert isinstance(line, Line)
        number = base + k
        k += 1
        last = k - 1  # the last line it reads
        if line.kind == "comment":
            builder.comment(line.comment or "")
            return k
        if line.kind == "label":
            self.labels = True
            builder.label(line.words[0].text)
            return k
        if line.kind == "parameter":
            self._error("stray-parameter", number, line.words[0].column,
                        text=line.words[0].text[:20])
            return k
        if line.function is not None:  # the text was read before: its parameters now
            fast = self.params.valid_params(line.function, recs, last)
            if fast is not None:
                return self._add_function(line, base, number, line.function, *fast,
                                          builder)
        reported = len(self.diagnostics)
        alone = True  # the text alone makes the instruction: no parameter lines taken
        head = line.words[0]
        operands = line.words[1:]
        spec = lookup(head.text)
        if spec is None and head.text[:4].upper() == "SUB.":
            spec = spec_for(head.text, len(operands))  # one-line unknown `SUB.219 p1 p2`
            if spec is not None:
                self.diagnostics.append(Diagnostic("unknown-sub", {"number": spec.sub},
                                                   number, head.column, Severity.WARNING))
        if spec is None:
            if len(operands) == 0 and ADDRESS_SHAPE.match(head.text):
                self._error("stray-parameter", number, head.column, text=head.text[:20])
            else:
                self._error("unknown-instruction", number, head.column, name=head.text[:20])
            return k
        if spec.kind is Kind.BASIC and len(operands) > 1 and head.text.upper() in BY_MNEMONIC:
            spec = BY_MNEMONIC[head.text.upper()]  # one-line `AND 1 R10 R11 R12`: LOGAND
        if spec.name == SUB_KEYWORD and len(operands) == 1 and operands[0].is_int:
            sub = small_int(operands[0].text, 6)
            sub = sub if sub is not None and sub >= 0 else None
            sub_spec = BY_SUB.get(sub) if sub is not None else None
            if sub_spec is None:
                return self._unknown_sub(line, number, sub, recs, base, k, builder)
            spec = sub_spec
            operands = []
            alone = False
        elif spec.kind is not Kind.BASIC and not operands and spec.params:
            alone = False
        if not alone:
            if len(self.diagnostics) == reported:
                line.function = spec
            fast = self.params.valid_params(spec, recs, last)
            if fast is not None:  # what the lines below would make, with no diagnostic
                params, last = fast
                return self._add_function(line, base, number, spec, params, last,
                                          builder)
            last = self._collect_params(spec, recs, last, operands)
        k = last + 1
        end_line = base + last
        instruction = self.params.build(spec, line, number, operands)
        if instruction is None:
            return k
        starts, ends = flow(spec)
        if alone and len(self.diagnostics) == reported:
            line.made = (spec, instruction.name, instruction.operand, instruction.params,
                         instruction.comment, instruction.column, starts, ends)
        builder.add(instruction, end_line, starts, ends)
        return k

    def _add_function(self, line: Line, base: int, number: int, spec: InstructionSpec,
                      params: tuple[ParamValue, ...], last: int,
                      builder: NetworkBuilder) -> int:
        """Add the function `line` (number `number`) makes with its valid parameters from the
        lines after it up to `recs[last]`."""
        comment = line.comment or ""
        column = line.words[0].column
        starts, ends = flow(spec)
        builder.add(new_instruction(spec.name, None, params, comment, (), number, column),
                    base + last, starts, ends)
        return last + 1


    def _unknown_sub(self, line: Line, number: int, sub: int | None, recs: list[Line | Made],
                     base: int, k: int, builder: NetworkBuilder) -> int:
        """`SUB n` the table does not know: every following parameter line is its parameter."""
        column = line.words[1].column
        text = line.words[1].text
        make = getattr(_table, "unknown_sub", None)
        if make is None or sub is None:
            self._error("unknown-sub", number, column, number=text[:20])
            return k
        operands: list[Token] = []
        last = self._collect_params(None, recs, k - 1, operands)
        self.diagnostics.append(Diagnostic("unknown-sub", {"number": sub}, number,
                                           column, Severity.WARNING))
        spec = make(sub, len(operands))
        instruction = self.params.build(spec, line, number, operands)
        if instruction is not None:
            builder.add(instruction, base + last, *flow(spec))
        return last + 1

    def _collect_params(self, spec: InstructionSpec | None, recs: list[Line | Made],
                        last: int, out: list[Token]) -> int:
        """FANUC form: take the parameters from the lines after `recs[last]`, one per line
        (blank lines and lines with a syntax error skipped), as many as `spec` takes (every
        one for None); returns the index of the last line taken (`last` for none)."""
        needed, table = shape(spec) if spec is not None else (0, None)
        size: int | None = None
        sized = False  # the table's size is read once the fixed parameters are all taken
        count = len(recs)
        k = last + 1
        while k < count:
            line = recs[k]
            if line is BLANK or line is BAD:
                k += 1
                continue
            if not isinstance(line, Line) or not line.param:
                break
            if spec is not None and len(out) >= needed:
                if table is None:
                    break
                if not sized:
                    size, sized = table_size(spec, out), True
                if size is None or len(out) >= needed + size:
                    break
            out.append(line.words[0])
            last = k
            k += 1
        return last

    def _error(self, code: str, line: int, column: int, **args: object) -> None:
        self.diagnostics.append(Diagnostic(code, dict(args), line, column))


class NetworkBuilder:
    """Groups instructions into networks: a label, or an RD after an output, starts one.

    Also records which source lines each network came from (`spans()`, 0-based, end
    exclusive): from the end of the previous network to its last instruction or parameter
    line."""

    __slots__ = ("closed", "current", "cursor", "firsts", "heads", "lasts", "networks",
                 "pending", "pending_label")

    def __init__(self, start: int) -> None:
        self.networks: list[Network] = []
        self.current: list[Instruction] | None = None  # the instructions of the last network
        self.closed = False  # the current network has reached an output
        self.pending: list[str] = []
        self.pending_label = ""
        self.cursor = start  # first line index not yet in a network
        self.firsts: list[int] = []  # spans: first line index of each network
        self.lasts: list[int] = []  # spans: end of each network
        self.heads: list[int] = []

    def comment(self, text: str) -> None:
        self.pending.append(text)

    def label(self, text: str) -> None:
        if self.pending_label:  # two labels in a row: the first one labels nothing
            self.pending.append(self.pending_label + ":")
        self.pending_label = text
        self.closed = True

    def add(self, instruction: Instruction, end_line: int, starts: bool, ends: bool) -> None:
        """Add an instruction (its last line `end_line`); `starts`, `ends` are its flow()."""
        current = self.current
        if current is None or (self.closed and (starts or self.pending_label)):
            network = Network(None, self.pending, self.pending_label)  # positional: quicker
            current = self.current = network.instructions
            self.pending = []
            self.pending_label = ""
            self.networks.append(network)
            self.firsts.append(self.cursor)
            self.lasts.append(end_line)
            self.heads.append(instruction.line - 1)
            self.closed = False
        else:
            if self.pending:
                instruction = _with_lead(instruction, self.pending)
                self.pending = []
            self.lasts[-1] = end_line
        current.append(instruction)
        self.cursor = end_line
        if ends:
            self.closed = True

    def spans(self) -> list[tuple[int, int]]:
        """The source lines of each network."""
        return list(zip(self.firsts, self.lasts, strict=True))

    def finish_pending(self) -> list[str]:
        """Comment lines after the last network (a label there is kept as its text)."""
        if self.pending_label:
            self.pending.append(self.pending_label + ":")
            self.pending_label = ""
        return self.pending


def _with_lead(instruction: Instruction, lead: list[str]) -> Instruction:
    return Instruction(instruction.name, instruction.operand, instruction.params,
                       instruction.comment, tuple(lead), instruction.line, instruction.column)

