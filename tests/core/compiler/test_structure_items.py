"""The structure analysis reads only the items with a flow: every item still gets its unit, and
the plain items outside every unit their problems, in item order."""

from __future__ import annotations

from ladderworks.core.compiler.structure import analyse, analyse_flows
from ladderworks.core.il.program import ProgramRef
from ladderworks.core.instructions import Flow, spec_for


def items(text: str) -> list[tuple[object, tuple[object, ...]]]:
    """(row, parameters) per line `NAME [Pn]`."""
    found: list[tuple[object, tuple[object, ...]]] = []
    for line in text.split():
        name, _, number = line.partition(":")
        found.append((spec_for(name), (ProgramRef(int(number)),) if number else ()))
    return found


def test_plain_items_get_their_unit_or_their_problem() -> None:
    program = items("RD WRT END1 RD WRT END2 SP:1 RD WRT SPE RD END RD WRT")
    structure = analyse(program)  # type: ignore[arg-type]
    assert [unit.name if unit else None for unit in structure.unit_of] == [
        "L1", "L1", "L1", "L2", "L2", "L2", "P1", "P1", "P1", "P1", None, None, None, None]
    assert [(p.code, p.index) for p in structure.problems] == [
        ("outside-subprogram", 10), ("after-end", 12), ("after-end", 13)]
    flows = [(k, spec, params) for k, (spec, params) in enumerate(program)
             if spec.flow is not Flow.NONE]  # type: ignore[attr-defined]
    again = analyse_flows(len(program), flows)  # type: ignore[arg-type]
    assert again.unit_of == structure.unit_of
    assert again.problems == structure.problems
    assert [(u.name, u.start, u.end) for u in again.units()] == [
        (u.name, u.start, u.end) for u in structure.units()] == [
        ("L1", 0, 3), ("L2", 3, 6), ("L3", 6, 6), ("P1", 6, 10)]  # L3: empty


def test_a_program_of_plain_items_only_is_level_two() -> None:
    structure = analyse(items("RD WRT RD WRT"))  # type: ignore[arg-type]
    assert [unit.name if unit else None for unit in structure.unit_of] == ["L2"] * 4
    assert structure.problems == []
