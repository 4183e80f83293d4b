"""Fatek rows made native (native/fatek_contacts.py, fatek_timers.py) equal their Python
implementations exactly: a small program of the rows runs on a Python and a native engine,
fast and monitored; before every scan hypothesis draws R0-R11, the X inputs, the scan's
period and, now and then, the timers' and counters' present values (their limits included)
and the boxes' FO bytes;
after every scan all memory, the call sites' states and the power flow are equal, and no op
calls back into Python (test_native_functions' helpers)."""

from __future__ import annotations

import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.dialects.fatek.devices import FO_AREA
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.test_native_functions import (  # noqa: F401 (the fixture is autouse)
    DATA,
    _byte,
    _engines,
    disk_cache_in_tmp,
)
from tests.hypothesis_profiles import examples

# present values poked from the data: T0, T1, T50 (2 bytes), C0, C150 (2), C200, C201 (4)
_VALUES = ("T0", "T1", "T50", "C0", "C150", "C200", "C201")
_LIMITS = (b"\xff\x7f", b"\xfe\x7f", b"\x00\x80", b"\xff\xff", b"\x00\x00")
_scan = st.tuples(st.lists(_byte, min_size=DATA, max_size=DATA), st.integers(0, 255),
                  st.integers(0, 255), st.sampled_from((1, 7, 10, 35, 100, 999, 1000, 2500)),
                  st.one_of(st.none(), st.sampled_from(_LIMITS), st.binary(min_size=2,
                                                                          max_size=2)))
_scans = st.lists(_scan, min_size=1, max_size=10)


def _binary(text: str) -> BinaryProgram:
    result = parse_bytes(text.encode("ascii"), "fatek")
    assert not [d for d in result.diagnostics if d.is_error], [
        d.located("t") for d in result.diagnostics][:3]
    compiled = compile_program(result.program)
    assert compiled.binary is not None, [d.message() for d in compiled.diagnostics][:3]
    return decode(compiled.binary)


def _run(text: str, monitored: bool, scans: list) -> None:
    python, native = _engines(_binary(text), monitored)
    r0, _ = DEVICES.word("R0")
    places = [DEVICES.word(name) for name in _VALUES]
    for data, low, high, period, poke in scans:
        for engine in (python, native):
            engine.period_ms = period
            engine.memory.areas[r0.area][r0.byte:r0.byte + DATA] = bytes(data)
            if poke is not None:  # the PLC tables set a present value (the one data[0] says)
                fo_area, fo_first = FO_AREA  # and the boxes' FO bytes (the data again)
                engine.memory.areas[fo_area][fo_first:fo_first + DATA] = bytes(data)
                at, width = places[data[0] % len(places)]
                engine.memory.areas[at.area][at.byte:at.byte + 2] = poke
                if width == 4:
                    engine.memory.areas[at.area][at.byte + 2:at.byte + 4] = poke
            engine.memory.areas[Area.X][0] = low
            engine.memory.areas[Area.X][1] = high
            engine.scan()
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        if monitored:
            assert native.power_flow == python.power_flow


