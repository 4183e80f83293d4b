"""Evaluating the drawn grid as a circuit (left to right only) = running its instruction list."""

from __future__ import annotations

import random

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Address, Area
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.logic import Rung, code_rung
from ladderworks.core.ladder.model import WIRE, Coil, Contact, LadderNetwork
from ladderworks.core.ladder.power import PowerFlow
from tests.core.ladder.reference import run
from tests.core.ladder.strategies import rungs
from tests.hypothesis_profiles import examples

POOL = [Address(Area.X, 0, bit) for bit in range(6)]


def _random_values(rnd: random.Random) -> dict[Address, bool]:
    return {address: rnd.random() < 0.5 for address in POOL}


def _agree(network: LadderNetwork, values: dict[Address, bool]) -> None:
    code, problems = network_to_instructions(network)
    assert problems == [] and code is not None
    flow = PowerFlow(network, lambda a: values.get(a, False))
    result = run(code, lambda a: values.get(a, False))
    boxes = [(anchor, e) for anchor, e in network.elements() if not isinstance(e, Contact | Coil)
             and e is not WIRE]
    if boxes:
        anchor, _ = boxes[0]
        assert [stack for _, stack in result.calls] == [flow.pins(anchor)]
    else:
        assert sorted(result.writes, key=str) == sorted(flow.writes(), key=str)  # chains


@settings(max_examples=examples(500), deadline=None)
@given(rungs(with_comments=False), st.randoms(use_true_random=False))
def test_laid_out_networks_evaluate_like_their_code(rung: Rung, rnd: random.Random) -> None:
    network = layout_network(code_rung(rung))
    for _ in range(6):
        values = {a: rnd.random() < 0.5 for a in _addresses(network)}
        _agree(network, values)


def _addresses(network: LadderNetwork) -> set[Address]:
    return {e.address for _, e in network.elements()
            if isinstance(e, Contact) and e.address is not None}


def _random_grid(rnd: random.Random) -> LadderNetwork:
    """A randomly drawn network: contacts, wires and links anywhere in a small grid."""
    columns = rnd.randint(2, 5)
    rows = rnd.randint(1, 4)
    network = LadderNetwork(columns, rows)
    for r in range(rows):
        for c in range(columns):
            roll = rnd.random()
            if roll < 0.5:
                network.cells[(r, c)] = Contact(rnd.choice(POOL), rnd.random() < 0.3)
            elif roll < 0.8:
                network.cells[(r, c)] = WIRE
        for k in range(1, columns + 1):
            if r + 1 < rows and rnd.random() < 0.3:
                network.links.add((r, k))
    coils = rnd.randint(1, rows)
    for r in range(coils):
        network.cells[(r, columns)] = Coil(Address(Area.Y, 0, r), rnd.random() < 0.3)
        if r and rnd.random() < 0.7:
            network.links.add((r - 1, columns))
    return network


def test_thousands_of_drawn_networks_evaluate_like_their_code() -> None:
    rnd = random.Random(20240611)
    coded = 0
    for _ in range(12000):
        network = _random_grid(rnd)
        code, _ = network_to_instructions(network)
        if code is None:
            continue
        coded += 1
        for _ in range(4):
            _agree(network, _random_values(rnd))
    assert coded >= 2000


def test_diagnostics_of_random_drawings_point_at_an_element() -> None:
    rnd = random.Random(99)
    rejected = 0
    for _ in range(3000):
        network = _random_grid(rnd)
        code, diagnostics = network_to_instructions(network, 0)
        if code is not None:
            continue
        rejected += 1
        assert diagnostics
        for diagnostic in diagnostics:
            assert diagnostic.cell is not None and diagnostic.network == 0
            assert network.element_at(*diagnostic.cell) is not None, diagnostic
    assert rejected > 1000
