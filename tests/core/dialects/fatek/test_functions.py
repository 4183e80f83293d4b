"""The Fatek box implementations called as the scan calls them (seed 001's timers, counters and
CMP; FUN 8, 11-17, 170-175; FUN 94 ASCWR to the terminal; the boxes not simulated)."""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.fatek.ascii_format import parse_format
from ladderworks.core.dialects.fatek.devices import Device, bit_address, fo_address, word_address
from ladderworks.core.dialects.fatek.terminal import AsciiTerminal
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.memory import Memory

REGISTRY = load_all()
FO = fo_address(0)


class Plc:
    """A memory and a clock; `run` calls one box the way the generated scan does."""

    def __init__(self, scan_ms: int = 10) -> None:
        self.ctx = FunctionContext(Memory(), 0, scan_ms)
        self.states: dict[str, dict] = {}

    def run(self, name: str, inputs: tuple[bool, ...], params: tuple, site: str = "") -> bool:
        result = REGISTRY[name](self.ctx, self.states.setdefault(name + site, {}), inputs,
                                params)
        return result

    def tick(self) -> None:
        self.ctx.now_ms += self.ctx.scan_ms

    def word(self, text: str) -> int:
        address, width = word_address(Device(text.rstrip("0123456789"),
                                             int(text.lstrip("CDRT"))))
        return self.ctx.memory.read(address, width, signed=True)

    def set_word(self, text: str, value: int) -> None:
        address, width = word_address(Device(text[0], int(text[1:])))
        self.ctx.memory.write(address, value, width)

    def bit(self, kind: str, number: int) -> int:
        return self.ctx.memory.bit(bit_address(Device(kind, number)))

    def fo(self) -> list[int]:
        value = self.ctx.memory.read(FO, 1)
        return [(value >> n) & 1 for n in range(3)]


def _time_to_contact(plc: Plc, timer: int, preset: int | Address, limit: int) -> int:
    for _ in range(limit):
        if plc.run("FBS.TMR", (True,), (timer, preset, FO)):
            return plc.ctx.now_ms
        plc.tick()
    return -1


def test_timer_t0_pv_1000_is_10_seconds() -> None:
    """001:392-416: T0 counts 0.01 s; PV 1000 -> 10 s."""
    plc = Plc()
    assert _time_to_contact(plc, 0, 1000, 2000) == 10_000
    assert plc.bit("T", 0) == 1 and plc.fo()[0] == 1
    for _ in range(40_000):  # 001:424-428: CV runs on to 32767 and stays there
        plc.tick()
        plc.run("FBS.TMR", (True,), (0, 1000, FO))
    assert plc.word("T0") == 32767
    plc.run("FBS.TMR", (False,), (0, 1000, FO))  # EN = 0: CV = 0, Tn and TUP open
    assert (plc.word("T0"), plc.bit("T", 0), plc.fo()[0]) == (0, 0, 0)


def test_timer_bases_and_a_register_preset() -> None:
    """T50 counts 0.1 s, T200 1 s; R0 = 100 -> 10 s, R0 = 200 -> 20 s (001:449-461)."""
    plc = Plc(scan_ms=100)
    assert _time_to_contact(plc, 200, 3, 100) == 3_000
    register, _ = word_address(Device("R", 0))
    for value, seconds in ((100, 10), (200, 20)):
        plc = Plc(scan_ms=100)
        plc.set_word("R0", value)
        assert _time_to_contact(plc, 50, register, 1000) == seconds * 1000


def test_up_counter() -> None:
    """001:598-612: each CK 0 -> 1 +1; CUP while CV >= PV; CLR clears and wins; 32767 top."""
    plc = Plc()
    for count in range(1, 11):
        plc.run("FBS.CTR", (False, False), (0, 10, FO))
        up = plc.run("FBS.CTR", (True, False), (0, 10, FO))
        assert plc.word("C0") == count
        assert up == (count >= 10)
    plc.run("FBS.CTR", (True, False), (0, 10, FO))  # held: counts once
    assert plc.word("C0") == 10 and plc.bit("C", 0) == 1
    plc.run("FBS.CTR", (False, True), (0, 10, FO))
    assert (plc.word("C0"), plc.bit("C", 0), plc.fo()[0]) == (0, 0, 0)
    assert not plc.run("FBS.CTR", (True, True), (0, 10, FO))  # CLR = 1: no counting
    assert plc.word("C0") == 0
    plc.set_word("C5", 32767)
    plc.run("FBS.CTR", (False, False), (5, 1, FO), "5")
    plc.run("FBS.CTR", (True, False), (5, 1, FO), "5")
    assert plc.word("C5") == 32767


