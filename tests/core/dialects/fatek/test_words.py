"""The word FUNs as docs/dialects.md's FUN table gives them, from key-in listings, fast and
monitored: FUN 18 AND, 19 OR, 35 XOR, 36 XNR (FO0 D=0), 26 SQRT (FO0 ERR), 27 NEG, 28 ABS,
29 EXT, 51 SHFL / 52 SHFR (INB, FO0 OTB), 53 ROTL / 54 ROTR; P and D forms; the P forms
skipping scans equal to every scan."""

from __future__ import annotations

import random

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from tests.core.dialects.fatek.test_families import MODES, get, plc, put, scan
from tests.core.dialects.fatek.test_programs import fatek
from tests.core.plc.test_skipping import Driver, bytes_of, pair


@MODES
def test_logic_and_its_zero_output(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 18 AND\n Sa : R0\n Sb : R1\n D : R10\nFO 0\nOUT Y0\n"
                 "ORG X0\nFUN 19 OR\n Sa : R0\n Sb : R1\n D : R11\nFO 0\nOUT Y1\n"
                 "ORG X0\nFUN 35 XOR\n Sa : R0\n Sb : R1\n D : R12\nFO 0\nOUT Y2\n"
                 "ORG X0\nFUN 36 XNR\n Sa : R0\n Sb : 255\n D : R13\nFO 0\nOUT Y3\n", monitored)
    put(engine, "R0", 0x0F0F)
    put(engine, "R1", 0x00F0)
    scan(engine, X0=1)
    assert [get(engine, f"R{n}") & 0xFFFF for n in (10, 11, 12, 13)] == [
        0x0000, 0x0FFF, 0x0FFF, 0xF00F]
    assert [get(engine, f"Y{n}") for n in range(4)] == [1, 0, 0, 0]
    put(engine, "R1", 0x0F00)
    scan(engine, X0=0)  # EN 0: nothing runs, D and FO kept
    assert get(engine, "R10") == 0 and get(engine, "Y0") == 1
    scan(engine, X0=1)
    assert get(engine, "R10") == 0x0F00 and get(engine, "Y0") == 0


