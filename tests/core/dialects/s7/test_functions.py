"""The S7 box implementations called as the generated scan calls them: IEC timers (ET when the
box runs, PT latched, TP no retrigger, TONR's R, -(PT)- / -(RT)-), counters with type limits,
typed compares on Int/DInt/Real/Time, IN_RANGE/OUT_RANGE bounds, OK/NOT_OK, arithmetic."""

from __future__ import annotations

import math

from ladderworks.core.address import Address, Area
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.memory import Memory

REGISTRY = load_all()
T = Address(Area.D, 0)  # a timer instance
C = Address(Area.D, 100)  # a counter instance
INT, DINT, REAL, TIME = (int(typed.ValueType.INT), int(typed.ValueType.DINT),
                         int(typed.ValueType.REAL), int(typed.ValueType.TIME))


class Plc:
    """A big-endian memory and a clock; `run` calls one box as the scan does."""

    def __init__(self, scan_ms: int = 10) -> None:
        self.ctx = FunctionContext(Memory("big"), 0, scan_ms)
        self.states: dict[str, dict] = {}

    def run(self, name: str, inputs: tuple[bool, ...], params: tuple) -> bool:
        return REGISTRY[name](self.ctx, self.states.setdefault(name, {}), inputs, params)

    def at(self, ms: int) -> Plc:
        self.ctx.now_ms = ms
        return self

    def et(self) -> int:
        return self.ctx.memory.read(Address(Area.D, 4), 4, signed=True)


def test_ton_q_after_pt_and_reset_when_in_drops() -> None:
    plc = Plc()
    assert not plc.at(0).run("S7.TON", (True,), (T, 10_000, 0))
    assert not plc.at(9_990).run("S7.TON", (True,), (T, 10_000, 0))
    assert plc.at(10_000).run("S7.TON", (True,), (T, 10_000, 0))
    assert plc.et() == 10_000
    assert not plc.at(10_010).run("S7.TON", (False,), (T, 10_000, 0))
    assert plc.et() == 0


def test_ton_computes_et_when_it_runs_after_being_skipped() -> None:
    """A box not run for 7 s (skipped by a jump) catches up at its next run (3.5)."""
    plc = Plc()
    plc.at(0).run("S7.TON", (True,), (T, 5_000, 0))
    assert plc.at(7_000).run("S7.TON", (True,), (T, 5_000, 0))
    assert plc.et() == 5_000


def test_a_pt_change_while_ton_runs_has_no_effect() -> None:
    plc = Plc()
    plc.at(0).run("S7.TON", (True,), (T, 5_000, 0))
    assert not plc.at(4_990).run("S7.TON", (True,), (T, 9_000, 0))
    assert plc.at(5_000).run("S7.TON", (True,), (T, 9_000, 0))  # the PT taken at the start


def test_tof_holds_q_for_pt_after_in_drops() -> None:
    plc = Plc()
    assert plc.at(0).run("S7.TOF", (True,), (T, 3_000, 0))
    assert plc.at(100).run("S7.TOF", (False,), (T, 3_000, 0))
    assert plc.at(3_090).run("S7.TOF", (False,), (T, 3_000, 0))
    assert not plc.at(3_100).run("S7.TOF", (False,), (T, 3_000, 0))
    assert plc.at(3_200).run("S7.TOF", (True,), (T, 3_000, 0))


def test_tp_does_not_retrigger() -> None:
    plc = Plc()
    assert plc.at(0).run("S7.TP", (True,), (T, 1_000, 0))
    assert plc.at(500).run("S7.TP", (False,), (T, 1_000, 0))
    assert plc.at(600).run("S7.TP", (True,), (T, 1_000, 0))  # no new pulse, still the first
    assert not plc.at(1_000).run("S7.TP", (True,), (T, 1_000, 0))
    assert plc.et() == 1_000  # ET stays PT while IN is 1
    assert not plc.at(1_100).run("S7.TP", (False,), (T, 1_000, 0))
    assert plc.et() == 0


def test_tonr_keeps_time_while_in_is_off_and_r_resets() -> None:
    plc = Plc()
    plc.at(0).run("S7.TONR", (True, False), (T, 3_000, 0))
    plc.at(2_000).run("S7.TONR", (False, False), (T, 3_000, 0))
    assert plc.et() == 2_000
    plc.at(5_000).run("S7.TONR", (True, False), (T, 3_000, 0))
    assert not plc.at(5_990).run("S7.TONR", (True, False), (T, 3_000, 0))
    assert plc.at(6_000).run("S7.TONR", (True, False), (T, 3_000, 0))
    assert plc.at(6_500).run("S7.TONR", (False, False), (T, 3_000, 0))  # Q kept
    assert not plc.at(6_600).run("S7.TONR", (False, True), (T, 3_000, 0))
    assert plc.et() == 0


def test_pt_coil_loads_and_rt_coil_resets() -> None:
    plc = Plc()
    plc.at(0).run("S7.TON", (True,), (T, 10_000, 0))
    plc.at(100).run("S7.PT", (True,), (T, 200))
    assert plc.at(200).run("S7.TON", (True,), (T, 10_000, 0))
    plc.at(300).run("S7.RT", (True,), (T,))
    assert not plc.at(300).run("S7.TON", (True,), (T, 10_000, 0))
    assert plc.at(500).run("S7.TON", (True,), (T, 10_000, 0))


