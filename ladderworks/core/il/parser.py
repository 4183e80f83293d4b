"""Parser from `.LAD` / `.MOD` text to a Program, with diagnostics instead of exceptions."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from importlib import resources
from pathlib import Path

import lark

from ladderworks.core.address import Address, AddressError, parse_address
from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il.program import Instruction, Network, ParamValue, Program, Section
from ladderworks.core.instructions import (
    BY_SUB,
    InstructionSpec,
    Kind,
    Param,
    ParamKind,
    lookup,
    value_is_address,
    width_of,
)

_SECTION_START = re.compile(r"^\s*%@\s*(\d+)\s*$")
_SECTION_END = re.compile(r"^\s*%\s*$")
_MASK = re.compile(r"^[01]{1,4}$")


@dataclass(slots=True)
class ParseResult:
    """A parsed program with its diagnostics and the text encoding that was read."""

    program: Program
    diagnostics: list[Diagnostic] = field(default_factory=list)
    encoding: str = "utf-8"

    @property
    def ok(self) -> bool:
        """True when there is no error (warnings allowed)."""
        return not has_errors(self.diagnostics)


@lru_cache(maxsize=1)
def line_parser() -> lark.Lark:
    """The lark parser for one line, loaded once from grammar.lark."""
    grammar = resources.files("ladderworks.core.il").joinpath("grammar.lark").read_text("utf-8")
    return lark.Lark(grammar, start="line", parser="lalr", maybe_placeholders=False)


def decode(data: bytes) -> tuple[str, str]:
    """Decode file bytes as UTF-8 (BOM allowed) or else Turkish Windows cp1254."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        return data.decode("cp1254", errors="replace"), "cp1254"


def parse_bytes(data: bytes) -> ParseResult:
    """Parse file contents given as bytes."""
    text, encoding = decode(data)
    result = parse(text)
    result.encoding = encoding
    return result


def parse_file(path: str | Path) -> ParseResult:
    """Parse a `.LAD` / `.MOD` file."""
    return parse_bytes(Path(path).read_bytes())


def parse(text: str) -> ParseResult:
    """Parse program text; never raises for bad input, returns diagnostics instead."""
    return _FileParser(text).run()


@dataclass(slots=True)
class _Token:
    text: str
    column: int
    is_int: bool


@dataclass(slots=True)
class _Line:
    """One parsed line of the ladder section."""

    number: int
    kind: str  # "blank", "comment", "instruction", "parameter"
    words: list[_Token] = field(default_factory=list)
    comment: str | None = None


def _comment_text(raw: str) -> str:
    """Comment body after its marker (`//`, `;` or `,`), right-stripped."""
    body = raw[2:] if raw.startswith("//") else raw[1:]
    return body.rstrip()


def _scan_line(text: str, number: int) -> _Line | Diagnostic:
    """Run the lark grammar on one line."""
    try:
        tree = line_parser().parse(text)
    except lark.exceptions.UnexpectedInput as exc:
        column = getattr(exc, "column", 1) or 1
        bad = text[column - 1:].split()[0] if text[column - 1:].split() else text.strip()
        return Diagnostic("syntax", {"text": bad}, number, column)
    kind = tree.data
    if kind == "blank_line":
        return _Line(number, "blank")
    if kind == "comma_comment_line":
        return _Line(number, "comment", comment=_comment_text(str(tree.children[0]).strip()))
    if kind == "comment_line":
        raw = str(tree.children[0].children[0])
        return _Line(number, "comment", comment=_comment_text(raw))
    statement = tree.children[0]
    comment: str | None = None
    if len(tree.children) > 1:
        comment = _comment_text(str(tree.children[1].children[0])).strip()
    if statement.data == "parameter_line":
        tok = statement.children[0]
        return _Line(number, "parameter", [_Token(str(tok), tok.column, True)], comment)
    words = [_Token(str(statement.children[0]), statement.children[0].column, False)]
    for operand in statement.children[1:]:
        tok = operand.children[0]
        words.append(_Token(str(tok), tok.column, operand.data == "int_operand"))
    return _Line(number, "instruction", words, comment)