def test_counters_retentive_and_32_bit() -> None:
    """001:576-588: C0-C139 keep their value at a load, C140-C199 start from 0; C200+ 32-bit."""
    plc = Plc()
    plc.set_word("C1", 7)
    plc.set_word("C150", 7)
    plc.run("FBS.CTR", (False, False), (1, 100, FO), "1")
    plc.run("FBS.CTR", (False, False), (150, 100, FO), "150")
    assert (plc.word("C1"), plc.word("C150")) == (7, 0)
    address, width = word_address(Device("C", 200))
    assert width == 4
    plc.ctx.memory.write(address, 40_000, 4)
    plc.run("FBS.CTR", (False, False), (200, 100_000, FO), "200")
    plc.run("FBS.CTR", (True, False), (200, 100_000, FO), "200")
    assert plc.ctx.memory.read(address, 4, signed=True) == 40_001


def test_up_down_counter() -> None:
    """001:652-694: U/D 1 up, 0 down; FO0 only while CV = PV; 32767 + 1 -> -32768 and back."""
    plc = Plc()
    c0 = word_address(Device("C", 0))[0]
    for expected, fo0 in ((1, False), (2, True), (3, False)):
        plc.run("FBS.UDCTR", (False, True, False), (c0, 2, FO))
        assert plc.run("FBS.UDCTR", (True, True, False), (c0, 2, FO)) is fo0
        assert plc.word("C0") == expected and plc.bit("C", 0) == fo0  # C0's contact too
    plc.set_word("C0", 32767)
    plc.run("FBS.UDCTR", (False, True, False), (c0, 2, FO))
    plc.run("FBS.UDCTR", (True, True, False), (c0, 2, FO))
    assert plc.word("C0") == -32768
    plc.run("FBS.UDCTR", (False, False, False), (c0, 2, FO))
    plc.run("FBS.UDCTR", (True, False, False), (c0, 2, FO))
    assert plc.word("C0") == 32767


def test_up_down_counter_on_a_register() -> None:
    """The FBs manual's own form (§5.1, `FUN 7 / CV: R 0 / PV: 10`): CV is a register; FO0
    while CV = PV; CLR clears it; no counter contact is touched."""
    plc = Plc()
    r0 = _r(0)
    for _ in range(2):
        plc.run("FBS.UDCTR", (False, True, False), (r0, 2, FO), "r")
        fo0 = plc.run("FBS.UDCTR", (True, True, False), (r0, 2, FO), "r")
    assert plc.word("R0") == 2 and fo0 and plc.fo()[0] == 1
    assert plc.bit("C", 0) == 0
    plc.run("FBS.UDCTR", (False, False, False), (r0, 2, FO), "r")
    assert not plc.run("FBS.UDCTR", (True, False, False), (r0, 2, FO), "r")  # down: 1
    assert plc.word("R0") == 1
    assert not plc.run("FBS.UDCTR", (False, False, True), (r0, 2, FO), "r")  # CLR
    assert plc.word("R0") == 0 and plc.fo()[0] == 0


def test_reset_of_a_timer_and_a_counter() -> None:
    plc = Plc()
    plc.set_word("C3", 9)
    plc.ctx.memory.set_bit(bit_address(Device("C", 3)), 1)
    plc.run("FBS.RST", (True,), (1, 3))
    assert (plc.word("C3"), plc.bit("C", 3)) == (0, 0)


def _r(number: int) -> Address:
    return word_address(Device("R", number))[0]


def test_cmp_of_seed_001() -> None:
    """001:1091-1095: R0 = 1, R1 = 2 -> FO0 = 0, FO1 = 0, FO2 = 1."""
    plc = Plc()
    plc.set_word("R0", 1)
    plc.set_word("R1", 2)
    assert not plc.run("FBS.CMP", (True,), (0, _r(0), _r(1), FO))
    assert plc.fo() == [0, 0, 1]