def test_et_goes_to_its_pin_big_endian() -> None:
    plc = Plc()
    et = Address(Area.R, 0)
    plc.at(0).run("S7.TON", (True,), (T, 10_000, et))
    plc.at(0x0102).run("S7.TON", (True,), (T, 10_000, et))
    assert bytes(plc.ctx.memory.areas[Area.R][0:4]) == b"\x00\x00\x01\x02"


def _pulse(plc: Plc, name: str, inputs: tuple[bool, ...], params: tuple) -> bool:
    plc.run(name, tuple(False if n == 0 else v for n, v in enumerate(inputs)), params)
    return plc.run(name, inputs, params)


def test_ctu_counts_edges_to_pv_and_r_resets() -> None:
    plc = Plc()
    params = (C, INT, 4, 0)
    results = [_pulse(plc, "S7.CTU", (True, False), params) for _ in range(5)]
    assert results == [False, False, False, True, True]
    assert not plc.run("S7.CTU", (True, True), params)
    assert plc.ctx.memory.read(C, 4, signed=True) == 0


def test_ctu_stops_at_the_type_limit() -> None:
    plc = Plc()
    plc.ctx.memory.write(C, 32_766, 4)
    for _ in range(3):
        _pulse(plc, "S7.CTU", (True, False), (C, INT, 100, 0))
    assert plc.ctx.memory.read(C, 4, signed=True) == 32_767


def test_ctd_loads_and_counts_down_and_ctud_both_in_one_scan_is_unchanged() -> None:
    plc = Plc()
    assert not plc.run("S7.CTD", (False, True), (C, INT, 3, 0))
    for expected in (False, False, True):
        assert _pulse(plc, "S7.CTD", (True, False), (C, INT, 3, 0)) is expected
    other = Plc()
    other.ctx.memory.write(C, 2, 4)
    other.run("S7.CTUD", (True, True, False, False), (C, INT, 4, 0, 0))
    assert other.ctx.memory.read(C, 4, signed=True) == 2


def test_compares_on_real_time_and_dint() -> None:
    plc = Plc()
    at = Address(Area.R, 8)
    plc.ctx.memory.write(at, typed.real_bits(1.5), 4)
    assert plc.run("S7.GT", (True,), (REAL, at, typed.real_bits(1.25)))
    assert not plc.run("S7.GT", (False,), (REAL, at, typed.real_bits(1.25)))
    plc.ctx.memory.write(at, 5_000, 4)
    assert plc.run("S7.GE", (True,), (TIME, at, 5_000))
    plc.ctx.memory.write(at, -70_000, 4)
    assert plc.run("S7.LT", (True,), (DINT, at, -69_999))


def test_in_range_bounds_are_inclusive() -> None:
    plc = Plc()
    at = Address(Area.R, 2)
    seen = {}
    for value in (49, 50, 150, 151):
        plc.ctx.memory.write(at, value, 2)
        seen[value] = (plc.run("S7.IN_RANGE", (True,), (INT, 50, at, 150)),
                       plc.run("S7.OUT_RANGE", (True,), (INT, 50, at, 150)))
    assert seen == {49: (False, True), 50: (True, False), 150: (True, False),
                    151: (False, True)}


def test_ok_and_not_ok() -> None:
    plc = Plc()
    at = Address(Area.R, 4)
    for value, valid in ((1.5, True), (math.inf, False), (math.nan, False), (1e-40, False)):
        plc.ctx.memory.write(at, typed.real_bits(value), 4)
        assert plc.run("S7.OK", (True,), (at,)) is valid
        assert plc.run("S7.NOT_OK", (True,), (at,)) is not valid


def test_add_wraps_with_eno_0_and_div_by_zero_writes_nothing() -> None:
    plc = Plc()
    out = Address(Area.R, 20)
    assert not plc.run("S7.ADD", (True,), (INT, 32_767, 1, out))
    assert plc.ctx.memory.read(out, 2, signed=True) == -32_768
    plc.ctx.memory.write(out, 7, 2)
    assert not plc.run("S7.DIV", (True,), (INT, 5, 0, out))
    assert plc.ctx.memory.read(out, 2) == 7
    assert plc.run("S7.DIV", (True,), (INT, -7, 2, out))
    assert plc.ctx.memory.read(out, 2, signed=True) == -3
    assert plc.run("S7.MOVE", (True,), (REAL, typed.real_bits(2.5), out))
    assert typed.read(plc.ctx.memory, out, typed.ValueType.REAL) == 2.5
    assert plc.run("S7.CONVERT", (True,), (REAL, INT, typed.real_bits(2.5), out))
    assert plc.ctx.memory.read(out, 2) == 2  # round half to even
    assert not plc.run("S7.MOVE", (False,), (INT, 9, out))


def test_edge_contact_and_sr() -> None:
    plc = Plc()
    operand, memory_bit, q = Address(Area.R, 30, 0), Address(Area.R, 30, 1), Address(Area.R, 31, 0)
    plc.ctx.memory.set_bit(operand, True)
    assert plc.run("S7.P", (True,), (operand, memory_bit))
    assert not plc.run("S7.P", (True,), (operand, memory_bit))
    assert plc.run("S7.SR", (True, False), (q,))
    assert not plc.run("S7.SR", (True, True), (q,))  # reset dominant
    assert plc.run("S7.RS", (True, True), (q,))  # set dominant