class _FileParser:
    """Splits the file into sections and parses the ladder section into networks."""

    def __init__(self, text: str) -> None:
        self.lines = text.splitlines()
        self.program = Program()
        self.diagnostics: list[Diagnostic] = []

    def run(self) -> ParseResult:
        ladder_body: list[tuple[int, str]] | None = None
        i = 0
        seen_sections: set[int] = set()
        has_any_section = any(_SECTION_START.match(line) for line in self.lines)
        if not has_any_section:
            self.diagnostics.append(Diagnostic("missing-start", {}, 1, 1))
            body = [(n + 1, line) for n, line in enumerate(self.lines)]
            if body and _SECTION_END.match(body[-1][1]):
                body.pop()
            self._parse_ladder(body)
            return self._result()
        while i < len(self.lines):
            line = self.lines[i]
            start = _SECTION_START.match(line)
            stripped = line.strip()
            if start:
                number = int(start.group(1))
                if number > 5:
                    self.diagnostics.append(Diagnostic("bad-section", {"number": number}, i + 1, 1))
                if number in seen_sections:
                    self.diagnostics.append(
                        Diagnostic("duplicate-section", {"number": number}, i + 1, 1))
                seen_sections.add(number)
                j = i + 1
                while j < len(self.lines) and not _SECTION_END.match(self.lines[j]):
                    if _SECTION_START.match(self.lines[j]):
                        break
                    j += 1
                closed = j < len(self.lines) and bool(_SECTION_END.match(self.lines[j]))
                if not closed:
                    self.diagnostics.append(
                        Diagnostic("missing-end", {}, min(j, len(self.lines)), 1))
                if number == 3 and ladder_body is None:
                    ladder_body = [(n + 1, self.lines[n]) for n in range(i + 1, j)]
                else:
                    section = Section(number, self.lines[i + 1:j])
                    (self.program.after if ladder_body is not None else self.program.before
                     ).append(section)
                i = j + 1 if closed else j
                continue
            if not stripped:
                pass
            elif stripped.startswith(("//", ";", ",")):
                target = self.program.header if ladder_body is None else self.program.footer
                target.append(_comment_text(stripped))
            else:
                self.diagnostics.append(
                    Diagnostic("text-outside-section", {"text": stripped[:40]}, i + 1,
                               len(line) - len(line.lstrip()) + 1))
            i += 1
        if ladder_body is None:
            self.diagnostics.append(Diagnostic("missing-start", {}, 1, 1))
            ladder_body = []
        self._parse_ladder(ladder_body)
        return self._result()

    def _result(self) -> ParseResult:
        self.diagnostics.sort(key=lambda d: (d.line, d.column))
        return ParseResult(self.program, self.diagnostics)

    # -- the ladder section -------------------------------------------------------------

    def _parse_ladder(self, body: list[tuple[int, str]]) -> None:
        scanned: list[_Line] = []
        for number, text in body:
            item = _scan_line(text, number)
            if isinstance(item, Diagnostic):
                self.diagnostics.append(item)
            elif item.kind != "blank":
                scanned.append(item)
        builder = _NetworkBuilder()
        k = 0
        while k < len(scanned):
            line = scanned[k]
            k += 1
            if line.kind == "comment":
                builder.comment(line.comment or "")
                continue
            if line.kind == "parameter":
                self._error("stray-parameter", line.number, line.words[0].column,
                            text=line.words[0].text)
                continue
            head = line.words[0]
            operands = line.words[1:]
            spec = lookup(head.text)
            if spec is None:
                if len(operands) == 0 and _looks_like_address(head.text):
                    self._error("stray-parameter", line.number, head.column, text=head.text)
                else:
                    self._error("unknown-instruction", line.number, head.column,
                                name=head.text)
                continue
            if spec.name == "SUB" and len(operands) == 1 and operands[0].is_int:
                number = int(operands[0].text)
                sub_spec = BY_SUB.get(number)
                if sub_spec is None:
                    self._error("unknown-sub", line.number, operands[0].column, number=number)
                    continue
                spec = sub_spec
                operands = []
                k = self._collect_params(spec, scanned, k, operands)
            elif spec.kind is not Kind.BASIC and not operands and spec.params:
                k = self._collect_params(spec, scanned, k, operands)
            instruction = self._build(spec, line, operands)
            if instruction is not None:
                builder.add(instruction)
        self.program.networks = builder.finish()
        self.program.trailer = builder.pending

    def _collect_params(self, spec: InstructionSpec, scanned: list[_Line], k: int,
                        out: list[_Token]) -> int:
        """FANUC form: take the parameters from the following lines, one per line."""
        needed = len(spec.fixed_params())
        table = spec.table_param()
        while k < len(scanned):
            line = scanned[k]
            if line.kind == "parameter" or (
                line.kind == "instruction" and len(line.words) == 1
                and lookup(line.words[0].text) is None
                and _looks_like_address(line.words[0].text)
            ):
                if len(out) >= needed:
                    if table is None:
                        break
                    size = _table_size(spec, out)
                    if size is None or len(out) >= needed + size:
                        break
                out.append(line.words[0])
                k += 1
                continue
            break
        return k

    def _error(self, code: str, line: int, column: int, **args: object) -> None:
        self.diagnostics.append(Diagnostic(code, dict(args), line, column))

    def _build(self, spec: InstructionSpec, line: _Line,
               operands: list[_Token]) -> Instruction | None:
        head = line.words[0]
        comment = line.comment or ""
        if spec.kind is Kind.BASIC:
            if not spec.operand:
                if operands:
                    self._error("extra-operand", line.number, operands[0].column,
                                name=spec.name, text=operands[0].text)
                    return None
                return Instruction(spec.name, comment=comment, line=line.number,
                                   column=head.column)
            if not operands:
                self._error("missing-operand", line.number, head.column, name=spec.name)
                return None
            if len(operands) > 1:
                self._error("extra-operand", line.number, operands[1].column,
                            name=spec.name, text=operands[1].text)
                return None
            address = self._address(operands[0], line.number, want_bit=True, width=1)
            if address is None:
                return None
            return Instruction(spec.name, address, comment=comment, line=line.number,
                               column=head.column)
        params = self._params(spec, operands, line.number, head.column)
        if params is None:
            return None
        return Instruction(spec.name, params=params, comment=comment, line=line.number,
                           column=head.column)

    def _address(self, token: _Token, line: int, *, want_bit: bool,
                 width: int) -> Address | None:
        try:
            return parse_address(token.text, want_bit=want_bit, width=width)
        except AddressError as exc:
            self._error(exc.code, line, token.column, **exc.args_map)
            return None

    def _params(self, spec: InstructionSpec, operands: list[_Token], line: int,
                column: int) -> tuple[ParamValue, ...] | None:
        fixed = spec.fixed_params()
        table = spec.table_param()
        size = _table_size(spec, operands) if table else 0
        expected = len(fixed) + (size or 0)
        if len(operands) < len(fixed) or (table is None and len(operands) != len(fixed)) or (
            table is not None and size is not None and len(operands) != expected
        ):
            self._error("param-count", line, operands[-1].column if operands else column,
                        name=spec.name, expected=expected, found=len(operands))
            return None
        values: dict[str, object] = {}
        out: list[ParamValue] = []
        ok = True
        for index, (param, token) in enumerate(zip(fixed, operands, strict=False), start=1):
            value = self._param(spec, param, token, index, values, line)
            if value is None:
                ok = False
                continue
            values[param.name] = value
            out.append(value)
        if table is not None:
            for offset, token in enumerate(operands[len(fixed):]):
                index = len(fixed) + offset + 1
                value = self._number(spec, table, token, index, line)
                if value is None:
                    ok = False
                    continue
                out.append(value)
        return tuple(out) if ok else None

    def _param(self, spec: InstructionSpec, param: Param, token: _Token, index: int,
               values: dict[str, object], line: int) -> ParamValue | None:
        if param.kind is ParamKind.NUMBER:
            return self._number(spec, param, token, index, line)
        if param.kind is ParamKind.MASK:
            if not token.is_int or not _MASK.match(token.text):
                self._error("param-mask", line, token.column, name=spec.name, index=index,
                            param=param.name, text=token.text)
                return None
            return int(token.text, 2)
        width = width_of(spec, param, values)
        if param.kind is ParamKind.ADDRESS or (
            param.kind is ParamKind.VALUE and not token.is_int
        ):
            if token.is_int:
                self._error("param-kind-address", line, token.column, name=spec.name,
                            index=index, param=param.name, text=token.text)
                return None
            if param.kind is ParamKind.VALUE and value_is_address(spec, values) is False:
                self._error("param-kind-number", line, token.column, name=spec.name,
                            index=index, param=param.name, text=token.text)
                return None
            return self._address(token, line, want_bit=False, width=width)
        # a VALUE given as a constant
        if value_is_address(spec, values) is True:
            self._error("param-kind-address", line, token.column, name=spec.name,
                        index=index, param=param.name, text=token.text)
            return None
        return self._number(spec, param, token, index, line)

    def _number(self, spec: InstructionSpec, param: Param, token: _Token, index: int,
                line: int) -> int | None:
        if not token.is_int:
            self._error("param-kind-number", line, token.column, name=spec.name, index=index,
                        param=param.name, text=token.text)
            return None
        value = int(token.text)
        if param.choices and value not in param.choices:
            self._error("param-choice", line, token.column, name=spec.name, index=index,
                        param=param.name, value=value,
                        choices=", ".join(str(c) for c in param.choices))
            return None
        if not param.lo <= value <= param.hi:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=param.hi, value=value)
            return None
        return value