_SYMBOLS = ("=", ">", "<", "<>", ">=", "<=")
PROGRAMS = {
    # FUN 170-175 starting a rung (ORG), a block (LD, then ANDLD/ORLD) and in parallel (OR)
    "compare": "".join(f"ORGF {170 + k}{form} ({s})\n Sa: R{k}\n Sb: {sb}\nOUT Y{k}\n"
                       f"ORG X{k}\nLDF {170 + k} ({s})\n Sa: R{k + 1}\n Sb: R7\nORLD\n"
                       f"ORF {170 + k}{form} ({s})\n Sa: R8\n Sb: {sb}\nOUT Y1{k}\n"
                       for k, (s, form, sb) in enumerate(zip(
                           _SYMBOLS, ("", "D", "", "D", "", ""),
                           ("R1", "R10", "-1", "0", "R9", "32767"), strict=True)))
               + "".join(f"ORGF {170 + k} ({s})\n Sa: R7\n Sb: R7\nOUT M{k}\n"
                         for k, s in enumerate(_SYMBOLS)),  # equal: every test's boundary
    # TU/TD in series, starting a rung, a block and in parallel; on X and on M (written by itself)
    "edges": "ORG TU X0\nOUT Y0\nORG TD X0\nOUT Y1\nORG X1\nAND TU X2\nOUT Y2\n"
             "ORG X3\nAND TD X2\nOUT Y3\nORG X4\nOR TU X5\nOUT Y4\nORG X6\nOR TD X5\nOUT Y5\n"
             "ORG X7\nLD TU X10\nOR X11\nANDLD\nOUT Y6\nORG X12\nLD TD X10\nORLD\nOUT Y7\n"
             "ORG TU M0\nOUT M0\nORG X13\nOUT M0\nORG TD M0\nOUT Y10\n",
    # T0/T1 0.01 s, T50 0.1 s, T200 1 s; PV constants and registers; FO0 and the contacts
    "timers": "ORG X0\nTMR T0 0.01S R0\nFO 0\nOUT Y0\nORG X1\nTMR T1 0.01S 5\nFO 0\nOUT Y1\n"
              "ORG X2\nTMR T50 0.1S R1\nORG T50\nOUT Y2\nORG X3\nTMR T200 1S 2\nFO 0\n"
              "OUT Y3\nORG X4\nTMR T1 0.01S 32767\nFO 0\nOUT Y4\nORG X5\nRST T0\nOUT Y5\n"
              "ORG X6\nTMR T2 0.01S T2\nFO 0\nOUT Y6\nORG X7\nRST T50\n",
    # CTR (16 and 32 bits, retentive or not), UDCTR on counters and a register, RST
    "counters": "ORG X0\nLD X1\nCTR C0 R0\nFO 0\nOUT Y0\nORG X2\nLD X3\nCTR C200 R2\nFO 0\n"
                "OUT Y1\nORG X4\nLD X5\nCTR C150 3\nFO 0\nOUT Y2\nORG X4\nLD X5\n"
                "CTR C240 -2\nFO 0\nOUT Y3\nORG X6\nLD X7\nLD X10\nFUN 7 UDCTR\n  CV: C201\n"
                "  PV: R4\nFO 0\nOUT Y4\nORG X11\nLD X12\nLD X13\nFUN 7 UDCTR\n  CV: R6\n"
                "  PV: R7\nFO 0\nOUT Y5\nORG X11\nLD X13\nLD X12\nFUN 7 UDCTR\n  CV: C150\n"
                "  PV: 1\nFO 0\nOUT Y6\nORG X14\nRST C0\nORG X15\nRST C200\nOUT Y7\n",
}



_TWO = ("SHFL", "SHFR", "BITWR", "T_SHF", "T_ROT", "DIV48", "R-T_S", "QUEUE", "STACK", "SORT")
_THREE = ("R->T", "T->R", "T->T", "T-T_C")


def _boxes(*boxes: str) -> str:
    """Each box under its own EN (X0-X13; X15 the second input of those with two or three
    inputs, X14 the third), its FO0-FO3 on Y (Y0-Y3 of the first box, Y10-Y13 of the
    second …)."""
    text = ""
    for k, body in enumerate(boxes):
        name = body.split()[2]
        inb = "LD X15\n" if name in _TWO else "LD X15\nLD X14\n" if name in _THREE else ""
        outputs = "".join(f"FO {n}\nOUT Y{k}{n}\n" for n in range(4)) if "FO" in body else ""
        text += f"ORG X{k}\n{inb}FUN {body.replace('FO', '').rstrip()}\n{outputs}"
    return text


def _fun(head: str, *operands: str, fo: bool = True) -> str:
    return head + "".join(f"\n {operand}" for operand in operands) + (" FO" if fo else "")


