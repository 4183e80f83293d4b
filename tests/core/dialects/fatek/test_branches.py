"""Seed 002's branch logic on the engine's stack: each listing runs as its [derived] function
(every input combination, fast and monitored) and is drawn as the seed draws it."""

from __future__ import annotations

import itertools

import pytest

from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek.branches import lower_branches
from ladderworks.core.dialects.fatek.devices import bit_address, device_at, parse_device
from ladderworks.core.dialects.fatek.listing import read_listing
from ladderworks.core.il.program import Network, Program
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.logic import code_rung
from ladderworks.core.ladder.model import Contact
from ladderworks.core.ladder.reading import read_rung
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.fatek.seed002 import CASES, PAIRS


def lowered(text: str) -> list[Network]:
    listing, problems = read_listing(text.splitlines())
    assert problems == []
    parts, problems = lower_branches(listing.records)
    assert problems == []
    return [Network(list(part.instructions)) for part in parts]


def engine(text: str, monitored: bool) -> ScanEngine:
    return ScanEngine(compile(Program(networks=lowered(text))), monitored=monitored)


def inputs_of(text: str) -> list[str]:
    """The devices the listing reads as contacts (not its TR points, OPEN or SHORT)."""
    listing, _ = read_listing(text.splitlines())
    return sorted({r.operand for r in listing.records
                   if r.mnemonic in ("ORG", "LD", "AND", "OR") and r.modifier != "TR"
                   and r.operand not in ("OPEN", "SHORT")})


def outputs(plc: ScanEngine, values: dict[str, int], names: list[str]) -> dict[str, int]:
    for name, value in values.items():
        plc.memory.set_bit(bit_address(parse_device(name, bit=True)), value)
    plc.scan()
    return {name: plc.memory.bit(bit_address(parse_device(name, bit=True))) for name in names}


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize(("where", "text", "functions"), CASES, ids=[c[0] for c in CASES])
def test_seed_listing_runs_as_its_function(where: str, text: str, functions: dict,
                                           monitored: bool) -> None:
    plc = engine(text, monitored)
    names = inputs_of(text)
    for bits in itertools.product((0, 1), repeat=len(names)):
        values = dict(zip(names, bits, strict=True))
        got = outputs(plc, values, sorted(functions))
        want = {name: function(values) for name, function in functions.items()}
        assert got == want, (where, values)


@pytest.mark.parametrize(("where", "before", "after"), PAIRS, ids=[p[0] for p in PAIRS])
def test_simplification_pairs_are_equal(where: str, before: str, after: str) -> None:
    names = inputs_of(before + "\n" + after)
    first, second = engine(before, False), engine(after, False)
    outs = ["Y0", "Y1"]
    for bits in itertools.product((0, 1), repeat=len(names)):
        values = dict(zip(names, bits, strict=True))
        assert outputs(first, values, outs) == outputs(second, values, outs), (where, values)


def _drawn(network: Network) -> dict[tuple[int, int], str]:
    grid = layout_network(network.instructions)
    assert grid.listing is None
    cells: dict[tuple[int, int], str] = {}
    for cell, element in grid.elements():
        if isinstance(element, Contact) and element.address is not None:
            device = device_at(element.address)
            cells[cell] = str(device) if device is not None else str(element.address)
    return cells


@pytest.mark.parametrize(("where", "text", "cells"), [
    # (X0·X1 + (X2+X3)·X4)·X5: the series row, the block under it, X5 after the join
    ("002:158-168", CASES[0][1], {(0, 0): "X0", (0, 1): "X1", (1, 0): "X2", (2, 0): "X3",
                                  (1, 1): "X4", (0, 2): "X5"}),
    # (X1+X2)·(X3·X4 + X5·X6)·X7
    ("002:272-286", CASES[7][1], {(0, 0): "X1", (1, 0): "X2", (0, 1): "X3", (0, 2): "X4",
                                  (1, 1): "X5", (1, 2): "X6", (0, 3): "X7"}),
    # X0·(X1+X2)·(X3·X4 + X5·X6 + X7)
    ("002:301-317", CASES[9][1], {(0, 0): "X0", (0, 1): "X1", (1, 1): "X2", (0, 2): "X3",
                                  (0, 3): "X4", (1, 2): "X5", (1, 3): "X6", (2, 2): "X7"}),
])
def test_decompositions_are_drawn_as_the_seed_draws_them(where: str, text: str,
                                                         cells: dict) -> None:
    (network,) = lowered(text)
    assert _drawn(network) == cells


@pytest.mark.parametrize(("where", "text", "functions"), CASES[:11], ids=[c[0] for c in CASES[:11]])
def test_seed_coding_is_the_standard_coding_of_its_picture(where: str, text: str,
                                                           functions: dict) -> None:
    """Seed 002's coding rules (ORG, LD at a branch line, ORLD/ANDLD, AND after a block) are
    the layout's own: the picture codes back to the same instructions (no kept source)."""
    for network in lowered(text):
        assert code_rung(read_rung(network.instructions)) == network.instructions
        assert layout_network(network.instructions).source is None


def test_branched_circuit_is_drawn_as_temporary_relay_networks() -> None:
    """002:367-382: the point after X0 is TR0; each later row starts a network `RD TR0`."""
    networks = lowered(CASES[11][1])
    assert [len(n.instructions) for n in networks] == [5, 3, 2]
    for network in networks:
        assert layout_network(network.instructions).listing is None
    assert str(device_at(networks[1].instructions[0].operand)) == "TR0"  # type: ignore[arg-type]


@pytest.mark.parametrize(("text", "code", "line"), [
    ("ORG X0\nOUT Y0\nOUT Y1\nOUT\tY\t2\nORG X1\nLD X2\nAND X3\nOUT Y3", "fatek-open-block", 8),
    ("LD X0\nAND M0\nLD X1\nAND M1\nORLD\nLD X2\nAND M2\nORLD\nLD X3\nAND M3\nOUT Y0",
     "fatek-open-block", 11),  # 002:255-270 as printed: X3·M3 is never joined
    ("ORG X0\nOUT Y0\nOUT Y1\nANDLD", "fatek-stack-empty", 4),
    ("ORG X0\nOUT TR 0\nOUT TR 0\nOUT Y0", "fatek-tr-reused", 3),
    ("ORG X0\nLD TR 3\nOUT Y0", "fatek-tr-unset", 2),
    ("ORG X0\nOUT X1", "fatek-device-kind", 2),
    ("ORG X0\nOUT L M1", "fatek-device-kind", 2),
    ("ORG X0\nAND X999", "fatek-device-range", 2),
    ("ORG X0\nAND Q1", "fatek-device-kind", 2),
])
def test_bad_branch_logic_is_diagnosed_at_its_line(text: str, code: str, line: int) -> None:
    listing, problems = read_listing(text.splitlines())
    _parts, problems2 = lower_branches(listing.records)
    found = problems + problems2
    assert [(d.code, d.line) for d in found][:1] == [(code, line)]


def test_an_output_on_the_left_rail_is_refused() -> None:
    """002:319: OUT never on the left rail (ORG SHORT before it)."""
    listing, _ = read_listing(["OUT Y0"])
    _parts, problems = lower_branches(listing.records)
    assert [(d.code, d.line) for d in problems] == [("fatek-output-on-rail", 1)]