def _looks_like_address(text: str) -> bool:
    return bool(re.match(r"^[A-Za-z]\d+(\.\d+)?$", text))


def _table_size(spec: InstructionSpec, operands: list[_Token]) -> int | None:
    """Number of table entries, read from the parameter that gives it (None if unknown)."""
    table = spec.table_param()
    if table is None:
        return 0
    fixed = spec.fixed_params()
    for index, param in enumerate(fixed):
        if param.name == table.length_of and index < len(operands):
            token = operands[index]
            if token.is_int:
                value = int(token.text)
                return value if param.lo <= value <= param.hi else None
    return None


class _NetworkBuilder:
    """Groups instructions into networks: a new one starts at an RD after an output."""

    def __init__(self) -> None:
        self.networks: list[Network] = []
        self.current: Network | None = None
        self.closed = False  # the current network has reached an output
        self.pending: list[str] = []

    def comment(self, text: str) -> None:
        self.pending.append(text)

    def add(self, instruction: Instruction) -> None:
        spec = instruction.spec
        starts = instruction.name in ("RD", "RD.NOT") or (
            spec.kind is not Kind.BASIC and not spec.inputs
        )
        if self.current is None or (starts and self.closed):
            self.current = Network(comments=self.pending)
            self.pending = []
            self.networks.append(self.current)
            self.closed = False
        elif self.pending:
            instruction = _with_lead(instruction, self.pending)
            self.pending = []
        self.current.instructions.append(instruction)
        if spec.writes or spec.kind is not Kind.BASIC:
            self.closed = True

    def finish(self) -> list[Network]:
        return self.networks


def _with_lead(instruction: Instruction, lead: list[str]) -> Instruction:
    return Instruction(instruction.name, instruction.operand, instruction.params,
                       instruction.comment, tuple(lead), instruction.line, instruction.column)
