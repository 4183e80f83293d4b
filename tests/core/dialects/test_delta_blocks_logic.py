"""Delta ZRST, NOP, BMOV, FMOV, XCH, SFTR/SFTL, DECO/ENCO, ALT, SUM, WAND/WOR/WXOR, NEG,
ROR/ROL, BCD/BIN (and D / P forms), fast and monitored; stateful ones skip exactly."""

from __future__ import annotations

import pytest

from tests.core.dialects.conftest import bit_of, delta, engine, get, put
from tests.core.dialects.test_delta_words32 import same_when_skipping

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


@MODES
def test_zrst_resets_bits_words_timers_and_counters(monitored: bool) -> None:
    plc = engine("LD X0\nZRST M10 M20\nZRST D5 D7\nZRST T1 T2\nZRST C3 C3\nZRSTP Y0 Y7\n"
                 "ZRST S9 S8\nEND\n", monitored=monitored)
    for device in ("M9", "M10", "M20", "M21", "Y1", "Y10", "S9", "S8"):
        put(plc, device, 1)
    for device, number in (("D4", 4), ("D5", 5), ("D7", 7), ("D8", 8), ("T1", 1), ("T2", 2),
                           ("C3", 3)):
        put(plc, device, number)
    plc.memory.set_bit(bit_of("T1"), 1)  # T1's contact
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, d) for d in ("M9", "M10", "M20", "M21")] == [1, 0, 0, 1]
    assert [get(plc, d) for d in ("D4", "D5", "D7", "D8")] == [4, 0, 0, 8]
    assert [get(plc, d) for d in ("T1", "T2", "C3")] == [0, 0, 0]
    assert plc.memory.bit(bit_of("T1")) == 0
    assert (get(plc, "Y1"), get(plc, "Y10")) == (0, 1)
    assert (get(plc, "S9"), get(plc, "S8")) == (0, 1)  # D1 > D2: only D1 [chosen]


def test_nop_anywhere_does_nothing_and_keeps_the_rung() -> None:
    program = delta("NOP\nLD X0\nNOP\nOUT Y0\nNOP\nLD X1\nOUT Y1\nNOP\nEND\n")
    assert len(program.networks) == 3  # NOP, LD X0 ... NOP, LD X1 ... NOP; END
    plc = engine("NOP\nLD X0\nNOP\nOUT Y0\nNOP\nLD X1\nOUT Y1\nEND\n")
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 0)


@MODES
def test_bmov_fmov_xch(monitored: bool) -> None:
    plc = engine("LD X0\nBMOV D0 D1 K3\nFMOV K-2 D10 K3\nDFMOV K100000 D20 K2\nXCH D30 D31\n"
                 "DXCH D40 D42\nEND\n", monitored=monitored)
    for k, number in enumerate((1, 2, 3, 4)):
        put(plc, f"D{k}", number)
    put(plc, "D30", 30)
    put(plc, "D31", 31)
    put(plc, "D40:4", 400000)
    put(plc, "D42:4", -1)
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, f"D{k}") for k in range(5)] == [1, 1, 2, 3, 0]  # overlapping: a block
    assert [get(plc, f"D{k}") for k in range(10, 14)] == [-2, -2, -2, 0]
    assert (get(plc, "D20:4"), get(plc, "D22:4"), get(plc, "D24")) == (100000, 100000, 0)
    assert (get(plc, "D30"), get(plc, "D31")) == (31, 30)
    assert (get(plc, "D40:4"), get(plc, "D42:4")) == (-1, 400000)


@MODES
def test_sftr_sftl_shift_bits_in_from_the_source(monitored: bool) -> None:
    plc = engine("LD X0\nSFTRP X10 M0 K8 K2\nSFTLP X10 M20 K8 K2\nEND\n", monitored=monitored)
    put(plc, "X10", 1)  # X10 on, X11 off: the two bits shifted in
    for k in (0, 1, 7):
        put(plc, f"M{k}", 1)
        put(plc, f"M{20 + k}", 1)
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, f"M{k}") for k in range(8)] == [0, 0, 0, 0, 0, 1, 1, 0]
    assert [get(plc, f"M{20 + k}") for k in range(8)] == [1, 0, 1, 1, 0, 0, 0, 0]
    plc.scan()  # SFTRP: once per rising edge
    assert [get(plc, f"M{k}") for k in range(8)] == [0, 0, 0, 0, 0, 1, 1, 0]


