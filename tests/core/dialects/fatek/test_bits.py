"""The bit and word-move FUNs as docs/dialects.md's FUN table gives them, from key-in listings,
fast and monitored: FUN 9 MOV/, 10 TOGG, 37 ZNCMP (FO0 INZ, FO1 >U, FO2 <L, FO3 ERR), 40 BITRD
(FO0 OTB), 41 BITWR (INB), 42 BITMV, 43 NBMV, 44 BYMV, 45 XCHG, 46 SWAP; P and D forms."""

from __future__ import annotations

from tests.core.dialects.fatek.test_families import MODES, get, plc, put, scan


@MODES
def test_inverted_move_exchange_and_swap(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 9 MOV/\n S : R0\n D : R1\n"
                 "ORG X0\nFUN 9D MOV/\n S : 0\n D : R20\n"
                 "ORG X1\nFUN 45P XCHG\n Da : R2\n Db : R3\n"
                 "ORG X1\nFUN 46P SWAP\n D : R4\n"
                 "ORG X1\nFUN 46DP SWAP\n D : R6\n", monitored)
    put(engine, "R0", 0x00FF)
    put(engine, "R2", 1)
    put(engine, "R3", 2)
    put(engine, "R4", 0x1234)
    put(engine, "R6", 0x1111)
    put(engine, "R7", 0x2222)
    scan(engine, X0=1, X1=1)
    assert get(engine, "R1") & 0xFFFF == 0xFF00
    assert (get(engine, "R20"), get(engine, "R21")) == (-1, -1)
    assert (get(engine, "R2"), get(engine, "R3")) == (2, 1)
    assert get(engine, "R4") == 0x3412
    assert (get(engine, "R6"), get(engine, "R7")) == (0x2222, 0x1111)
    scan(engine)  # the P forms ran once
    assert (get(engine, "R2"), get(engine, "R3"), get(engine, "R4")) == (2, 1, 0x3412)


@MODES
def test_zone_compare(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 37 ZNCMP\n S : R0\n SU : R1\n SL : R2\nFO 0\nOUT Y0\nFO 1\n"
                 "OUT Y1\nFO 2\nOUT Y2\nFO 3\nOUT Y3\n", monitored)
    put(engine, "R1", 10)
    put(engine, "R2", -5)
    seen = []
    for value in (-6, -5, 10, 11):
        put(engine, "R0", value)
        scan(engine, X0=1)
        seen.append(tuple(get(engine, f"Y{n}") for n in range(4)))
    assert seen == [(0, 0, 1, 0), (1, 0, 0, 0), (1, 0, 0, 0), (0, 1, 0, 0)]
    put(engine, "R2", 20)  # SU < SL
    scan(engine)
    assert tuple(get(engine, f"Y{n}") for n in range(4)) == (0, 0, 0, 1)


@MODES
def test_bit_read_write_move(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 40 BITRD\n S : R0\n N : R9\nFO 0\nOUT Y0\n"
                 "ORG X0\nLD X1\nFUN 41 BITWR\n D : R1\n N : 3\n"
                 "ORG X0\nFUN 42 BITMV\n S : R0\n Ns : R9\n D : R2\n Nd : 15\n"
                 "ORG X0\nLD X1\nFUN 41D BITWR\n D : R4\n N : 20\n", monitored)
    put(engine, "R0", 0x0020)
    put(engine, "R9", 5)
    put(engine, "R1", 0x0001)
    scan(engine, X0=1, X1=1)
    assert get(engine, "Y0") == 1
    assert get(engine, "R1") == 0x0009
    assert get(engine, "R2") & 0xFFFF == 0x8000
    assert (get(engine, "R4"), get(engine, "R5")) == (0, 0x0010)
    scan(engine, X1=0)
    assert get(engine, "R1") == 0x0001 and get(engine, "R5") == 0
    put(engine, "R9", 16)  # N past 15: BITRD keeps OTB, BITMV writes nothing
    put(engine, "R0", 0)
    scan(engine)
    assert get(engine, "Y0") == 1 and get(engine, "R2") & 0xFFFF == 0x8000


@MODES
def test_toggle(monitored: bool) -> None:
    """TOGG inverts its bit each time it runs (P: each EN 0 -> 1); FO0 OTP follows the bit."""
    engine = plc("ORG X0\nFUN 10P TOGG\n D : Y0\nFO 0\nOUT Y1\n"
                 "ORG X1\nFUN 10 TOGG\n D : M5\n", monitored)
    seen = []
    for value in (1, 1, 0, 1):
        scan(engine, X0=value, X1=1)
        seen.append((get(engine, "Y0"), get(engine, "Y1"), get(engine, "M5")))
    assert seen == [(1, 1, 1), (1, 1, 0), (1, 1, 1), (0, 0, 0)]  # M5 every scan


@MODES
def test_nibble_and_byte_moves(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 43 NBMV\n S : R0\n Ns : 3\n D : R1\n Nd : 0\n"
                 "ORG X0\nFUN 44 BYMV\n S : R0\n Ns : 0\n D : R2\n Nd : R9\n"
                 "ORG X0\nFUN 44D BYMV\n S : R0\n Ns : 1\n D : R4\n Nd : 3\n", monitored)
    put(engine, "R0", 0x7A5C)
    put(engine, "R1", 0x1234)
    put(engine, "R2", 0x1234)
    put(engine, "R9", 1)
    scan(engine, X0=1)
    assert get(engine, "R1") == 0x1237
    assert get(engine, "R2") == 0x5C34
    assert (get(engine, "R4"), get(engine, "R5")) == (0, 0x7A00)
    put(engine, "R9", 2)  # byte 2 of a 16-bit D: nothing moved
    put(engine, "R0", 0)
    scan(engine)
    assert get(engine, "R2") == 0x5C34


@MODES
def test_dist_as_the_manuals_example_and_unit_back(monitored: bool) -> None:
    """FBs manual p. 7-23: WX0 = 0x0421, N 3 into R0-R2 = 1, 2, 4; UNIT puts them together
    again; N outside 1-4 is ERR, nothing written."""
    engine = plc("ORG X0\nFUN 48P DIST\n S : R10\n N : 3\n D : R0\nFO 0\nOUT Y0\n"
                 "ORG X1\nFUN 47P UNIT\n S : R0\n N : R11\n D : R12\nFO 0\nOUT Y1\n",
                 monitored)
    put(engine, "R10", 0x7421)
    put(engine, "R2", 0x7F0)
    put(engine, "R11", 3)
    scan(engine, X0=1)
    assert [get(engine, f"R{k}") for k in range(4)] == [1, 2, 4, 0] and get(engine, "Y0") == 0
    scan(engine, X1=1)
    assert (get(engine, "R12"), get(engine, "Y1")) == (0x421, 0)
    put(engine, "R11", 5)
    scan(engine, X1=0)
    scan(engine, X1=1)
    assert (get(engine, "R12"), get(engine, "Y1")) == (0x421, 1)