@MODES
def test_the_pulse_and_32_bit_forms(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 19DP OR\n Sa : R0\n Sb : R2\n D : R10\n", monitored)
    put(engine, "R1", 0x0001)  # R0-R1 = 0x0001_0000
    put(engine, "R2", 0x0002)
    scan(engine, X0=1)
    assert (get(engine, "R10"), get(engine, "R11")) == (2, 1)
    put(engine, "R2", 0x0004)
    scan(engine)  # EN still 1: the P form does not run again
    assert get(engine, "R10") == 2
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert get(engine, "R10") == 4


@MODES
def test_sqrt_neg_abs_ext(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 26 SQRT\n S : R0\n D : R10\nFO 0\nOUT Y0\n"
                 "ORG X1\nFUN 27P NEG\n D : R11\n"
                 "ORG X1\nFUN 28P ABS\n D : R12\n"
                 "ORG X1\nFUN 29 EXT\n D : R20\n"
                 "ORG X1\nFUN 26D SQRT\n S : R30\n D : R32\n", monitored)
    put(engine, "R0", 99)
    put(engine, "R11", 5)
    put(engine, "R12", -7)
    put(engine, "R20", -2)
    put(engine, "R21", 0x1234)  # ignored: D + 1 takes the sign
    put(engine, "R31", 16)  # R30-R31 = 16 * 65536 = 1048576 = 1024 ** 2
    scan(engine, X0=1, X1=1)
    assert (get(engine, "R10"), get(engine, "Y0")) == (9, 0)
    assert (get(engine, "R11"), get(engine, "R12")) == (-5, 7)
    assert (get(engine, "R20"), get(engine, "R21")) == (-2, -1)  # sign extended
    assert (get(engine, "R32"), get(engine, "R33")) == (1024, 0)
    scan(engine)  # the P forms ran once
    assert (get(engine, "R11"), get(engine, "R12")) == (-5, 7)
    put(engine, "R0", -4)
    scan(engine)
    assert (get(engine, "R10"), get(engine, "Y0")) == (9, 1)  # ERR, D kept
    put(engine, "R11", -32768)
    scan(engine, X1=0)
    scan(engine, X1=1)
    assert get(engine, "R11") == -32768  # no opposite in 16 bits: wrapped


@MODES
def test_shifts_take_inb_and_give_the_bit_out(monitored: bool) -> None:
    engine = plc("ORG X0\nLD X1\nFUN 51P SHFL\n D : R0\n N : 4\nFO 0\nOUT Y0\n"
                 "ORG X0\nLD X1\nFUN 52P SHFR\n D : R1\n N : 1\nFO 0\nOUT Y1\n", monitored)
    put(engine, "R0", 0x1801)
    put(engine, "R1", 0x0003)
    scan(engine, X0=1, X1=1)
    assert get(engine, "R0") & 0xFFFF == 0x801F and get(engine, "Y0") == 1  # bit 12 out last
    assert get(engine, "R1") & 0xFFFF == 0x8001 and get(engine, "Y1") == 1
    scan(engine, X0=0, X1=0)
    scan(engine, X0=1)
    assert get(engine, "R0") & 0xFFFF == 0x01F0 and get(engine, "Y0") == 0
    assert get(engine, "R1") & 0xFFFF == 0x4000 and get(engine, "Y1") == 1


@MODES
def test_rotations(monitored: bool) -> None:
    engine = plc("ORG X0\nFUN 53P ROTL\n D : R0\n N : 4\nFO 0\nOUT Y0\n"
                 "ORG X0\nFUN 54DP ROTR\n D : R2\n N : R9\nFO 0\nOUT Y1\n", monitored)
    put(engine, "R0", 0x1234)
    put(engine, "R2", 0x0001)  # R2-R3 = 1
    put(engine, "R9", 1)
    scan(engine, X0=1)
    assert get(engine, "R0") & 0xFFFF == 0x2341 and get(engine, "Y0") == 1
    assert (get(engine, "R2"), get(engine, "R3") & 0xFFFF) == (0, 0x8000)
    assert get(engine, "Y1") == 1
    put(engine, "R9", 40)  # N above 32: nothing moved
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert get(engine, "R0") & 0xFFFF == 0x3412
    assert (get(engine, "R2"), get(engine, "R3") & 0xFFFF) == (0, 0x8000)


@MODES
def test_shfl_and_rotr_as_the_manuals_examples_and_n_out_of_range(monitored: bool) -> None:
    """FBs manual p. 7-26: R0 0x32F0 shifted left 4 with INB 1 is 0x2F0F, OTB 1; p. 7-29:
    0xF0AA rotated right 8 is 0xAAF0, OTB 1. N outside 1-16 sets ERR (FO1), nothing moved."""
    engine = plc("ORG X0\nLD X1\nFUN 51P SHFL\n D : R0\n N : R9\nFO 0\nOUT Y0\nFO 1\nOUT Y1\n"
                 "ORG X0\nFUN 54P ROTR\n D : R2\n N : 8\nFO 0\nOUT Y2\nFO 1\nOUT Y3\n",
                 monitored)
    put(engine, "R0", 0x32F0)
    put(engine, "R2", 0xF0AA - 0x10000)
    put(engine, "R9", 4)
    scan(engine, X0=1, X1=1)
    assert get(engine, "R0") & 0xFFFF == 0x2F0F and (get(engine, "Y0"), get(engine, "Y1")) == (1, 0)
    assert get(engine, "R2") & 0xFFFF == 0xAAF0 and (get(engine, "Y2"), get(engine, "Y3")) == (1, 0)
    for n in (0, 17):
        put(engine, "R9", n)
        scan(engine, X0=0)
        scan(engine, X0=1)
        assert get(engine, "R0") & 0xFFFF == 0x2F0F
        assert (get(engine, "Y0"), get(engine, "Y1")) == (0, 1)


@MODES
def test_ext_as_the_manuals_example(monitored: bool) -> None:
    """FBs manual p. 7-8: EXT's one operand D; R0 = CFC7H (-12345) becomes R1R0 = FFFFCFC7H
    whatever R1 held, and 33FFH becomes 000033FFH."""
    engine = plc("ORG X0\nFUN 29P EXT\n D : R0\n", monitored)
    put(engine, "R0", 0xCFC7 - 0x10000)
    put(engine, "R1", 0x0ABC)
    scan(engine, X0=1)
    assert (get(engine, "R0"), get(engine, "R1")) == (-12345, -1)
    put(engine, "R0", 0x33FF)
    scan(engine)  # the P form: not again while EN stays 1
    assert get(engine, "R1") == -1
    scan(engine, X0=0)
    scan(engine, X0=1)
    assert (get(engine, "R0"), get(engine, "R1")) == (0x33FF, 0)


@MODES
def test_pulse_forms_skip_scans_exactly(monitored: bool) -> None:
    """The P forms hold EN's last state: a skipping engine equals the every-scan one (random
    X0-X15, R0-R3 from outside)."""
    text = ("ORG X0\nFUN 18P AND\n Sa : R0\n Sb : R1\n D : R10\nFO 0\nOUT Y0\n"
            "ORG X1\nLD X2\nFUN 51P SHFL\n D : R11\n N : 1\nFO 0\nOUT Y1\n"
            "ORG X3\nFUN 53DP ROTL\n D : R12\n N : R2\nFO 0\nOUT Y2\n"
            "ORG X4\nFUN 27P NEG\n D : R14\n"
            "ORG X5\nFUN 24P SUM\n Ts : R0\n L : 4\n D : R15\nFO 0\nOUT Y3\n"
            "ORG X6\nFUN 104P T_SWP\n Ta : R16\n Tb : R18\n L : 2\n"
            "ORG X7\nFUN 36P XNR\n Sa : R3\n Sb : R16\n D : R17\n"
            "ORG X8\nLD X9\nLD X10\nFUN 100P R->T\n Rs : R0\n Td : R30\n L : 4\n Pr : R40\n"
            "ORG X11\nLD X12\nLD X13\nFUN 101 T->R\n Ts : R30\n L : 4\n Pr : R41\n Rd : R42\n")
    compiled = compile_program(fatek(text))
    assert compiled.binary is not None
    engines = pair(decode(compiled.binary), monitored=monitored)
    driver = Driver(engines, random.Random(text), bytes_of(Area.X, 2), bytes_of(Area.D, 8), [])
    assert driver.run(1500, rate=0.05) > 0
