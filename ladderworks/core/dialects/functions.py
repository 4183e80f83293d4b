"""A dialect's rows for the tool palette (boxes, program structure, contacts), and their
operands checked by its reader."""

from __future__ import annotations

from collections.abc import Callable, Iterable
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
from ladderworks.core.ladder.row_contacts import contact_combine, operand_width

# Parameters a dialect's text does not write as operands of their own: Fatek's FO relay byte
# (`fo`), function number (`fun`) and the T/C `kind` of RST written with its number (`T5`),
# Delta MC's coil count (`coils`, always 0) (core/dialects/*/printer.py).
NOT_OPERANDS = frozenset({"fo", "fun", "kind", "coils"})

# The palette's groups of a dialect program, by what the rows do: `<dialect>` its boxes,
# `<dialect>.structure` program structure, `<dialect>.contacts` edge and comparison contacts.
STRUCTURE = ".structure"
CONTACTS = ".contacts"


def operand_params(spec: InstructionSpec) -> tuple[Param, ...]:
    """The parameters typed as operands of a line of `spec`'s text, in the line's order
    (Fatek's `mode` is the first: its forms, `P`, `D`, `DP` or empty)."""
    if not spec.dialect:
        return spec.params
    return tuple(param for param in spec.params if param.name not in NOT_OPERANDS)


def is_contact(spec: InstructionSpec) -> bool:
    """True for a dialect's row placed as a contact (an edge or comparison contact)."""
    return contact_combine(spec) is not None


def _offered(spec: InstructionSpec, found: dialects.Dialect) -> bool:
    """True when the dialect's text writes `spec` in a form its reader reads back (its probe
    lines read as the row) and the row is simulated (`cnc` rows are kept, not run)."""
    if spec.cnc:
        return False
    if spec.flow in (Flow.LABEL, Flow.SUBPROGRAM) and len(spec.params) == 1:
        return True  # a pointer line is its operand alone (not Delta's FOR: a label and more)
    _params, problems = check_params(spec, [], found.name)
    return not any(problem.code.endswith("unknown-instruction") for problem in problems)


def _rows(dialect: str) -> list[InstructionSpec]:
    seen: dict[str, InstructionSpec] = {}
    for spec in list(BY_NAME.values()):
        if spec.dialect == dialect and spec.kind in (Kind.FUNCTION, Kind.END) \
                and spec.simulated:  # a shown-only row is read from a file, never placed
            seen.setdefault(spec.name, spec)
    return list(seen.values())


@cache
def palette_rows(dialect: str | None) -> tuple[InstructionSpec, ...]:
    """The boxes a program of `dialect` may place: its functional rows that are not contacts
    (no `pushes`/`combine`, no edge/comparison `operation` on one input) nor program structure
    (no `flow`), that its reader reads back alone, in the table's order."""
    found = dialects.get(dialect)
    if found is None:
        return ()
    return tuple(spec for spec in _rows(found.name)
                 if spec.kind is Kind.FUNCTION and not spec.pushes
                 and spec.combine is Combine.NONE and spec.flow is Flow.NONE
                 and not is_contact(spec) and _offered(spec, found))


def _program_end(found: dialects.Dialect) -> tuple[InstructionSpec, ...]:
    """The table's END row when the dialect's text has it as an instruction of its own
    (Delta's END; a Fatek listing's END is written by its printer, after every network)."""
    from ladderworks.core.families import program_end

    end = program_end(found.name)
    return () if end is None else (end,)


@cache
def structure_rows(dialect: str | None) -> tuple[InstructionSpec, ...]:
    """The program-structure rows a program of `dialect` may place (Delta's CJ, CALL, P,
    SRET, FEND, MC/MCR, END): its rows with a `flow`, as boxes."""
    found = dialects.get(dialect)
    if found is None:
        return ()
    return tuple(spec for spec in _rows(found.name)
                 if spec.flow is not Flow.NONE and not spec.pushes
                 and spec.combine is Combine.NONE and _offered(spec, found)) \
        + _program_end(found)


@cache
def contact_rows(dialect: str | None) -> tuple[InstructionSpec, ...]:
    """The edge and comparison contacts of `dialect`, one row per `operation`: the one that
    starts a rung (READ, no push) where the dialect has it, else its series form (Fatek's
    TU/TD/FUN 170-175). Coding picks the row of the contact's place (`row_contacts.row_for`)."""
    found = dialects.get(dialect)
    if found is None:
        return ()
    chosen: dict[object, InstructionSpec] = {}
    for spec in _rows(found.name):
        if not is_contact(spec) or not _offered(spec, found):
            continue
        key = (spec.operation, operand_width(spec))  # Delta's DLD= apart from LD=
        known = chosen.get(key)
        if known is None or (spec.combine is Combine.READ and not spec.pushes
                             and known.combine is not Combine.READ):
            chosen[key] = spec
    return tuple(chosen.values())