@MODES
def test_deco_enco(monitored: bool) -> None:
    plc = engine("LD X0\nDECO D0 M10 K3\nDECO D0 D1 K4\nENCO M30 D2 K3\nENCO D3 D4 K4\n"
                 "ENCO M40 D5 K2\nEND\n", monitored=monitored)
    put(plc, "D0", 0x15)  # low 3 bits: 5; low 4 bits: 5
    put(plc, "D1", -1)
    put(plc, "M31", 1)
    put(plc, "M34", 1)
    put(plc, "D3", 0b0100_0010)
    put(plc, "D5", 9)
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, f"M{k}") for k in range(10, 18)] == [0, 0, 0, 0, 0, 1, 0, 0]
    assert get(plc, "D1") == 1 << 5
    assert (get(plc, "D2"), get(plc, "D4")) == (4, 6)  # the highest bit on
    assert get(plc, "D5") == 9 and get(plc, "M1067") == 1  # none on: error, kept


@MODES
def test_alt_flips_each_scan_altp_each_rising_edge(monitored: bool) -> None:
    plc = engine("LD X0\nALT M0\nALTP M1\nEND\n", monitored=monitored)
    put(plc, "X0", 1)
    states = []
    for _ in range(3):
        plc.scan()
        states.append((get(plc, "M0"), get(plc, "M1")))
    assert states == [(1, 1), (0, 1), (1, 1)]
    put(plc, "X0", 0)
    plc.scan()
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "M1") == 0


@MODES
def test_sum_counts_bits(monitored: bool) -> None:
    plc = engine("LD X0\nSUM D0 D1\nDSUM D2 D4\nSUM D6 D7\nEND\n", monitored=monitored)
    put(plc, "D0", -1)
    put(plc, "D2:4", 0x1010_0101)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "D1"), get(plc, "D4:4"), get(plc, "D7")) == (16, 4, 0)
    assert get(plc, "M1020") == 1  # the last SUM: zero


@MODES
def test_word_logic_negation_rotation(monitored: bool) -> None:
    plc = engine("LD X0\nWAND D0 H0FF0 D1\nWOR D0 K1 D2\nWXOR D0 H00FF D3\n"
                 "DAND D10 H0FFFF0000 D12\nDOR D10 K1 D14\nDXOR D10 D10 D16\n"
                 "NEG D4\nDNEG D18\nROR D5 K4\nROL D6 K1\nDROL D20 K8\nEND\n",
                 monitored=monitored)
    put(plc, "D0", 0x1234)
    put(plc, "D10:4", 0x1234_5678)
    put(plc, "D4", 7)
    put(plc, "D18:4", -100000)
    put(plc, "D5", 0x0001)
    put(plc, "D6", -32768)  # 0x8000
    put(plc, "D20:4", 0x8100_0001)
    put(plc, "X0", 1)
    plc.scan()
    assert [get(plc, f"D{k}") & 0xFFFF for k in (1, 2, 3)] == [0x0230, 0x1235, 0x12CB]
    assert [get(plc, f"D{k}:4") & 0xFFFF_FFFF for k in (12, 14, 16)] == [
        0x1234_0000, 0x1234_5679, 0]
    assert (get(plc, "D4"), get(plc, "D18:4")) == (-7, 100000)
    assert get(plc, "D5") & 0xFFFF == 0x1000
    assert get(plc, "D6") == 1 and get(plc, "M1022") == 1  # the last rotation: DROL
    assert get(plc, "D20:4") & 0xFFFF_FFFF == 0x0000_0181


