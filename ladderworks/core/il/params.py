"""Parameters of the ladder section's functional instructions: read and checked against the
instruction table in the program's dialect (`ParamReader`), and the instruction a line makes
with its operands."""

from __future__ import annotations

import re

from ladderworks.core.address import Address, AddressError, parse_address_cached
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.line_scan import Line, Made, Token
from ladderworks.core.il.program import (
    Instruction,
    LabelRef,
    ParamValue,
    ProgramRef,
    new_instruction,
)
from ladderworks.core.instructions import (
    InstructionSpec,
    Kind,
    Param,
    ParamKind,
    value_is_address,
    width_of,
)

_MASK = re.compile(r"^[01]{1,4}$")
_REF = re.compile(r"^([PpLl])0*(\d{1,6})$")
MAX_NUMBER_DIGITS = 12  # a parameter with more digits is out of range (no int() of it)


class ParamReader:
    """Reads parameters for one parse: its diagnostics are the parse's (appended to), its
    dialect gives the upper limits; what a spec's operands made without a diagnostic is kept
    (real programs repeat `SUB 43` with its lines)."""

    def __init__(self, diagnostics: list[Diagnostic], dialect: str) -> None:
        self.diagnostics = diagnostics
        self.dialect = dialect
        self.made_params: dict[tuple[int, tuple[tuple[str, bool], ...]],
                               tuple[ParamValue, ...]] = {}
        # _valid_params' reading of each spec (by id, holding the spec), in this dialect
        self.plans: dict[int, tuple[InstructionSpec,
                                    tuple[tuple[Param, ParamKind, int, int], ...] | None]] = {}

    def valid_params(self, spec: InstructionSpec, recs: list[Line | Made],
                      last: int) -> tuple[tuple[ParamValue, ...], int] | None:
        """The fixed parameters of `spec` from the lines right after `recs[last]`, and the
        index of the last line taken, when they are all there and valid; else None, and the
        lines are read by _collect_params and _params, which report what is wrong.

        One pass with no diagnostic to keep: most functions of a real program are valid."""
        plan = self.plans.get(id(spec))
        if plan is None or plan[0] is not spec:
            plan = self.plans[id(spec)] = (spec, self._plan(spec))
        steps = plan[1]
        if steps is None:
            return None
        end = last + 1 + len(steps)
        lines = recs[last + 1:end]
        if len(lines) < len(steps):
            return None
        values: dict[str, object] = {}
        out: list[ParamValue] = []
        for (param, kind, width, hi), rec in zip(steps, lines, strict=True):
            if rec.__class__ is not Line or not rec.param:
                return None  # a blank line, a syntax error, no parameter: _collect_params
            token = rec.words[0]
            value: ParamValue | None
            # the two common kinds inline (as _valid_param reads them), the others through it
            if kind is _NUMBER and token.is_int and len(token.text) <= MAX_NUMBER_DIGITS:
                value = int(token.text)
                if (param.choices and value not in param.choices) or not (
                        param.lo <= value <= hi):
                    return None
            elif kind is _ADDRESS and not token.is_int:
                try:
                    value = parse_address_cached(token.text, False,
                                                 width or width_of(spec, param, values))
                except AddressError:
                    return None
            else:
                value = self._valid_param(spec, param, token, values)
                if value is None:
                    return None
            values[param.name] = value
            out.append(value)
        return tuple(out), end - 1

    def _plan(self, spec: InstructionSpec) -> tuple[tuple[Param, ParamKind, int, int], ...] | None:
        """For _valid_params: each fixed parameter of `spec` with its kind, its width when
        fixed (else 0) and its upper limit in this program's dialect; None for a spec with
        a TABLE parameter (left to _collect_params)."""
        fixed, table = fixed_and_table(spec)
        if table is not None:
            return None
        return tuple((param, param.kind, param.width if isinstance(param.width, int) else 0,
                      param.highest(self.dialect)) for param in fixed)

    def _valid_param(self, spec: InstructionSpec, param: Param, token: Token,
                     values: dict[str, object]) -> ParamValue | None:
        """What _param gives for a valid parameter; None (and nothing reported) where it
        would report."""
        reported = len(self.diagnostics)
        value = self._param(spec, param, token, 0, values, 0)
        if len(self.diagnostics) > reported:  # the slow path reads it again and reports
            del self.diagnostics[reported:]
            return None
        return value


    def _error(self, code: str, line: int, column: int, **args: object) -> None:
        self.diagnostics.append(Diagnostic(code, dict(args), line, column))

    def build(self, spec: InstructionSpec, line: Line, number: int,
               operands: list[Token]) -> Instruction | None:
        head = line.words[0]
        comment = line.comment or ""
        if spec.kind is Kind.BASIC:
            if not spec.operand:
                if operands:
                    self._error("extra-operand", number, operands[0].column,
                                name=spec.name, text=operands[0].text[:20])
                    return None
                return Instruction(spec.name, comment=comment, line=number,
                                   column=head.column)
            if not operands:
                self._error("missing-operand", number, head.column, name=spec.name)
                return None
            if len(operands) > 1:
                self._error("extra-operand", number, operands[1].column,
                            name=spec.name, text=operands[1].text[:20])
                return None
            address = self._address(operands[0], number, want_bit=True, width=1)
            if address is None:
                return None
            return Instruction(spec.name, address, comment=comment, line=number,
                               column=head.column)
        key = (id(spec), tuple([(token.text, token.is_int) for token in operands]))
        params = self.made_params.get(key)  # real programs repeat `SUB 43` with its lines
        if params is None:
            reported = len(self.diagnostics)
            params = self._params(spec, operands, number, head.column)
            if params is None:
                return None
            if len(self.diagnostics) == reported:
                self.made_params[key] = params
        return new_instruction(spec.name, None, params, comment, (), number, head.column)

    def _address(self, token: Token, line: int, *, want_bit: bool | None,
                 width: int) -> Address | None:
        try:
            return parse_address_cached(token.text, want_bit, width)
        except AddressError as exc:
            args = {k: (v[:20] if isinstance(v, str) and k == "text" else v)
                    for k, v in exc.args_map.items()}
            self._error(exc.code, line, token.column, **args)
            return None

    def _params(self, spec: InstructionSpec, operands: list[Token], line: int,
                column: int) -> tuple[ParamValue, ...] | None:
        fixed, table = fixed_and_table(spec)
        size = table_size(spec, operands) if table else 0
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
                number = self._number(spec, table, token, index, line)
                if number is None:
                    ok = False
                    continue
                out.append(number)
        return tuple(out) if ok else None

    def _param(self, spec: InstructionSpec, param: Param, token: Token, index: int,
               values: dict[str, object], line: int) -> ParamValue | None:
        kind = param.kind
        if kind is ParamKind.NUMBER:
            return self._number(spec, param, token, index, line)
        if kind is ParamKind.MASK:
            if not token.is_int or not _MASK.match(token.text):
                self._error("param-mask", line, token.column, name=spec.name, index=index,
                            param=param.name, text=token.text[:20])
                return None
            return int(token.text, 2)
        if kind is ParamKind.PROGRAM or kind is ParamKind.LABEL:
            return self._reference(spec, param, token, index, line,
                                   "P" if kind is ParamKind.PROGRAM else "L")
        if kind is ParamKind.RAW:
            return self._raw(token, line)
        width = width_of(spec, param, values)
        if param.kind is ParamKind.ADDRESS or (
            param.kind is ParamKind.VALUE and not token.is_int
        ):
            if token.is_int:
                self._error("param-kind-address", line, token.column, name=spec.name,
                            index=index, param=param.name, text=token.text[:20])
                return None
            if param.kind is ParamKind.VALUE and value_is_address(spec, values) is False:
                self._error("param-kind-number", line, token.column, name=spec.name,
                            index=index, param=param.name, text=token.text[:20])
                return None
            return self._address(token, line, want_bit=False, width=width)
        # a VALUE given as a constant
        if value_is_address(spec, values) is True:
            self._error("param-kind-address", line, token.column, name=spec.name,
                        index=index, param=param.name, text=token.text[:20])
            return None
        return self._number(spec, param, token, index, line)

    def _reference(self, spec: InstructionSpec, param: Param, token: Token, index: int,
                   line: int, letter: str) -> ProgramRef | LabelRef | None:
        match = _REF.match(token.text)
        if match is None or match.group(1).upper() != letter:
            self._error("param-kind-ref", line, token.column, name=spec.name, index=index,
                        param=param.name, text=token.text[:20], letter=letter)
            return None
        number = int(match.group(2))
        hi = param.highest(self.dialect)
        if hi and not param.lo <= number <= hi:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=hi, value=token.text)
            return None
        return ProgramRef(number) if letter == "P" else LabelRef(number)

    def _raw(self, token: Token, line: int) -> ParamValue | None:
        """A parameter of an unknown `SUB n`: an integer, an address, `Pn` or `Ln`."""
        if token.is_int:
            value = small_int(token.text, MAX_NUMBER_DIGITS)
            if value is None:
                self._error("number-too-long", line, token.column, text=token.text[:20])
            return value
        match = _REF.match(token.text)
        if match is not None:
            number = int(match.group(2))
            return ProgramRef(number) if match.group(1).upper() == "P" else LabelRef(number)
        return self._address(token, line, want_bit=None, width=1)

    def _number(self, spec: InstructionSpec, param: Param, token: Token, index: int,
                line: int) -> int | None:
        if not token.is_int:
            self._error("param-kind-number", line, token.column, name=spec.name, index=index,
                        param=param.name, text=token.text[:20])
            return None
        value = small_int(token.text, MAX_NUMBER_DIGITS)
        hi = param.highest(self.dialect)
        if value is None:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=hi, value=token.text[:20] + "…")
            return None
        if param.choices and value not in param.choices:
            self._error("param-choice", line, token.column, name=spec.name, index=index,
                        param=param.name, value=value,
                        choices=", ".join(str(c) for c in param.choices))
            return None
        if not param.lo <= value <= hi:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=hi, value=value)
            return None
        return value