def palette_groups(dialect: str | None) -> tuple[tuple[str, tuple[InstructionSpec, ...]], ...]:
    """A dialect program's palette groups (key, rows): boxes, structure, contacts; empty ones
    left out; () for a PMC program."""
    name = str(dialect)
    groups = ((name, palette_rows(dialect)), (name + STRUCTURE, structure_rows(dialect)),
              (name + CONTACTS, contact_rows(dialect)))
    return tuple((key, rows) for key, rows in groups if rows)


def same_operation(spec: InstructionSpec) -> tuple[InstructionSpec, ...]:
    """The contact rows of `spec`'s dialect with its `operation` (LD=, AND=, OR=), in the
    table's order, one per spelling: what a contact offered as `spec` may be written as."""
    spelled: dict[str, InstructionSpec] = {}
    for row in _rows(spec.dialect):
        if is_contact(row) and row.operation is spec.operation \
                and operand_width(row) == operand_width(spec):
            spelled.setdefault(row.text_name, row)
    return tuple(spelled.values())


def _default_probe(spec: InstructionSpec, texts: list[str], found: dialects.Dialect
                   ) -> list[str]:
    """The line of `spec` with its operands, after a contact on X0 when it has inputs."""
    read = lookup("RD")
    assert read is not None
    head = [f"{found.instruction_name(read)} X0"] if spec.inputs else []  # X0: in every dialect
    return [*head, " ".join([found.instruction_name(spec), *(t.strip() for t in texts
                                                           if t.strip())])]


def operand_texts(spec: InstructionSpec, params: tuple[ParamValue, ...]) -> list[str]:
    """The operands of an instruction of `spec` as its dialect writes them, one a typed operand
    (`K5`, `D10`; Fatek's forms `P` then `R0`)."""
    from ladderworks.core.dialects.spelling import spelling

    found = dialects.get(spec.dialect)
    if found is not None and found.operand_texts:
        texts: Callable[..., list[str]] = found.function(found.operand_texts)  # type: ignore
        return texts(spec, params)
    return spelling(spec.dialect).params(spec, params)


def check_params(spec: InstructionSpec, texts: list[str], dialect: str
                 ) -> tuple[tuple[ParamValue, ...] | None, list[Diagnostic]]:
    """Typed operands of `spec` read exactly as the dialect's reader reads its text (the
    dialect's probe lines: after a contact on X0, or alone), with the errors it gives; an
    error without the operand's index gets the index of the operand it names."""
    from ladderworks.core.il.reading import parse_text

    found = dialects.get(dialect)
    if found is None:
        raise ValueError(dialect)
    if found.probe:
        probe: Callable[..., list[str]] = found.function(found.probe)  # type: ignore
        lines = probe(spec, texts)
    else:
        lines = _default_probe(spec, texts, found)
    result = parse_text("\n".join([*lines, "END", ""]), dialect)
    errors = [_indexed(d, texts) for d in result.diagnostics if d.is_error]
    if errors:
        return None, errors
    for instruction in result.program.instructions():
        if instruction.name == spec.name:
            return instruction.params, []
    return None, [d for d in result.diagnostics]


def _indexed(diagnostic: Diagnostic, texts: list[str]) -> Diagnostic:
    """The diagnostic with `index` (1-based) of the typed operand it quotes, where it has none."""
    from dataclasses import replace

    text = diagnostic.args.get("text")
    if "index" in diagnostic.args or not isinstance(text, str):
        return diagnostic
    for index, typed in enumerate(texts):
        if typed.strip() and typed.strip().upper() == text.strip().upper():
            return replace(diagnostic, args={**diagnostic.args, "index": index + 1})
    return diagnostic


def placed_params(spec: InstructionSpec, params: tuple[ParamValue, ...],
                  others: Iterable[tuple[InstructionSpec, tuple[ParamValue, ...]]]
                  ) -> tuple[ParamValue, ...]:
    """The params of a box of `spec` placed in a program whose other boxes are `others`, as
    its dialect gives them (Fatek: its own FO byte); unchanged for a dialect without."""
    found = dialects.get(spec.dialect)
    if found is None or not found.placed:
        return params
    placed: Callable[..., tuple[ParamValue, ...]] = found.function(found.placed)  # type: ignore
    return placed(spec, params, others)
