"""Delta high-speed counters C241-C255 (DCNT): one input with reset/start, up/down inputs, A/B
phases, counted from their X inputs as the scan sees them, fast and monitored; skipping scans
equal to every scan."""

from __future__ import annotations

import pytest

from tests.core.dialects.conftest import engine, get, put
from tests.core.dialects.test_delta_words32 import same_when_skipping

MODES = pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])


def _feed(plc, steps: list[dict[str, int]]) -> None:
    """One scan per step, with the inputs it names set first."""
    for inputs in steps:
        for name, on in inputs.items():
            put(plc, name, on)
        plc.scan()


def _pulses(name: str, count: int) -> list[dict[str, int]]:
    return [step for _ in range(count) for step in ({name: 1}, {name: 0})]


@MODES
def test_c241_counts_x0_down_by_m1241_and_x1_resets(monitored: bool) -> None:
    plc = engine("LD M10\nDCNT C241 K3\nLD C241\nOUT Y0\nEND\n", monitored=monitored)
    _feed(plc, _pulses("X0", 2))
    assert get(plc, "C241") == 0  # DCNT's input off: no count
    put(plc, "M10", 1)
    _feed(plc, _pulses("X0", 3))
    assert (get(plc, "C241"), get(plc, "Y0")) == (3, 1)
    put(plc, "M1241", 1)
    _feed(plc, _pulses("X0", 1))
    assert (get(plc, "C241"), get(plc, "Y0")) == (2, 0)
    _feed(plc, [{"X1": 1}, {"X0": 1}, {"X0": 0}])  # R on: held at 0
    assert get(plc, "C241") == 0
    put(plc, "M10", 0)
    _feed(plc, [{"X1": 0}, {"X1": 0}])
    put(plc, "C241", 7)
    _feed(plc, [{"X1": 1}])  # the reset works with DCNT's input off too
    assert get(plc, "C241") == 0


@MODES
def test_c244_counts_only_while_its_start_input_x6_is_on(monitored: bool) -> None:
    plc = engine("LD M1000\nDCNT C244 K100\nLD M1000\nDCNT C242 K100\nEND\n",
                 monitored=monitored)
    _feed(plc, _pulses("X0", 2))
    put(plc, "X6", 1)
    _feed(plc, _pulses("X0", 3) + _pulses("X2", 4))
    assert (get(plc, "C244"), get(plc, "C242")) == (3, 4)
    _feed(plc, [{"X3": 1}])  # C242's reset
    assert get(plc, "C242") == 0 and get(plc, "C244") == 3


@MODES
def test_c246_up_and_down_inputs_and_the_direction_flag(monitored: bool) -> None:
    plc = engine("LD M1000\nDCNT C246 D0\nLD C246\nOUT Y0\nLD M1000\nDCNT C248 K10\nEND\n",
                 monitored=monitored)
    put(plc, "D0:4", 70000)
    put(plc, "C246", 69998)
    _feed(plc, _pulses("X0", 2))
    assert (get(plc, "C246"), get(plc, "Y0"), get(plc, "M1246")) == (70000, 1, 0)
    _feed(plc, _pulses("X1", 3))
    assert (get(plc, "C246"), get(plc, "Y0"), get(plc, "M1246")) == (69997, 0, 1)
    _feed(plc, [{"X0": 1, "X1": 1}, {"X0": 0, "X1": 0}])  # both at once: +1 -1
    assert get(plc, "C246") == 69997
    _feed(plc, _pulses("X3", 5) + _pulses("X4", 1))  # C248: U X3, D X4, R X5
    assert get(plc, "C248") == 4
    _feed(plc, [{"X5": 1}])
    assert get(plc, "C248") == 0


@MODES
def test_c251_a_b_phases_count_up_when_a_leads_down_when_b_leads(monitored: bool) -> None:
    plc = engine("LD M1000\nDCNT C251 K2\nLD C251\nOUT Y0\nEND\n", monitored=monitored)
    forward = [{"X0": 1}, {"X1": 1}, {"X0": 0}, {"X1": 0}]  # A leads B
    backward = [{"X1": 1}, {"X0": 1}, {"X1": 0}, {"X0": 0}]  # B leads A
    _feed(plc, forward * 3)
    assert (get(plc, "C251"), get(plc, "Y0"), get(plc, "M1251")) == (3, 1, 0)
    _feed(plc, backward * 2)
    assert (get(plc, "C251"), get(plc, "Y0"), get(plc, "M1251")) == (1, 0, 1)
    _feed(plc, [{"X0": 1, "X1": 1}, {"X0": 0, "X1": 0}])  # both changed in one scan: no count
    assert get(plc, "C251") == 1


