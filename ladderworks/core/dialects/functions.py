"""A dialect's functional rows for the tool palette, and their parameters checked by its reader."""

from __future__ import annotations

from functools import cache

from ladderworks.core import dialects
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import ParamValue
from ladderworks.core.instructions import (
    BY_NAME,
    Combine,
    Flow,
    InstructionSpec,
    Kind,
    Param,
    lookup,
)

# Parameters a dialect's text does not write as operands: Fatek's 32-bit/pulse forms (`mode`),
# its FO relay byte (`fo`) and function number (`fun`) (core/dialects/fatek/printer.py).
NOT_OPERANDS = frozenset({"mode", "fo", "fun"})


def operand_params(spec: InstructionSpec) -> tuple[Param, ...]:
    """The parameters typed as operands of a line of `spec`'s text, in the line's order."""
    if not spec.dialect:
        return spec.params
    return tuple(param for param in spec.params if param.name not in NOT_OPERANDS)


def _one_line(spec: InstructionSpec, found: dialects.Dialect) -> bool:
    """True when the dialect writes `spec` as one step line its reader reads back alone (not
    Fatek's `FUN n` head with operand lines, its `ORG TU` contacts, nor a `kind`+`number`
    pair written as one operand: not offered yet)."""
    if found.instruction_name(spec).startswith("FUN"):
        return False
    if any(param.name == "kind" for param in spec.params):
        return False
    _params, problems = check_params(spec, [], found.name)
    return not any(problem.code.endswith("unknown-instruction") for problem in problems)


@cache
def palette_rows(dialect: str | None) -> tuple[InstructionSpec, ...]:
    """The boxes a program of `dialect` may place: its functional rows that are not contacts
    (no `pushes`/`combine`) nor program structure (no `flow`), written as one line, in the
    table's order."""
    found = dialects.get(dialect)
    if found is None:
        return ()
    seen: dict[str, InstructionSpec] = {}
    for spec in BY_NAME.values():
        if (spec.dialect == dialect and spec.kind is Kind.FUNCTION and not spec.pushes
                and spec.combine is Combine.NONE and spec.flow is Flow.NONE
                and spec.name not in seen and _one_line(spec, found)):
            seen[spec.name] = spec
    return tuple(seen.values())


def check_params(spec: InstructionSpec, texts: list[str], dialect: str
                 ) -> tuple[tuple[ParamValue, ...] | None, list[Diagnostic]]:
    """Typed operands of `spec` read exactly as the dialect's reader reads a line of its text
    (after a contact on X0), with the errors it gives."""
    from ladderworks.core.il.reading import parse_text

    found = dialects.get(dialect)
    if found is None:
        raise ValueError(dialect)
    read = lookup("RD")
    assert read is not None
    head = [f"{found.instruction_name(read)} X0"]  # X0: an input of every dialect
    line = " ".join([found.instruction_name(spec), *(t.strip() for t in texts if t.strip())])
    result = parse_text("\n".join([*head, line, "END", ""]), dialect)
    errors = [d for d in result.diagnostics if d.is_error]
    if errors:
        return None, errors
    for instruction in result.program.instructions():
        if instruction.name == spec.name:
            return instruction.params, []
    return None, [d for d in result.diagnostics]
