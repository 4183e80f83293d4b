"""PlcRun, the session policy without Qt: cold start, held inputs, forces over a reload, params."""

from __future__ import annotations

from typing import Any

import pytest

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.il import parse
from ladderworks.core.plc import engine as engine_module
from ladderworks.core.plc.codegen import GeneratedScan, generate
from ladderworks.core.plc.parameters import parse_parameters
from ladderworks.core.plc.session import PlcRun

TIMER = "%@3\nRD R1.4\nTMR 1\nWRT R1.7\nRD X2.1\nWRT R2.0\nRD K5.0\nWRT Y0.0\n%\n"
OTHER = "%@3\nRD X2.1\nWRT Y1.0\n%\n"


def a(text: str) -> Address:
    """An address from text."""
    return parse_address(text)


def loaded(text: str = TIMER) -> PlcRun:
    """A run on the virtual clock with `text` loaded and started."""
    run = PlcRun()
    assert run.load_program(parse(text).program).binary is not None
    assert run.start()
    return run


def test_parameters_are_applied_after_the_cold_start() -> None:
    run = PlcRun()
    run.set_parameters(parse_parameters("T0:4 = 100\nK5 = 0b1\n").parameters)
    run.write(a("R1"), 0xFF)
    assert run.load_program(parse(TIMER).program).binary is not None
    assert run.read(a("R1")) == 0  # cold start
    assert run.timer_preset(1) == 100 and run.bit(a("K5.0")) == 1
    run.start()
    run.set_bit(a("R1.4"), 1)
    run.step(96)
    assert run.bit(a("R1.7")) == 0
    run.step(8)  # the scan at 96 ms: 100 ms rounded down to 48 ms ticks
    assert run.bit(a("R1.7")) == 1 and run.bit(a("Y0.0")) == 1


def test_table_values_are_parameters_and_survive_a_reload() -> None:
    run = loaded()
    run.set_timer_preset(1, 960)
    run.set_counter_preset(3, 12)
    run.set_counter_value(3, 4)
    run.write(a("D7"), 9)  # a machine-side write is not a parameter
    assert [str(v.address) for v in run.parameters] == ["T0", "C8", "C10"]
    assert run.load_program(parse(OTHER).program).binary is not None
    assert run.timer_preset(1) == 960 and run.counter(3) == (12, 4) and run.read(a("D7")) == 9


def test_opening_parameters_resets_the_tables_to_them() -> None:
    run = loaded()
    run.write(a("K9"), 3)
    run.set_parameters(parse_parameters("D1 = 2\n").parameters)
    assert run.read(a("K9")) == 0 and run.read(a("D1")) == 2


def test_forces_stay_over_a_reload_disabled_elements_do_not() -> None:
    run = loaded()
    run.force(a("X2.1"), 1)
    run.disable(0)
    run.start_trace([a("X2.1")], 8)
    assert run.load_program(parse(OTHER).program).binary is not None
    assert not run.running
    assert [str(e) for e in run.forces()] == ["force X2.1 = 1"]
    run.start()
    run.run_scans(1)
    assert run.bit(a("Y1.0")) == 1
    assert [s.values for s in run.trace_samples()] == [(1,)]


def test_a_released_machine_input_gets_its_machine_value_back() -> None:
    run = loaded()
    run.set_bit(a("X2.1"), 1)
    run.force(a("X2.1"), 0)
    run.set_bit(a("X2.1"), 0)  # the machine changes the wire while forced
    run.set_bit(a("X2.1"), 1)
    run.run_scans(1)
    assert run.bit(a("R2.0")) == 0
    run.release(a("X2.1"))
    run.run_scans(1)
    assert run.bit(a("R2.0")) == 1
    run.force(a("R9.0"), 1)  # not a machine area: nothing held
    run.release_all()
    assert run.bit(a("R9.0")) == 1 and run.forces() == []


def test_stop_is_the_safe_state_and_figures_count_scans() -> None:
    run = loaded()
    assert run.step(80) == 10
    status = run.status()
    assert status.running and status.scan_count == 10 and status.max_ms >= status.min_ms > 0
    run.write(Address(Area.Y, 0), 0xFF)
    assert run.stop() and not run.stop()
    assert run.read(Address(Area.Y, 0)) == 0 and run.run_scans(3) == 0


def test_a_refused_binary_leaves_the_run_as_it_was() -> None:
    run = loaded()
    problems = run.load(b"not a program")
    assert problems and problems[0].code == "bad-binary"
    assert run.running and run.engine is not None


def test_a_load_while_a_view_monitors_generates_one_scan_variant(
        monkeypatch: pytest.MonkeyPatch) -> None:
    made: list[bool] = []

    def counted(*args: Any, **kwargs: Any) -> GeneratedScan:
        made.append(kwargs["monitored"])
        return generate(*args, **kwargs)

    monkeypatch.setattr(engine_module, "generate", counted)
    run = PlcRun()
    run.monitor(True)
    assert run.load_program(parse(TIMER).program).binary is not None
    assert made == [True] and run.engine is not None and run.engine.monitored
    run.start()
    run.set_bit(a("R1.4"), 1)
    run.set_bit(a("X2.1"), 1)
    run.step(8)
    assert list(run.engine.power_flow)[3:5] == [1, 1]  # RD X2.1, WRT R2.0
    run.monitor(False)  # the fast variant is made when first needed
    assert made == [True, False] and not run.engine.monitored
    run.set_bit(a("X2.1"), 0)
    run.step(8)
    assert run.bit(a("R2.0")) == 0
    run.set_bit(a("X2.1"), 1)
    run.step(8)
    assert run.bit(a("R2.0")) == 1


def test_a_load_without_monitoring_generates_the_fast_variant_only(
        monkeypatch: pytest.MonkeyPatch) -> None:
    made: list[bool] = []

    def counted(*args: Any, **kwargs: Any) -> GeneratedScan:
        made.append(kwargs["monitored"])
        return generate(*args, **kwargs)

    monkeypatch.setattr(engine_module, "generate", counted)
    assert loaded().engine is not None
    assert made == [False]