PROGRAMS.update({
    "logic": _boxes(*(_fun(f"{n}{form} {name}", f"Sa : {sa}", f"Sb : {sb}", f"D : {d}")
                      for (n, name), (form, sa, sb, d) in zip(
                          ((18, "AND"), (19, "OR"), (35, "XOR"), (36, "XNR")) * 2,
                          (("", "R0", "R1", "R20"), ("P", "R2", "255", "R21"),
                           ("D", "R4", "R6", "R22"), ("DP", "R8", "-1", "R24"),
                           ("", "R10", "R10", "R26"), ("D", "-2", "R0", "R28"),
                           ("P", "0", "R11", "R30"), ("", "-32768", "R3", "R31")),
                          strict=True))),
    "math": _boxes(_fun("26 SQRT", "S : R0", "D : R20"), _fun("26D SQRT", "S : R2", "D : R22"),
                   _fun("26P SQRT", "S : 32767", "D : R24"), _fun("27 NEG", "D : R3", fo=False),
                   _fun("27D NEG", "D : R4", fo=False), _fun("28P ABS", "D : R6", fo=False),
                   _fun("28D ABS", "D : R8", fo=False), _fun("29 EXT", "D : R10", fo=False),
                   _fun("9 MOV/", "S : R0", "D : R25", fo=False),
                   _fun("9D MOV/", "S : -7", "D : R26", fo=False),
                   _fun("46 SWAP", "D : R1", fo=False), _fun("46D SWAP", "D : R5", fo=False),
                   _fun("45 XCHG", "Da : R2", "Db : R7", fo=False),
                   _fun("45D XCHG", "Da : R8", "Db : R9", fo=False),
                   _fun("26D SQRT", "S : -1", "D : R28"),
                   _fun("26 SQRT", "S : R11", "D : R11"),
                   _fun("18P AND", "Sa : R0", "Sb : R1", "D : R32", fo=False)),  # no FO lines
    "div48": _boxes(_fun("23 DIV48", "Sa : R0", "Sb : R3", "D : R20"),
                    _fun("23P DIV48", "Sa : R6", "Sb : R9", "D : R24"),
                    _fun("23 DIV48", "Sa : R2", "Sb : R40", "D : R28"),
                    _fun("23 DIV48", "Sa : R0", "Sb : R0", "D : R1")),
    "movers": _boxes(*(_fun(f"{n}{form} {name}", f"D : R{k}", f"N : {count}")
                       for k, ((n, name), (form, count)) in enumerate(zip(
                           ((51, "SHFL"), (52, "SHFR"), (53, "ROTL"), (54, "ROTR")) * 3,
                           (("", "R11"), ("P", "1"), ("D", "R10"), ("DP", "R11"),
                            ("D", "32"), ("", "16"), ("", "R9"), ("D", "R9"),
                            ("", "0"), ("D", "33"), ("P", "R9"), ("D", "-1")), strict=True)))),
    "bits": _boxes(_fun("10P TOGG", "D : Y7"), _fun("10 TOGG", "D : M5"),
                   _fun("37 ZNCMP", "S : R0", "SU : R1", "SL : R2"),
                   _fun("37D ZNCMP", "S : R4", "SU : 5", "SL : -5"),
                   _fun("40 BITRD", "S : R0", "N : R9"), _fun("40D BITRD", "S : R2", "N : R10"),
                   _fun("41 BITWR", "D : R20", "N : R9", fo=False),
                   _fun("41D BITWR", "D : R22", "N : R10", fo=False),
                   _fun("42 BITMV", "S : R0", "Ns : R9", "D : R24", "Nd : R10", fo=False),
                   _fun("42D BITMV", "S : R2", "Ns : 31", "D : R26", "Nd : R11", fo=False),
                   _fun("43 NBMV", "S : R0", "Ns : R9", "D : R28", "Nd : 3", fo=False),
                   _fun("43DP NBMV", "S : R4", "Ns : 7", "D : R30", "Nd : R10", fo=False),
                   _fun("44 BYMV", "S : R1", "Ns : R11", "D : R32", "Nd : R9", fo=False),
                   _fun("44D BYMV", "S : -2", "Ns : 3", "D : R34", "Nd : R10", fo=False),
                   _fun("40 BITRD", "S : -1", "N : 15")),
    "nibbles": _boxes(_fun("47 UNIT", "S : R0", "N : R9", "D : R20"),
                      _fun("47P UNIT", "S : R4", "N : 4", "D : R21"),
                      _fun("48 DIST", "S : R1", "N : R10", "D : R22"),
                      _fun("48P DIST", "S : -1", "N : 3", "D : R26"),
                      _fun("20 BCD", "S : R0", "D : R30"), _fun("20D BCD", "S : R2", "D : R32"),
                      _fun("20 BCD", "S : 9999", "D : R34"), _fun("20D BCD", "S : -1",
                                                                  "D : R36"),
                      _fun("21 BIN", "S : R4", "D : R38"), _fun("21D BIN", "S : R6", "D : R40"),
                      _fun("21 BIN", "S : 4660", "D : R42"), _fun("21P BIN", "S : 43981",
                                                                  "D : R43"),
                      _fun("20DP BCD", "S : 99999999", "D : R44"),
                      _fun("21D BIN", "S : -1", "D : R46")),
    # tables: L a constant or R9/R10 (drawn), tables in the drawn R0-R11 or after them, at
    # R8060 (12 registers before the area's end: L 12 fits, 13 does not)
    "sums": _boxes(_fun("24 SUM", "Ts : R0", "L : 4", "D : R20"),
                   _fun("24D SUM", "Ts : R0", "L : 3", "D : R22"),
                   _fun("25 MEAN", "Ts : R0", "L : R9", "D : R24"),
                   _fun("25D MEAN", "Ts : R2", "L : 5", "D : R26"),
                   _fun("24 SUM", "Ts : R8060", "L : 12", "D : R28"),
                   _fun("24 SUM", "Ts : R8060", "L : 13", "D : R29"),
                   _fun("25P MEAN", "Ts : R3", "L : 1", "D : R30"),
                   _fun("25 MEAN", "Ts : R1", "L : 0", "D : R31"),
                   _fun("25 MEAN", "Ts : R0", "L : 7", "D : R3")),
    "table moves": _boxes(_fun("103 BT_M", "Ts : R0", "Td : R20", "L : 6"),
                          _fun("103D BT_M", "Ts : R0", "Td : R2", "L : R9"),
                          _fun("104 T_SWP", "Ta : R0", "Tb : R300", "L : R10"),
                          _fun("104D T_SWP", "Ta : R4", "Tb : R600", "L : 3"),
                          _fun("107 T_FIL", "S : R0", "Td : R40", "L : 5"),
                          _fun("107D T_FIL", "S : -1", "Td : R8060", "L : R9"),
                          _fun("108 T_SHF", "IW : R1", "Ts : R2", "L : 4", "OW : R60"),
                          _fun("109 T_ROT", "Ts : R5", "L : R9"),
                          _fun("108DP T_SHF", "IW : R2", "Ts : R4", "L : 3", "OW : R70"),
                          _fun("109D T_ROT", "Ts : R0", "L : 3"),
                          _fun("108 T_SHF", "IW : 7", "Ts : R0", "L : 1", "OW : R80"),
                          _fun("112 BKCMP", "Rs : R0", "Ts : R1", "L : 5", "D : R90"),
                          _fun("112D BKCMP", "Rs : R0", "Ts : R2", "L : 2", "D : R92"),
                          _fun("112 BKCMP", "Rs : R9", "Ts : R0", "L : R10", "D : R94")),
    # T_SWP of overlapping tables: Ta written before Tb, entry by entry
    "swaps": _boxes(_fun("104 T_SWP", "Ta : R0", "Tb : R2", "L : 5"),
                    _fun("104D T_SWP", "Ta : R0", "Tb : R1", "L : 3"),
                    _fun("104 T_SWP", "Ta : R3", "Tb : R3", "L : R9"),
                    _fun("104 T_SWP", "Ta : R6", "Tb : R4", "L : 4"),
                    _fun("104D T_SWP", "Ta : R8060", "Tb : R8062", "L : R10")),
    # kept and drawn, not simulated: FO 0 (the FO bytes drawn now and then)
    "not simulated": "ORG X1\nLD X2\nLD X3\n"
                     "FUN 140 HSPSO\n Ps: 0\n SR: R0\n WR: R100\n : C1\nFO 0\nOUT Y1\nFO 2\n"
                     "OUT Y2\nORG X4\nFUN 141 MPARA\n Ps: 0\n SR: R200\nFO 1\nOUT Y3\n",
    # searches (from the head, or after Pr), a queue and a stack, sorts, CRC16
    "searches": _boxes(_fun("105 R-T_S", "Rs : R0", "Ts : R1", "L : 6", "Pr : R160"),
                       _fun("105D R-T_S", "Rs : 0", "Ts : R0", "L : 5", "Pr : R161"),
                       _fun("106 T-T_C", "Ta : R0", "Tb : R6", "L : 5", "Pr : R162"),
                       _fun("106D T-T_C", "Ta : R0", "Tb : R2", "L : R10", "Pr : R9"),
                       _fun("105 R-T_S", "Rs : R9", "Ts : R0", "L : R10", "Pr : R163"),
                       _fun("110 QUEUE", "IW : R0", "QU : R170", "L : 4", "Pr : R180",
                            "OW : R181"),
                       _fun("111 STACK", "IW : R1", "ST : R190", "L : 3", "Pr : R200",
                            "OW : R201"),
                       _fun("110DP QUEUE", "IW : R2", "QU : R210", "L : 3", "Pr : R220",
                            "OW : R222"),
                       _fun("111D STACK", "IW : -9", "ST : R230", "L : R10", "Pr : R240",
                            "OW : R242"),
                       _fun("110 QUEUE", "IW : R3", "QU : R0", "L : 5", "Pr : R9", "OW : R250"),
                       # every entry matches (D/S = 0) or none (1): the first looked at found
                       _fun("106 T-T_C", "Ta : R0", "Tb : R0", "L : 5", "Pr : R164"),
                       _fun("105 R-T_S", "Rs : R1", "Ts : R1", "L : 3", "Pr : R165")),
    "sorts": _boxes(_fun("113 SORT", "S : R0", "D : R20", "L : 6"),
                    _fun("113D SORT", "S : R0", "D : R30", "L : 3"),
                    _fun("113 SORT", "S : R0", "D : R2", "L : R9"),
                    _fun("113 SORT", "S : R8060", "D : R40", "L : 12"),
                    _fun("113P SORT", "S : R4", "D : R50", "L : 128"),
                    _fun("31 CRC16", "MD : 0", "S : R0", "N : 6", "D : R60"),
                    _fun("31 CRC16", "MD : 0", "S : R0", "N : R9", "D : R62"),
                    _fun("31 CRC16", "MD : 1", "S : R0", "N : 2", "D : R64"),
                    _fun("31 CRC16", "MD : 0", "S : R8060", "N : 13", "D : R66"),
                    _fun("31D CRC16", "MD : 0", "S : R8060", "N : 12", "D : R68")),
    "pointers": _boxes(_fun("100 R->T", "Rs : R0", "Td : R100", "L : 4", "Pr : R110"),
                       _fun("101 T->R", "Ts : R0", "L : 6", "Pr : R111", "Rd : R112"),
                       _fun("102 T->T", "Ts : R0", "Td : R120", "L : 5", "Pr : R113"),
                       _fun("100D R->T", "Rs : -5", "Td : R130", "L : 3", "Pr : R114"),
                       _fun("101DP T->R", "Ts : R0", "L : 3", "Pr : R9", "Rd : R140"),
                       _fun("102D T->T", "Ts : R2", "Td : R150", "L : R10", "Pr : R115"),
                       _fun("100P R->T", "Rs : R1", "Td : R116", "L : 2", "Pr : R116")),
})


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("rows", sorted(PROGRAMS))
@settings(max_examples=examples(12), deadline=None)
@given(scans=_scans)
def test_fatek_rows_run_natively_as_in_python(rows: str, monitored: bool, scans: list) -> None:
    _run(PROGRAMS[rows], monitored, scans)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_a_timer_counts_to_its_most_and_stays_as_in_python(monitored: bool) -> None:
    """T0 runs 400 scans of 90 ms from a present value near 32767 (its most: the wake
    NEVER), stops, runs again; a counter counts 40 edges past its top."""
    scans = [([0] * DATA, 1, 0, 90, b"\x00\x7f" if k == 0 else None) for k in range(400)]
    scans += [([0] * DATA, 0, 0, 10, None), ([0] * DATA, 1, 0, 10, None)]
    _run(PROGRAMS["timers"], monitored, scans)
    counts = [([3] + [0] * (DATA - 1), 2 * (k % 2) | 1, 0, 10, b"\xfd\x7f" if k == 0 else None)
              for k in range(40)]
    _run(PROGRAMS["counters"], monitored, counts)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
