"""One set of checks: `check` reports an error exactly when `compile` refuses, and a program
that compiles always generates scan code that runs (issue #17 item 4)."""

from __future__ import annotations

from contextlib import suppress

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.compiler import check, compile_program
from ladderworks.core.diagnostics import has_errors
from ladderworks.core.plc.codegen import ScanLoopError
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.conftest import build

BITS = [f"R{b}.{k}" for b in range(2) for k in range(8)] + ["X0.0", "X0.1"]

_logic = st.sampled_from(["RD", "RD.NOT"]).flatmap(
    lambda rd: st.sampled_from(BITS).map(lambda a: [f"{rd} {a}"]))
_more = st.lists(st.sampled_from(["AND", "OR.NOT", "RD.STK", "AND.STK", "OR.STK"]).flatmap(
    lambda n: st.just(n) if n.endswith("STK") and not n.startswith("RD")
    else st.sampled_from(BITS).map(lambda a: f"{n} {a}")), max_size=3)
_series = st.lists(st.sampled_from(["AND", "OR.NOT", "AND.NOT"]).flatmap(
    lambda n: st.sampled_from(BITS).map(lambda a: f"{n} {a}")), max_size=3)
_coil = st.sampled_from(["WRT", "WRT.NOT", "SET", "RST"]).flatmap(
    lambda n: st.sampled_from(BITS[:16]).map(lambda a: f"{n} {a}"))
_program_number = st.integers(1, 4).map(lambda p: f"P{p}")
_label = st.integers(1, 3).map(lambda n: f"L{n}")


@st.composite
def _network(draw: st.DrawFn) -> list[str]:
    kind = draw(st.sampled_from(["logic", "logic", "logic", "jmp", "jmpe", "com", "come",
                                 "call", "callu", "sp", "spe", "lbl", "jmpb", "jmpc", "end1",
                                 "end2", "end", "x"]))
    head = draw(_logic)
    if kind == "logic":
        return head + draw(_more) + [draw(_coil)] + ([draw(_coil)] if draw(st.booleans()) else [])
    if kind in ("jmp", "com"):
        return [*head, f"{kind.upper()} {draw(st.sampled_from([0, 0, 1, 2]))}"]
    if kind in ("jmpe", "come", "spe", "end1", "end2", "end"):
        return [kind.upper()]
    if kind == "call":
        return [*head, f"CALL {draw(_program_number)}"]
    if kind == "callu":
        return [f"CALLU {draw(_program_number)}"]
    if kind == "sp":
        return [f"SP {draw(_program_number)}"]
    if kind == "lbl":
        return [f"LBL {draw(_label)}"]
    if kind in ("jmpb", "jmpc"):
        return [*head, f"{kind.upper()} {draw(_label)}"]
    return [*head, "SUB.250 R0 3", draw(_coil)]


@st.composite
def _body(draw: st.DrawFn, program: int, programs: int) -> list[str]:
    """Networks of one unit: logic, balanced JMP/COM ranges, labels and calls onward."""
    lines: list[str] = []
    for _ in range(draw(st.integers(0, 4))):
        roll = draw(st.integers(0, 9))
        head = draw(_logic)
        if roll < 4:
            lines += head + draw(_series) + [draw(_coil)]
        elif roll < 6:
            kind = draw(st.sampled_from(["JMP", "COM"]))
            inner = [*head, draw(_coil)]
            lines += [*draw(_logic), f"{kind} 0", *inner, f"{kind}E"]
        elif roll < 7 and program < programs:
            callee = draw(st.integers(program + 1, programs))
            lines += ([*head, f"CALL P{callee}"]) if draw(st.booleans()) else [f"CALLU P{callee}"]
        elif roll < 8:
            label = draw(st.integers(1, 3))
            if f"LBL L{label}" not in lines:
                lines += [f"LBL L{label}", *draw(_logic), draw(_coil)]
                target = draw(st.sampled_from([label, label, 1, 2, 3]))
                lines += [*draw(_logic), f"JMPB L{target}"]
        else:
            lines += [*head, "SUB.250 R0 3", draw(_coil)]
    return lines


@st.composite
def _structured(draw: st.DrawFn) -> list[list[str]]:
    """A program with levels and subprograms, then maybe one line dropped or one added."""
    programs = draw(st.integers(0, 3))
    lines = [*draw(_body(0, programs)), "END1", *draw(_body(0, programs)), "END2"]
    for number in range(1, programs + 1):
        lines += [f"SP P{number}", *draw(_body(number, programs)), "SPE"]
    lines.append("END")
    mutation = draw(st.sampled_from(["none", "none", "drop", "add"]))
    if mutation == "drop":
        del lines[draw(st.integers(0, len(lines) - 1))]
    elif mutation == "add":
        at = draw(st.integers(0, len(lines)))
        lines[at:at] = draw(_network())
    return [lines]


@settings(max_examples=300, deadline=None)
@given(st.one_of(st.lists(_network(), min_size=1, max_size=14), _structured()))
def test_check_errors_exactly_when_compile_refuses(networks: list[list[str]]) -> None:
    text = "\n".join(line for network in networks for line in network)
    program = build(text)
    result = compile_program(program)
    assert (result.binary is None) == has_errors(check(program)), text
    if result.binary is None:
        return
    engine = ScanEngine(result.binary)  # generates: never raises for a checked program
    engine.monitored = True
    with suppress(ScanLoopError):  # a backward JMPB on an always-true condition: the
        engine.run_scans(2)  # documented run-time stop