def test_move_and_arithmetic() -> None:
    plc = Plc()
    plc.run("FBS.MOV", (True,), (0, 1234, _r(2)))
    assert plc.word("R2") == 1234
    plc.set_word("R0", 32767)
    plc.run("FBS.ADD", (True,), (0, _r(0), 1, _r(1), FO))  # carry: wraps, FO1
    assert plc.word("R1") == -32768 and plc.fo()[:2] == [0, 1]
    plc.run("FBS.SUB", (True,), (0, 5, 5, _r(1), FO))
    assert plc.word("R1") == 0 and plc.fo()[0] == 1
    plc.run("FBS.MUL", (True,), (0, 300, 300, _r(4), FO))  # 90000: D and the next register
    assert plc.ctx.memory.read(_r(4), 4, signed=True) == 90_000
    plc.run("FBS.DIV", (True,), (0, -7, 2, _r(6), FO))
    assert (plc.word("R6"), plc.word("R7")) == (-3, -1)
    plc.run("FBS.DIV", (True,), (0, 7, 0, _r(6), FO), "zero")
    assert plc.fo()[1] == 1 and plc.word("R6") == -3  # ERR, nothing written


def test_pulse_form_runs_on_the_rising_edge_only() -> None:
    plc = Plc()
    for enable in (True, True, False, True):
        plc.run("FBS.INC", (enable,), (1, _r(9), FO))
    assert plc.word("R9") == 2
    assert plc.fo() == [0, 0, 0]  # no overflow (FO0 is not "D = 0")
    plc.set_word("R8", -32768)
    plc.run("FBS.DEC", (True,), (0, _r(8), FO))  # underflow: FO0 (FBs manual §5.4, UDF)
    assert plc.word("R8") == 32767 and plc.fo() == [1, 0, 0]
    plc.set_word("R8", 32767)
    assert plc.run("FBS.INC", (True,), (0, _r(8), FO))  # overflow: FO0 (manual: CY, FO0)
    assert plc.word("R8") == -32768 and plc.fo() == [1, 0, 0]
    plc.set_word("R8", -1)
    assert not plc.run("FBS.INC", (True,), (0, _r(8), FO))  # D = 0 is no output of (+1)
    assert plc.word("R8") == 0 and plc.fo() == [0, 0, 0]


def test_comparison_contacts() -> None:
    plc = Plc()
    plc.set_word("R0", 5)
    cases = {"FBS.EQ": (5, True), "FBS.GT": (4, True), "FBS.LT": (6, True), "FBS.NE": (5, False),
             "FBS.GE": (5, True), "FBS.LE": (4, False)}
    for name, (other, passes) in cases.items():
        assert plc.run(name, (True,), (0, _r(0), other)) is passes, name
        assert plc.run(name, (False,), (0, _r(0), other)) is False


def test_edge_contacts_are_on_for_one_execution() -> None:
    plc = Plc()
    x0 = bit_address(Device("X", 0))
    seen = []
    for value in (0, 1, 1, 0, 0):
        plc.ctx.memory.set_bit(x0, value)
        seen.append((plc.run("FBS.TU", (True,), (x0,)), plc.run("FBS.TD", (True,), (x0,))))
    assert seen == [(False, False), (True, False), (False, False), (False, True),
                    (False, False)]


def test_ascwr_writes_the_report_to_the_terminal() -> None:
    plc = Plc()
    terminal = AsciiTerminal()
    fmt, problems = parse_format("'R0=',\"6R0\",/,END")
    assert problems == []
    plc.ctx.extra["ascii_files"] = {_r(1000): fmt}
    plc.ctx.extra["ascii_terminal"] = terminal
    plc.set_word("R0", -42)
    params = (0, _r(1000), _r(10), FO)
    plc.run("FBS.ASCWR", (False, False, False), params)
    plc.run("FBS.ASCWR", (True, True, False), params)  # PAU: nothing sent
    assert terminal.text() == ""
    plc.run("FBS.ASCWR", (False, False, False), params)
    plc.run("FBS.ASCWR", (True, False, False), params)
    plc.run("FBS.ASCWR", (True, False, False), params)  # held: sent once
    assert terminal.text() == "R0=   -42\n"
    assert plc.fo() == [0, 0, 1]  # DN
    plc.run("FBS.ASCWR", (False, False, False), params)
    other = (0, _r(2000), _r(10), FO)
    plc.run("FBS.ASCWR", (True, False, False), other, "2")
    assert plc.fo() == [0, 1, 0]  # ERR: no ASCII file at R2000


def test_boxes_not_simulated_keep_their_outputs_at_0() -> None:
    plc = Plc()
    plc.ctx.memory.write(FO, 0xFF, 1)
    assert not plc.run("FBS.HSPSO", (True,), (140, FO))
    assert plc.ctx.memory.read(Address(Area.R, FO.byte), 1) == 0