@MODES
def test_bcd_bin_and_their_range_errors(monitored: bool) -> None:
    plc = engine("LD X0\nBCD D0 D1\nBIN D2 D3\nDBCD D4 D6\nDBIN D8 D10\nBCD D12 D13\n"
                 "BIN D14 D15\nEND\n", monitored=monitored)
    put(plc, "D0", 1234)
    put(plc, "D2", 0x9876)
    put(plc, "D4:4", 12345678)
    put(plc, "D8:4", 0x8765_4321)
    put(plc, "D12", 10000)
    put(plc, "D13", 5)
    put(plc, "D14", 0x00A0)
    put(plc, "D15", 6)
    put(plc, "X0", 1)
    plc.scan()
    assert get(plc, "D1") == 0x1234 and get(plc, "D3") == 9876
    assert get(plc, "D6:4") == 0x1234_5678 and get(plc, "D10:4") == 87654321
    assert (get(plc, "D13"), get(plc, "D15"), get(plc, "M1067")) == (5, 6, 1)


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_stateful_blocks_skip_exactly(monitored: bool) -> None:
    skipped = same_when_skipping(
        "LD X0\nALTP M0\nLD X1\nSFTLP X2 M10 K16 K1\nLD X3\nZRSTP M10 M13\nLD X4\n"
        "BMOVP D0 D10 K4\nXCHP D0 D1\nLD M0\nOUT Y0\nEND\n", 1500, monitored)
    assert skipped > 0


SEQUENCE = ("LD M1002\nSET S0\nSTL S0\nOUT Y0\nLD X0\nSET S20\nSTL S20\nOUT Y1\nTMR T0 K5\n"
            "LD T0\nSET S21\nSTL S21\nOUT Y2\nLD X1\nOUT S0\nRET\nLD X2\nOUT Y3\nEND\n")


@MODES
def test_step_ladder_moves_from_step_to_step(monitored: bool) -> None:
    plc = engine(SEQUENCE, monitored=monitored)

    def state() -> tuple[int, ...]:
        return tuple(get(plc, d) for d in ("S0", "S20", "S21", "Y0", "Y1", "Y2", "T0"))

    plc.scan()
    assert state() == (1, 0, 0, 1, 0, 0, 0)
    put(plc, "X0", 1)
    plc.scan()  # S0 moves to S20: S0 off at once, its Y0 off from the next scan
    assert state()[:3] == (0, 1, 0) and get(plc, "Y1") == 1
    put(plc, "X0", 0)
    plc.scan()
    assert state() == (0, 1, 0, 0, 1, 0, 0)
    plc.run_scans(60)  # T0 (0.5 s) moves on to S21; T0 of the step left is reset
    assert state() == (0, 0, 1, 0, 0, 1, 0)
    put(plc, "X1", 1)
    plc.run_scans(2)  # OUT S0 goes back to the first step
    assert state() == (1, 0, 0, 1, 0, 0, 0)
    put(plc, "X2", 1)
    plc.scan()
    assert get(plc, "Y3") == 1  # after RET: an ordinary rung


def test_step_ladder_saves_as_written() -> None:
    from ladderworks.core.dialects.delta.printer import network_lines

    lines = [line for network in delta(SEQUENCE).networks
             for line in network_lines(network, False)]
    assert [line.replace("\t", " ") for line in lines] == SEQUENCE.strip().split("\n")


def test_stl_needs_an_s_device() -> None:
    from ladderworks.core.il.reading import parse_bytes

    result = parse_bytes(b"STL M0\nRET\nEND\n", "delta")
    assert [(d.code, d.line) for d in result.diagnostics] == [("dialect-operand", 1)]


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_step_ladder_skips_exactly(monitored: bool) -> None:
    assert same_when_skipping(SEQUENCE, 1500, monitored) > 0


LOOPS = ("LD X0\nMOV K0 D0\nFOR K3\nFOR D10\nLD M1000\nINC D0\nNEXT\nLD M1000\nINC D1\nNEXT\n"
         "LD X0\nOUT Y0\nEND\n")