@MODES
def test_c254_reset_x2_and_start_x6_and_c253_on_x3_x4(monitored: bool) -> None:
    plc = engine("LD M1000\nDCNT C254 K100\nLD M1000\nDCNT C253 K100\nEND\n",
                 monitored=monitored)
    forward = [{"X0": 1}, {"X1": 1}, {"X0": 0}, {"X1": 0}]
    _feed(plc, forward * 2)
    assert get(plc, "C254") == 0  # S (X6) off
    put(plc, "X6", 1)
    _feed(plc, forward * 2)
    assert get(plc, "C254") == 2
    _feed(plc, [{"X2": 1}])
    assert get(plc, "C254") == 0
    _feed(plc, [{"X3": 1}, {"X4": 1}, {"X3": 0}, {"X4": 0}] * 3)
    assert get(plc, "C253") == 3


@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_high_speed_counters_skip_exactly(monitored: bool) -> None:
    same_when_skipping("LD X10\nDCNT C241 K5\nLD X11\nDCNT C245 K5\nLD X12\nDCNT C247 D0\n"
                       "LD X13\nDCNT C250 K3\nLD X14\nDCNT C252 K4\nLD X15\nDCNT C255 K-2\n"
                       "LD C247\nOUT Y0\nLD C252\nOUT Y1\nEND\n", 800, monitored)


# each counter's inputs as docs/dialects.md lists them: (kind, U/D or U or A, D or B, R, S)
INPUTS = {
    241: ("1", "X0", None, "X1", None), 242: ("1", "X2", None, "X3", None),
    243: ("1", "X3", None, "X4", None), 244: ("1", "X0", None, "X1", "X6"),
    245: ("1", "X2", None, "X3", "X7"),
    246: ("2", "X0", "X1", None, None), 247: ("2", "X0", "X1", "X2", None),
    248: ("2", "X3", "X4", "X5", None), 249: ("2", "X0", "X1", "X2", "X6"),
    250: ("2", "X3", "X4", "X5", "X7"),
    251: ("AB", "X0", "X1", None, None), 252: ("AB", "X0", "X1", "X2", None),
    253: ("AB", "X3", "X4", "X5", None), 254: ("AB", "X0", "X1", "X2", "X6"),
    255: ("AB", "X3", "X4", "X5", "X7"),
}


@pytest.mark.parametrize("number", sorted(INPUTS))
def test_each_counter_counts_its_own_inputs(number: int) -> None:
    kind, first, second, reset, start = INPUTS[number]
    plc = engine(f"LD M1000\nDCNT C{number} K3\nLD C{number}\nOUT Y0\nEND\n")
    if start is not None:
        _feed(plc, _pulses(first, 2))
        assert get(plc, f"C{number}") == 0  # not started
        put(plc, start, 1)
    others = [f"X{k}" for k in range(8) if f"X{k}" not in (first, second, reset, start)]
    _feed(plc, [step for name in others for step in _pulses(name, 1)])  # not its inputs
    up = _pulses(first, 3) if kind != "AB" else \
        [{first: 1}, {second: 1}, {first: 0}, {second: 0}] * 3
    _feed(plc, up)
    assert (get(plc, f"C{number}"), get(plc, "Y0")) == (3, 1)
    if kind == "1":
        put(plc, f"M{number + 1000}", 1)
        _feed(plc, _pulses(first, 1))
    elif kind == "2":
        _feed(plc, _pulses(second, 1))
    else:
        _feed(plc, [{second: 1}, {first: 1}, {second: 0}, {first: 0}])
    assert (get(plc, f"C{number}"), get(plc, "Y0")) == (2, 0)
    if kind != "1":
        assert get(plc, f"M{number + 1000}") == 1  # counted down last
    if reset is not None:
        _feed(plc, [{reset: 1}])
        assert get(plc, f"C{number}") == 0
