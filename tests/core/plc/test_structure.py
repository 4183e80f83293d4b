"""SET/RST, levels, subprograms (CALL/CALLU/SP/SPE) and label jumps (LBL/JMPB/JMPC)."""

from __future__ import annotations

import pytest

from ladderworks.core.address import Area
from ladderworks.core.compiler import check, compile_program
from ladderworks.core.plc.codegen import ScanLoopError
from tests.core.plc.conftest import at, bit, build, engine_of, set_bit


def errors(text: str) -> list[tuple[str, int]]:
    """The (code, line) of every check diagnostic of `build(text)`."""
    return [(d.code, d.line) for d in check(build(text))]


# -- SET / RST ---------------------------------------------------------------------------------

SET_RST = """
RD X0.0
SET Y0.0
WRT Y0.2
RD X0.1
RST Y0.0
"""


def test_set_and_rst_latch_and_keep_st0_for_the_next_coil() -> None:
    engine = engine_of(SET_RST)
    engine.scan()
    assert (bit(engine, "Y0.0"), bit(engine, "Y0.2")) == (0, 0)
    set_bit(engine, "X0.0", 1)
    engine.scan()
    assert (bit(engine, "Y0.0"), bit(engine, "Y0.2")) == (1, 1)
    set_bit(engine, "X0.0", 0)
    engine.scan()
    assert (bit(engine, "Y0.0"), bit(engine, "Y0.2")) == (1, 0)  # SET holds, WRT follows
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 0


def test_a_disabled_set_does_nothing_and_power_flow_shows_st0() -> None:
    engine = engine_of(SET_RST)
    engine.monitored = True
    engine.disable(1)
    set_bit(engine, "X0.0", 1)
    engine.scan()
    assert (bit(engine, "Y0.0"), bit(engine, "Y0.2")) == (0, 1)
    assert list(engine.power_flow) == [1, 1, 1, 0, 0]


def test_set_rst_pairs_are_not_coil_twice_but_mixing_with_wrt_warns() -> None:
    assert errors(SET_RST) == []
    found = check(build("RD X0.0\nWRT Y0.0\nRD X0.1\nSET Y0.0"))
    assert [(d.code, d.line, d.is_error) for d in found] == [("coil-mixed", 4, False)]


def test_set_rst_skipped_by_a_jump_keep_the_bit() -> None:
    engine = engine_of("RD X0.0\nJMP 0\nRD X0.1\nRST Y0.0\nJMPE")
    engine.memory.set_bit(at("Y0.0"), 1)
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 1


# -- levels ------------------------------------------------------------------------------------

LEVELS = """
RD.NOT R0.1
WRT R0.1
RD R9091.2
WRT R1.2
END1
RD.NOT R0.0
WRT R0.0
RD R9091.3
WRT R1.3
END2
"""


def test_level_1_runs_every_scan_and_level_2_once_per_pass() -> None:
    engine = engine_of(LEVELS, divisions=2)
    trace = engine.start_trace([at("R0.1"), at("R0.0")], 8)
    engine.run_scans(6)
    samples = trace.take()
    assert [s.time_ms for s in samples] == [0, 8, 16, 24, 32, 40]
    assert [s.values[0] for s in samples] == [1, 0, 1, 0, 1, 0]  # level 1: every scan
    assert [s.values[1] for s in samples] == [1, 1, 0, 0, 1, 1]  # level 2: every 2nd scan
    assert (bit(engine, "R1.2"), bit(engine, "R1.3")) == (1, 1)  # R9091.2/.3 while running
    assert bit(engine, "R9091.2") == bit(engine, "R9091.3") == 0


def test_by_default_one_scan_is_level_1_then_all_of_level_2() -> None:
    engine = engine_of(LEVELS)
    trace = engine.start_trace([at("R0.1"), at("R0.0")], 8)
    engine.run_scans(4)
    assert [s.values for s in trace.take()] == [(1, 1), (0, 0), (1, 1), (0, 0)]


def test_level_ends_out_of_order_are_errors() -> None:
    assert errors("RD X0.0\nWRT Y0.0\nEND2\nRD X0.0\nWRT Y0.1\nEND1") == [
        ("level-end-order", 6)]


# -- subprograms -------------------------------------------------------------------------------

SUBPROGRAMS = """
RD X0.0
WRT Y1.0
END1
RD X0.0
CALL P1
CALLU P2
CALLU P2
END2
SP P1
RD X0.1
WRT Y0.1
CALLU P3
SPE
SP P2
RD R9091.0
RD.STK R9091.1
ADDB 2 D0 1 D0
SPE
SP P3
RD X0.2
WRT Y0.3
SPE
END
"""


def test_nested_calls_and_a_subprogram_called_twice_in_one_scan() -> None:
    assert errors(SUBPROGRAMS) == []
    engine = engine_of(SUBPROGRAMS)
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    set_bit(engine, "X0.2", 1)
    engine.scan()
    assert (bit(engine, "Y0.1"), bit(engine, "Y0.3")) == (1, 1)
    assert engine.memory.read(at("D0"), 2) == 2  # P2 ran twice
    engine.scan()
    assert engine.memory.read(at("D0"), 2) == 4