@MODES
def test_for_next_repeats_in_one_scan_and_nests(monitored: bool) -> None:
    plc = engine(LOOPS, monitored=monitored)
    put(plc, "D10", 4)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "D0"), get(plc, "D1"), get(plc, "Y0")) == (12, 3, 1)
    put(plc, "X0", 0)
    put(plc, "D10", 1)
    plc.scan()
    assert (get(plc, "D0"), get(plc, "D1")) == (15, 6)


def test_for_next_save_as_written_and_pair_up() -> None:
    from ladderworks.core.dialects.delta.printer import network_lines
    from ladderworks.core.il.reading import parse_bytes

    lines = [line for network in delta(LOOPS).networks for line in network_lines(network, False)]
    assert [line.replace("\t", " ") for line in lines] == LOOPS.strip().split("\n")
    result = parse_bytes(b"NEXT\nFOR K2\nLD X0\nOUT Y0\nEND\n", "delta")
    assert [(d.code, d.line) for d in result.diagnostics] == [
        ("dvp-next-without-for", 1), ("dvp-for-without-next", 2)]


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_loops_skip_exactly(monitored: bool) -> None:
    same_when_skipping("FOR K2\nLD X0\nINCP D20\nALTP M0\nNEXT\nLD M0\nOUT Y0\nEND\n", 800,
                       monitored)


def test_a_step_starting_with_ld_has_no_dangling_read() -> None:
    from ladderworks.core.compiler import compile_program
    from ladderworks.core.il.reading import parse_bytes

    text = "LD M1002\nSET S0\nSTL S0\nLD X0\nOUT Y0\nLD X1\nSET S1\nSTL S1\nOUT Y1\nRET\nEND\n"
    result = parse_bytes(text.encode(), "delta")
    compiled = compile_program(result.program)
    assert [d.code for d in (*result.diagnostics, *compiled.diagnostics)] == []
    plc = engine(text)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 0)
    put(plc, "X1", 1)
    plc.run_scans(2)
    assert (get(plc, "Y0"), get(plc, "Y1"), get(plc, "S0")) == (0, 1, 0)


PULSED = ("LD X0\nCJP P1\nLD M1000\nINC D0\nP1\nLD X1\nCALLP P2\nFEND\nP2\nLD M1000\nINC D1\n"
          "SRET\nEND\n")


@MODES
def test_cjp_callp_act_on_the_rising_edge_only(monitored: bool) -> None:
    plc = engine(PULSED, monitored=monitored)
    put(plc, "X0", 1)
    put(plc, "X1", 1)
    plc.run_scans(3)
    assert (get(plc, "D0"), get(plc, "D1")) == (2, 1)  # jumped over once, called once
    after = engine("LD X1\nCJP P2\nOUT Y1\nP2\nEND\n", monitored=monitored)
    put(after, "X1", 1)
    after.run_scans(2)
    assert get(after, "Y1") == 1  # the rung goes on after CJP when it does not jump
    from ladderworks.core.dialects.delta.printer import network_lines

    lines = [line for network in delta(PULSED).networks for line in network_lines(network, False)]
    assert [line.replace("\t", " ") for line in lines] == PULSED.strip().split("\n")


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_cjp_callp_skip_exactly(monitored: bool) -> None:
    same_when_skipping(PULSED, 800, monitored)


def test_stl_without_ret_and_ret_alone_say_so_in_delta_words() -> None:
    from ladderworks.core.compiler import compile_program
    from ladderworks.core.il.reading import parse_bytes

    for text, code in (("STL S0\nOUT Y0\nEND\n", "dvp-range-open"),
                       ("LD X0\nOUT Y0\nRET\nEND\n", "dvp-range-end-alone")):
        result = parse_bytes(text.encode())  # STL alone makes the text Delta's
        assert result.program.dialect == "delta"
        codes = [d.code for d in compile_program(result.program).diagnostics]
        assert code in codes, codes
