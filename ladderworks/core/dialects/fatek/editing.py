"""What the function dialog shows and reads for a Fatek row: its forms (`P`, `D`, `DP`) and
operands, checked as the listing lines WinProladder prints for them (`FUN 11P (+)`, `Sa: R0`)."""

from __future__ import annotations

from collections.abc import Iterable

from ladderworks.core.dialects.fatek.devices import FO_BOXES, fo_address
from ladderworks.core.dialects.fatek.printer import params_text
from ladderworks.core.dialects.fatek.rows import OTHER, SERIES_OF, SUB_BASE, operand_label
from ladderworks.core.il.program import ParamValue
from ladderworks.core.instructions import InstructionSpec, Operation

MODE = "mode"  # the forms parameter: bit 0 the P (pulse) form, bit 1 the D (32-bit) form
_EDGES = (Operation.RISING, Operation.FALLING)
_HIDDEN = frozenset({"fo", "fun", "kind", MODE})


def forms_text(mode: object) -> str:
    """The forms a `mode` value writes after FUN n: "", "P", "D" or "DP"."""
    value = mode if isinstance(mode, int) else 0
    return ("D" if value & 2 else "") + ("P" if value & 1 else "")


def _labels(spec: InstructionSpec) -> list[str]:
    """The operand lines' labels, as the printer writes them (the destination is `D`)."""
    labels = []
    for param in spec.params:
        if param.name in _HIDDEN:
            continue
        labels.append(operand_label(param.name))
    return labels


def operand_texts(spec: InstructionSpec, params: tuple[ParamValue, ...]) -> list[str]:
    """A placed box's typed operands: its forms first when it has them, then its operands."""
    named = dict(zip((p.name for p in spec.params), params, strict=False))
    head = [forms_text(named.get(MODE, 0))] if any(p.name == MODE for p in spec.params) else []
    return [*head, *params_text(spec, params)]


def probe_lines(spec: InstructionSpec, texts: list[str]) -> list[str]:
    """The listing lines of `spec` with the typed texts, after `ORG X0`: a FUN box's head and
    one operand line each, an edge contact `AND TU X1`, a comparison `ANDF 170 (=)` with
    `Sa:`/`Sb:` lines, TMR/CTR/RST on one line."""
    values = [text.strip() for text in texts]
    forms = ""
    if any(p.name == MODE for p in spec.params):
        forms = values[0].upper() if values else ""
        values = values[1:]
    sub = spec.sub or 0
    fun = sub - SUB_BASE
    series = SERIES_OF.get(spec.name)
    if series is not None or spec.inputs == ("IN",):  # an edge or comparison contact
        return _contact_lines(spec, series or spec, forms, values)
    if SUB_BASE <= sub < OTHER:
        operands = [f"    {label}: {value}" for label, value in zip(_labels(spec), values,
                                                                     strict=False) if value]
        return ["ORG X0", f"FUN {fun}{forms} {spec.text_name}", *operands]
    return ["ORG X0", " ".join([spec.text_name, *(v for v in values if v)])]


def _contact_lines(spec: InstructionSpec, series: InstructionSpec, forms: str,
                   values: list[str]) -> list[str]:
    """A contact's lines in its place: `ORG TU X1` alone; `LD …` as a block joined by ANDLD;
    `AND …` / `OR …` after `ORG X0`."""
    place = spec.name.rsplit(".", 1)[1] if spec is not series else "AND"
    if series.operation in _EDGES:
        lines = [" ".join([place, series.text_name, *values])]
    else:
        fun = (series.sub or 0) - SUB_BASE
        lines = [f"{place}F {fun}{forms} {series.text_name}",
                 *(f"    {label}: {value}" for label, value in zip(_labels(series), values,
                                                                    strict=False))]
    head = [] if place == "ORG" else ["ORG X0"]
    return [*head, *lines, *(["ANDLD"] if place == "LD" else [])]


FO = "fo"  # a box's FO byte parameter (core/dialects/fatek/rows.py)


def placed_params(spec: InstructionSpec, params: tuple[ParamValue, ...],
                  others: Iterable[tuple[InstructionSpec, tuple[ParamValue, ...]]]
                  ) -> tuple[ParamValue, ...]:
    """A box placed in the editor gets the first FO byte no other box of the program has (the
    reader numbers them by position; a save and a new reading number them so again)."""
    names = [param.name for param in spec.params]
    if FO not in names:
        return params
    taken = set()
    for other, values in others:
        named = dict(zip((p.name for p in other.params), values, strict=False))
        if FO in named:
            taken.add(named[FO])
    index = next((k for k in range(FO_BOXES) if fo_address(k) not in taken), FO_BOXES - 1)
    chosen = list(params)
    chosen[names.index(FO)] = fo_address(index)
    return tuple(chosen)