@pytest.mark.parametrize("rows", sorted(PROGRAMS))
def test_fatek_rows_run_a_long_sequence_as_in_python(rows: str, monitored: bool) -> None:
    """Every box enabled for runs of scans (X15 on: the pointers move on to their tables'
    last entries; X14, CLR, off), then off, on again, cleared; small lengths and counts in
    the data (R9, R10 drawn from 0..7) and, every other scan, words of 00, 01 and FF bytes
    (equal entries: searches that find, sorts with ties) so the ordinary cases come too."""
    draw = random.Random(rows)
    scans = []
    for k in range(40):
        alphabet = range(256) if k % 2 else (0, 1, 0xFF)  # equal entries too
        data = [draw.choice(alphabet) for _ in range(DATA)]
        data[18:22] = [draw.randrange(8), 0, draw.randrange(8), 0]  # R9, R10
        low, high = (0xFF, 0xBF) if k % 10 < 7 else (0, 0) if k % 10 < 9 else (0xFF, 0x40)
        scans.append((data, low, high, 10, None))
    _run(PROGRAMS[rows], monitored, scans)


def test_native_timers_skip_scans_as_python_runs_every_one() -> None:
    """The skipper on native Fatek timers and counters ("ms" moved on as an elapsed time):
    after each step of time the memory and the states equal Python's every-scan run."""
    binary = _binary(PROGRAMS["timers"] + PROGRAMS["counters"].replace("ORG X", "ORG M"))
    python = ScanEngine(binary, period_ms=10)
    native = ScanEngine(binary, period_ms=10, backend="native")
    assert native.backend_used == "native" and native._current.callbacks == []
    python.every_scan = True
    r0, _ = DEVICES.word("R0")
    for low, ms in ((0x0F, 2500), (0x0F, 20_000), (0x07, 990), (0x0D, 3_000), (0, 500),
                    (0xFF, 30_000), (0x01, 1234)):
        for engine in (python, native):
            engine.memory.areas[r0.area][r0.byte:r0.byte + 4] = bytes((150, 0, 40, 0))
            engine.memory.areas[Area.X][0] = low
            engine.step(ms)
        assert native.memory.areas == python.memory.areas
        assert native.call_states() == python.call_states()
        assert native.scan_count == python.scan_count
    assert native.skipped > 0
