"""Each Fatek instruction family from listing text through the one engine, fast and monitored:
contacts and coils, edges, timers, counters, RST, data boxes (P and D forms), CMP and its FO,
comparison contacts, ASCWR, the boxes not simulated."""

from __future__ import annotations

import pytest

from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.dialects.fatek.ascii_format import parse_format
from ladderworks.core.dialects.fatek.terminal import AsciiTerminal
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects import conftest as dialects_conftest

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


def plc(text: str, monitored: bool) -> ScanEngine:
    result = parse_bytes(text.encode("utf-8"), "fatek")
    assert not [d for d in result.diagnostics if d.is_error], [
        d.located("t") for d in result.diagnostics]
    engine = ScanEngine(compile(result.program), period_ms=10)
    engine.monitored = monitored
    return engine


def get(engine: ScanEngine, text: str) -> int:
    """A Fatek device's value (a bit, or a signed word)."""
    return dialects_conftest.get(engine, text, "fatek")


def put(engine: ScanEngine, text: str, value: int) -> None:
    """Set a Fatek device."""
    dialects_conftest.put(engine, text, value, "fatek")


def scan(engine: ScanEngine, **inputs: int) -> None:
    for name, value in inputs.items():
        put(engine, name, value)
    engine.scan()


@MODES
def test_contacts_and_coils(monitored: bool) -> None:
    engine = plc("ORG X0\nAND NOT X1\nOUT Y0\nOUT NOT Y1\nORG X2\nOUTS M0\nORG X3\nOUTR M0\n"
                 "ORG M0\nOUT L Y2\nORG SHORT\nOR OPEN\nOUT Y3\nORG OPEN\nOUT Y4", monitored)
    scan(engine, X0=1, X1=0)
    assert [get(engine, y) for y in ("Y0", "Y1", "Y3", "Y4")] == [1, 0, 1, 0]
    scan(engine, X1=1)
    assert (get(engine, "Y0"), get(engine, "Y1")) == (0, 1)
    scan(engine, X2=1)
    scan(engine, X2=0)
    assert get(engine, "M0") == 1 and get(engine, "Y2") == 1  # OUTS holds
    scan(engine, X3=1)
    assert get(engine, "M0") == 0 and get(engine, "Y2") == 0


@MODES
def test_edge_contacts(monitored: bool) -> None:
    engine = plc("ORG TU X0\nOUT Y0\nORG TD X0\nOUT Y1\nORG X1\nAND TU X0\nOUT Y2\n"
                 "ORG X2\nOR TD X0\nOUT Y3\nORG X3\nLD TU X0\nOR X4\nANDLD\nOUT Y4", monitored)
    seen = []
    for value in (0, 1, 1, 0, 0):
        scan(engine, X0=value, X1=1, X3=1)
        seen.append(tuple(get(engine, y) for y in ("Y0", "Y1", "Y2", "Y3", "Y4")))
    assert seen == [(0, 0, 0, 0, 0), (1, 0, 1, 0, 1), (0, 0, 0, 0, 0), (0, 1, 0, 1, 0),
                    (0, 0, 0, 0, 0)]


@MODES
def test_timers(monitored: bool) -> None:
    """T0 0.01 s, T50 0.1 s with PV in R0, T200 1 s; FO0 and the contact."""
    engine = plc("ORG X0\nTMR T0 100\nFO 0\nOUT Y0\nORG X0\nTMR T50 0.1S R0\nORG T50\nOUT Y1\n"
                 "ORG X0\nTMR T200 1S 2\nOUT Y2", monitored)
    put(engine, "R0", 15)
    scan(engine, X0=1)
    for _ in range(99):
        engine.scan()
    assert (get(engine, "Y0"), get(engine, "T0")) == (0, 99)
    engine.scan()
    assert get(engine, "Y0") == 1 and get(engine, "Y1") == 0
    for _ in range(50):
        engine.scan()
    assert get(engine, "Y1") == 1 and get(engine, "Y2") == 0
    for _ in range(50):
        engine.scan()
    assert get(engine, "Y2") == 1 and get(engine, "T200") == 2
    scan(engine, X0=0)
    assert [get(engine, n) for n in ("Y0", "Y1", "Y2", "T0", "T50", "T200")] == [0] * 6


