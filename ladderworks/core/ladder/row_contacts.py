"""Contacts made of a dialect's functional row: edge (↑/↓) and comparison contacts.

A Delta LDP/ANDF/LD=/OR>= … or a Fatek TU/TD/FUN 170–175 is a row of kind FUNCTION that acts
as a contact: by its fields (`combine`, `pushes`, `operation`), never by its spelling. The ladder
draws it as a `Contact` whose `function` names the row it was read with and `params` its
operands; coding picks the row of the same dialect and operation for the contact's place."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ladderworks.core.address import Address, Area
from ladderworks.core.instructions import (
    BY_NAME,
    Combine,
    InstructionSpec,
    Kind,
    Operation,
    lookup,
    shown_name,
)

if TYPE_CHECKING:
    from ladderworks.core.dialects.spelling import Spelling
    from ladderworks.core.ladder.model import Contact

EDGES = frozenset((Operation.RISING, Operation.FALLING))
COMPARISONS = frozenset((Operation.EQUAL, Operation.GREATER, Operation.LESS,
                         Operation.NOT_EQUAL, Operation.LESS_EQUAL, Operation.GREATER_EQUAL))
_TESTS = EDGES | COMPARISONS
MARKS = {Operation.RISING: "↑", Operation.FALLING: "↓"}


def contact_combine(spec: InstructionSpec) -> Combine | None:
    """How a functional row joins the result as a contact, or None when it is a box.

    A row with `combine` (Delta) joins so; a one-input row with W1 that tests an edge or a
    comparison (Fatek's TU/TD/FUN 170–175: IN AND the test) is a series (AND) contact."""
    if spec.kind is not Kind.FUNCTION:
        return None
    if spec.combine is not Combine.NONE and not spec.simulated:  # shown only (never conducts)
        return spec.combine
    if spec.operation not in _TESTS:
        return None
    if spec.combine is not Combine.NONE:
        return spec.combine
    if len(spec.inputs) == 1 and spec.w1:
        return Combine.AND
    return None


_FOUND: dict[tuple[str, Operation, Combine, int, object], InstructionSpec] = {}


def operand_width(spec: InstructionSpec) -> object:
    """The width and name of a contact row's last operand: a 32-bit comparison (Delta DLD=) is
    coded with the 32-bit rows, a 16-bit one with the 16-bit rows, a floating-point one (FLD=,
    operands f1, f2) with the floating-point rows."""
    return (spec.params[-1].width, spec.params[-1].name) if spec.params else 0


def _rows(dialect: str, operation: Operation, combine: Combine, pushes: int, width: object
          ) -> InstructionSpec | None:
    key = (dialect, operation, combine, pushes, width)
    if key not in _FOUND:  # only hits are kept: a dialect registered later is still found
        for spec in list(BY_NAME.values()):
            if (spec.kind is Kind.FUNCTION and spec.dialect == dialect
                    and spec.operation is operation and contact_combine(spec) is combine
                    and spec.pushes == pushes and operand_width(spec) == width):
                _FOUND[key] = spec
                break
        else:
            return None
    return _FOUND[key]


def _shown_base(dialect: str, combine: Combine, pushes: int) -> InstructionSpec | None:
    """A dialect's shown-only contact row (no mnemonic of its own) joining by `combine`."""
    for spec in list(BY_NAME.values()):
        if (spec.kind is Kind.FUNCTION and spec.dialect == dialect and not spec.simulated
                and spec.combine is combine and spec.pushes == pushes):
            return spec
    return None


def row_for(function: str, combine: Combine, push: bool) -> InstructionSpec | None:
    """The row that codes a contact made of row `function` at a place that joins by `combine`
    (`push`: an RD.STK place), or None when the dialect has no such row (Fatek's TU has only
    the series form: it is read after a SHORT contact or another block)."""
    spec = lookup(function)
    if spec is None:
        return None
    if not spec.simulated:  # a shown-only contact: its dialect's shown row for the place
        base = _shown_base(spec.dialect, combine, 1 if push else 0)
        return None if base is None else lookup(shown_name(base, spec.text_name,
                                                            spec.operand_texts))
    if spec.combine is Combine.NONE:  # the one-input form joins only in series
        return spec if combine is Combine.AND and not push else None
    return _rows(spec.dialect, spec.operation, combine, 1 if push else 0, operand_width(spec))


def mark(function: str) -> str:
    """What the contact shows in its middle: ↑ / ↓ for an edge, the operator for a comparison."""
    spec = lookup(function)
    if spec is None:
        return "?"
    if spec.operation not in _TESTS:  # INV, a contact not simulated: its mnemonic
        return spec.text_name
    return MARKS.get(spec.operation, spec.operation.value)


def operands(function: str, params: tuple[object, ...]) -> tuple[object, ...]:
    """The operands the contact shows: an edge's device, a comparison's two values (a Fatek
    row's leading mode number is not one)."""
    return params[-1:] if is_edge(function) else params[-2:]


def shown_mark(contact: Contact) -> str:
    """The contact's own mark (a source's P, >=), else its row's (`mark`)."""
    return contact.mark or mark(contact.function)


def operand_texts(contact: Contact, spell: Spelling) -> list[str]:
    """The contact's operands in the program's spelling (`X2`; `T0`, `K100`), or as its
    source writes them (`texts`)."""
    if contact.texts:
        return list(contact.texts)
    spec = lookup(contact.function)
    if spec is None:
        return [str(value) for value in contact.params]
    texts = spell.params(spec, contact.params)
    return texts[-1:] if is_edge(contact.function) else texts[-2:]


# The engine's always-1 system relay (R9091.1, core/plc/engine.py): Fatek's SHORT, the contact
# its reader puts before a series-only contact at the start of a rung (`ORG TU X2`).
ALWAYS_ON = Address(Area.R, 9091, 1)


def needs_lead(function: str) -> bool:
    """True for a contact row with only its series form (Fatek's TU/TD/FUN 170-175): on the
    rail it needs a contact before it, as its reader reads `ORG TU X2` (SHORT, then TU)."""
    return (row_for(function, Combine.READ, False) is None
            and row_for(function, Combine.AND, False) is not None)


def simulated(function: str) -> bool:
    """False for a contact the simulator passes by (a shown-only row: it never conducts)."""
    spec = lookup(function)
    return spec is None or spec.simulated


def is_edge(function: str) -> bool:
    """True for an edge contact (its one operand is a bit device)."""
    spec = lookup(function)
    return spec is not None and spec.operation in EDGES
