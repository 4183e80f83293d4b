"""The table FUNs as docs/dialects.md's FUN table gives them, from key-in listings, fast and
monitored: FUN 24 SUM, 25 MEAN, 103 BT_M, 104 T_SWP, 107 T_FIL; FO0 ERR for a length out of
1-256 (nothing written); P and D forms."""

from __future__ import annotations

from tests.core.dialects.fatek.test_families import MODES, get, plc, put, scan


@MODES
def test_sum_and_mean(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 24 SUM\n Ts : R0\n L : 4\n D : R10\nFO 0\nOUT Y0\n"
                 "ORG X0\nFUN 25 MEAN\n Ts : R0\n L : R9\n D : R11\nFO 0\nOUT Y1\n"
                 "ORG X0\nFUN 24D SUM\n Ts : R20\n L : 2\n D : R30\n", monitored)
    for n, value in enumerate((10, -3, 7, 100)):
        put(engine, f"R{n}", value)
    put(engine, "R9", 3)
    put(engine, "R21", 1)  # R20-R21 = 65536
    put(engine, "R22", 5)  # R22-R23 = 5
    scan(engine, X0=1)
    assert (get(engine, "R10"), get(engine, "R11")) == (114, 4)  # 14 / 3 truncated
    assert (get(engine, "Y0"), get(engine, "Y1")) == (0, 0)
    assert (get(engine, "R30"), get(engine, "R31")) == (5, 1)
    put(engine, "R9", -1)
    put(engine, "R2", -30)
    scan(engine)
    assert (get(engine, "R11"), get(engine, "Y1")) == (4, 1)  # L out of range: ERR, D kept
    put(engine, "R9", 3)
    scan(engine)
    assert (get(engine, "R11"), get(engine, "Y1")) == (-7, 0)  # -23 / 3 toward 0


@MODES
def test_block_move_swap_and_fill(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 103P BT_M\n Ts : R0\n Td : R10\n L : 3\nFO 0\nOUT Y0\n"
                 "ORG X1\nFUN 104P T_SWP\n Ta : R0\n Tb : R20\n L : 2\n"
                 "ORG X2\nFUN 107 T_FIL\n S : -1\n Td : R30\n L : 3\n"
                 "ORG X2\nFUN 107D T_FIL\n S : R40\n Td : R50\n L : 2\n", monitored)
    for n, value in enumerate((1, 2, 3)):
        put(engine, f"R{n}", value)
    put(engine, "R20", 8)
    put(engine, "R21", 9)
    put(engine, "R40", 7)
    put(engine, "R41", 1)
    scan(engine, X0=1)
    assert [get(engine, f"R{n}") for n in (10, 11, 12)] == [1, 2, 3] and get(engine, "Y0") == 0
    put(engine, "R0", 5)
    scan(engine)  # P form: once
    assert get(engine, "R10") == 1
    scan(engine, X1=1, X2=1)
    assert [get(engine, f"R{n}") for n in (0, 1, 20, 21)] == [8, 9, 5, 2]
    assert [get(engine, f"R{n}") for n in (30, 31, 32, 33)] == [-1, -1, -1, 0]
    assert [get(engine, f"R{n}") for n in (50, 51, 52, 53, 54)] == [7, 1, 7, 1, 0]


@MODES
def test_a_length_out_of_range_is_an_error_and_writes_nothing(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 107 T_FIL\n S : 5\n Td : D10\n L : R9\nFO 0\nOUT Y0\n"
                 "ORG X0\nFUN 24 SUM\n Ts : R0\n L : 257\n D : R10\nFO 0\nOUT Y1\n", monitored)
    put(engine, "R10", 42)
    scan(engine, X0=1)  # L = R9 = 0
    assert (get(engine, "Y0"), get(engine, "D10")) == (1, 0)
    assert (get(engine, "Y1"), get(engine, "R10")) == (1, 42)
    put(engine, "R9", 256)
    scan(engine)
    assert (get(engine, "Y0"), get(engine, "D10"), get(engine, "D265")) == (0, 5, 5)


@MODES
def test_pointer_moves_register_to_table_and_back(monitored: bool) -> None:
    """R->T with PIN fills a table one entry per EN 0 -> 1, PEND at the last, the pointer
    staying there; CLR sets it to 0; T->R reads it back; a pointer out of range is ERR."""
    engine = plc("ORG X0\nLD X1\nLD X2\nFUN 100P R->T\n Rs : R0\n Td : R10\n L : 3\n"
                 " Pr : R20\nFO 0\nOUT Y0\nFO 1\nOUT Y1\n"
                 "ORG X3\nLD SHORT\nLD OPEN\nFUN 101P T->R\n Ts : R10\n L : 3\n Pr : R21\n"
                 " Rd : R22\nFO 0\nOUT Y2\nFO 1\nOUT Y3\n", monitored)
    for value in (5, 6, 7, 8):
        put(engine, "R0", value)
        scan(engine, X0=1, X1=1)
        scan(engine, X0=0)
    assert [get(engine, f"R{n}") for n in (10, 11, 12)] == [5, 6, 8]  # 8 overwrote the last
    assert (get(engine, "R20"), get(engine, "Y0"), get(engine, "Y1")) == (2, 1, 0)
    scan(engine, X2=1)  # CLR
    assert (get(engine, "R20"), get(engine, "Y0")) == (0, 0)
    seen = []
    for _ in range(3):
        scan(engine, X3=1)
        scan(engine, X3=0)
        seen.append((get(engine, "R22"), get(engine, "Y2")))
    assert seen == [(5, 0), (6, 0), (8, 1)] and get(engine, "R21") == 2
    put(engine, "R21", 3)
    put(engine, "R22", 0)
    scan(engine, X3=1)
    assert (get(engine, "R22"), get(engine, "Y3")) == (0, 1)


@MODES
def test_a_table_of_one_entry_is_an_error_for_the_table_instructions(monitored: bool) -> None:
    """FBs manual p. 7-83: a table consists of 2 or more registers (SUM and MEAN take 1)."""
    engine = plc("ORG X0\nFUN 103 BT_M\n Ts : R0\n Td : R10\n L : 1\nFO 0\nOUT Y0\n"
                 "ORG X0\nFUN 24 SUM\n Ts : R0\n L : 1\n D : R20\nFO 0\nOUT Y1\n", monitored)
    put(engine, "R0", 5)
    scan(engine, X0=1)
    assert (get(engine, "Y0"), get(engine, "R10")) == (1, 0)
    assert (get(engine, "Y1"), get(engine, "R20")) == (0, 5)