@MODES
def test_counters_and_reset(monitored: bool) -> None:
    engine = plc("ORG X0\nLD X1\nCTR C0 3\nFO 0\nOUT Y0\nORG X2\nRST C0\n"
                 "ORG X0\nLD X3\nLD X1\nFUN 7 UDCTR\n  CV: C200\n  PV: 2\nFO 0\nOUT Y1", monitored)
    for _ in range(3):
        scan(engine, X0=1, X3=1)
        scan(engine, X0=0)
    contact = DEVICES.bit("C0")
    assert (get(engine, "C0"), get(engine, "Y0"), engine.memory.bit(contact),
            get(engine, "C200")) == (3, 1, 1, 3)
    assert get(engine, "Y1") == 0  # FO0 only while CV = PV
    scan(engine, X3=0, X0=1)
    assert (get(engine, "C200"), get(engine, "Y1")) == (2, 1)
    scan(engine, X0=0, X2=1)  # RST runs after the CTR network: Y0 goes off in the next scan
    assert (get(engine, "C0"), engine.memory.bit(contact), get(engine, "Y0")) == (0, 0, 1)
    engine.scan()
    assert get(engine, "Y0") == 0
    scan(engine, X2=0, X1=1)
    assert get(engine, "C200") == 0


@MODES
def test_data_boxes(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 8 MOV\n S : 300\n D : R0\n"
                 "ORG X0\nFUN 13 (*)\n Sa: R0\n Sb: R0\n D : R2\n"
                 "ORG X0\nFUN 14 (/)\n Sa: 7\n Sb: 2\n D : R4\n"
                 "ORG X0\nFUN 12 (-)\n Sa: R0\n Sb: 300\n D : R6\nFO 0\nOUT Y0\n"
                 "ORG X1\nFUN 15P (+1)\n D : R7\n"
                 "ORG X1\nFUN 8D MOV\n S : 100000\n D : R8\n"
                 "ORG X1\nFUN 11D (+)\n Sa: R8\n Sb: R8\n D : R10", monitored)
    scan(engine, X0=1)
    assert [get(engine, r) for r in ("R0", "R4", "R5", "R6", "Y0")] == [300, 3, 1, 0, 1]
    address, _ = DEVICES.word("R2")
    assert engine.memory.read(address, 4, signed=True) == 90_000
    for value in (1, 1, 0, 1):
        scan(engine, X1=value)
    assert get(engine, "R7") == 2  # the P form: on each rising edge only
    r8, _ = DEVICES.word("R8")
    r10, _ = DEVICES.word("R10")
    assert engine.memory.read(r8, 4, signed=True) == 100_000
    assert engine.memory.read(r10, 4, signed=True) == 200_000


@MODES
def test_cmp_outputs_and_comparison_contacts(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\nFO 1\nOUT Y1\nFO 2\n"
                 "OUT Y2\nORGF 170 (=)\n Sa: R0\n Sb: 5\nOUT Y3\nORG X0\nANDF 171 (>)\n"
                 " Sa: R0\n Sb: R1\nOUT Y4\nORG X1\nORF 175 (<=)\n Sa: R0\n Sb: 0\nOUT Y5\n"
                 "ORG X0\nLDF 173 (<>)\n Sa: R0\n Sb: R1\nANDLD\nOUT Y6", monitored)
    put(engine, "R0", 1)
    put(engine, "R1", 2)
    scan(engine, X0=1)
    assert [get(engine, f"Y{n}") for n in range(7)] == [0, 0, 1, 0, 0, 0, 1]  # 001:1091-1095
    put(engine, "R0", 5)
    engine.scan()
    assert [get(engine, f"Y{n}") for n in range(7)] == [0, 1, 0, 1, 1, 0, 1]
    put(engine, "R1", 5)
    engine.scan()
    assert [get(engine, f"Y{n}") for n in (0, 1, 2, 6)] == [1, 0, 0, 0]


@MODES
def test_ascwr_and_the_boxes_not_simulated(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 94 ASCWR\n MD: 0\n S : R1000\n Pt: R900\nFO 2\nOUT Y0\n"
                 "ORG X1\nFUN 140 HSPSO\n Ps: 0\n SR: R0\n WR: R100\n : C1\nFO 0\nOUT Y1\n"
                 "ORG X1\nFUN 141 MPARA\n Ps: 0\n SR: R200\nFO 1\nOUT Y2", monitored)
    terminal = AsciiTerminal()
    fmt, problems = parse_format("'R0=',\"4R0\",END")
    assert problems == []
    engine.extra["ascii_terminal"] = terminal
    engine.extra["ascii_files"] = {DEVICES.word("R1000")[0]: fmt}
    put(engine, "R0", 42)
    scan(engine, X0=1, X1=1)
    assert terminal.text() == "R0=  42"
    assert [get(engine, y) for y in ("Y0", "Y1", "Y2")] == [1, 0, 0]