def small_int(text: str, digits: int) -> int | None:
    """The integer a token spells, or None when it has more than `digits` digits."""
    body = text.lstrip("+-").lstrip("0")
    return int(text) if len(body) <= digits else None


def table_size(spec: InstructionSpec, operands: list[Token]) -> int | None:
    """Number of table entries, read from the parameter that gives it (None if unknown)."""
    fixed, table = fixed_and_table(spec)
    if table is None:
        return 0
    for index, param in enumerate(fixed):
        if param.name == table.length_of and index < len(operands):
            token = operands[index]
            if token.is_int:
                value = small_int(token.text, MAX_NUMBER_DIGITS)
                return value if value is not None and param.lo <= value <= param.hi else None
    return None


def fixed_and_table(spec: InstructionSpec) -> tuple[tuple[Param, ...], Param | None]:
    """A spec's fixed parameters and its TABLE parameter (found once per row)."""
    found = _SHAPES.get(id(spec))
    if found is None or found[0] is not spec:
        found = _SHAPES[id(spec)] = (spec, spec.fixed_params(), spec.table_param())
    return found[1], found[2]


def shape(spec: InstructionSpec) -> tuple[int, Param | None]:
    """The number of fixed parameters of a spec and its TABLE parameter."""
    fixed, table = fixed_and_table(spec)
    return len(fixed), table


# by id(spec), holding the spec (so the id is not reused while the entry lives)
_SHAPES: dict[int, tuple[InstructionSpec, tuple[Param, ...], Param | None]] = {}


_NUMBER = ParamKind.NUMBER  # the kinds _valid_params reads inline, as module names
_ADDRESS = ParamKind.ADDRESS