def test_an_uncalled_subprogram_is_frozen() -> None:
    engine = engine_of(SUBPROGRAMS)
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    set_bit(engine, "X0.0", 0)  # P1 and P3 (called from P1) no longer run
    set_bit(engine, "X0.1", 0)
    set_bit(engine, "X0.2", 1)
    engine.scan()
    assert (bit(engine, "Y0.1"), bit(engine, "Y0.3")) == (1, 0)


def test_call_of_a_missing_subprogram_is_an_error_at_the_call() -> None:
    assert errors("RD X0.0\nCALL P7\nEND2\nSP P1\nRD X0.0\nWRT Y0.0\nSPE\nEND") == [
        ("call-missing", 2)]
    assert compile_program(build("RD X0.0\nCALL P7")).binary is None


def test_subprogram_structure_errors() -> None:
    assert errors("END2\nSP P1\nRD X0.0\nWRT Y0.0\nEND") == [("sp-without-spe", 2)]
    assert errors("RD X0.0\nWRT Y0.0\nSPE") == [("spe-without-sp", 3)]
    assert errors("END2\nSP P1\nRD X0.0\nWRT Y0.0\nSPE\nRD X0.0\nWRT Y0.1\nSP P2\nSPE") == [
        ("outside-subprogram", 6), ("outside-subprogram", 7)]
    assert errors("END2\nSP P1\nSPE\nSP P1\nSPE") == [("sp-twice", 4)]
    assert errors("END2\nSP P1\nSPE\nEND\nRD X0.0\nWRT Y0.0") == [
        ("after-end", 5), ("after-end", 6)]


def test_recursion_and_nesting_deeper_than_8_are_errors() -> None:
    recursive = "CALLU P1\nEND2\nSP P1\nCALLU P2\nSPE\nSP P2\nCALLU P1\nSPE"
    assert errors(recursive) == [("call-recursion", 7)]
    chain = "".join(f"SP P{k}\nCALLU P{k + 1}\nSPE\n" for k in range(1, 9)) + "SP P9\nSPE"
    assert errors("CALLU P1\nEND2\n" + chain) == [("call-depth", 1)]
    chain = "".join(f"SP P{k}\nCALLU P{k + 1}\nSPE\n" for k in range(2, 9)) + "SP P9\nSPE"
    assert errors("CALLU P2\nEND2\n" + chain) == []  # P2 .. P9: 8 deep


# -- label jumps -------------------------------------------------------------------------------

def test_jmpb_forward_skips_and_backward_loops() -> None:
    engine = engine_of("""
RD X0.0
JMPB L2
RD R9091.1
WRT Y0.1
LBL L2
RD R9091.1
NUMEB 2 0 D0
LBL L1
RD R9091.0
RD.STK R9091.1
ADDB 2 D0 1 D0
RD.NOT D0.2
JMPB L1
""")
    engine.scan()
    assert bit(engine, "Y0.1") == 1
    assert engine.memory.read(at("D0"), 2) == 4  # the loop body ran until D0.2 = 1
    engine.memory.set_bit(at("Y0.1"), 0)
    set_bit(engine, "X0.0", 1)
    engine.scan()
    assert bit(engine, "Y0.1") == 0


def test_an_endless_backward_jump_stops_the_run_with_an_error() -> None:
    engine = engine_of("RD X0.0\nWRT Y0.0\nLBL L1\nRD R9091.1\nJMPB L1")
    with pytest.raises(ScanLoopError) as info:
        engine.scan()
    assert [(d.code, d.line, d.args["label"]) for d in info.value.diagnostics] == [
        ("endless-loop", 3, 1)]


def test_jmpc_leaves_the_subprogram_for_a_label_of_the_main_program() -> None:
    engine = engine_of("""
RD R9091.1
CALL P1
RD R9091.1
WRT Y0.1
LBL L5
RD R9091.1
WRT Y0.2
END2
SP P1
RD X0.0
JMPC L5
RD R9091.1
WRT Y0.3
SPE
""")
    engine.scan()
    assert [bit(engine, f"Y0.{k}") for k in (1, 2, 3)] == [1, 1, 1]
    engine.memory.areas[Area.Y][0] = 0
    set_bit(engine, "X0.0", 1)
    engine.scan()
    assert [bit(engine, f"Y0.{k}") for k in (1, 2, 3)] == [0, 1, 0]


def test_label_errors() -> None:
    assert errors("RD X0.0\nJMPB L3") == [("label-missing", 2)]
    assert errors("RD X0.0\nJMPB L3\nEND2\nSP P1\nLBL L3\nSPE") == [("label-missing", 2)]
    assert errors("CALLU P1\nEND2\nSP P1\nRD X0.0\nJMPC L4\nSPE") == [("label-missing", 5)]
    assert errors("LBL L1\nLBL L1") == [("label-twice", 2)]
    assert errors("RD X0.0\nJMP 0\nLBL L1\nJMPE") == [("label-in-range", 3)]
    assert errors("RD X0.0\nJMPC L1\nLBL L1") == [("jmpc-in-main", 2)]


def test_an_unknown_sub_is_a_warning_and_runs_as_a_cnc_stub() -> None:
    text = "RD X0.0\nSUB.250 R0 7\nWRT Y0.0"
    assert [(d.code, d.is_error) for d in check(build(text))] == [("unknown-sub", False)]
    engine = engine_of(text)
    set_bit(engine, "X0.0", 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 1
