"""The native scan (llvmlite) is exactly the Python scan: differential runs on two engines.

Each program runs on a Python engine and a native one (`backend="native"`), with the same
changes written between runs of 1 to 600 scans (X/F inputs, R/D bytes written from outside,
forced and released bits, disabled elements, cold starts); after every run all memory, the
clock, the scan count, every call site's state, the DIFU/DIFD edge memories, the A-area log
and (monitored) the power flow must be equal (`differences` of test_skipping.py). The Python
engine runs every scan; the native one skips the scans of a repeating state as `advance` does,
so the skipper is proven on the native states too. Programs: every example (PMC, Delta,
Fatek), the three real programs (compiled once per session: the compiled-program cache), and
random programs (hypothesis) with levels, JMP/COM, subprograms, timers, edges, moves,
compares and arithmetic, forces and disabled elements, monitored or not.
"""

from __future__ import annotations

import ctypes
import dataclasses
import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.il import parse, parse_file
from ladderworks.core.plc import engine as engine_module
from ladderworks.core.plc.codegen import ScanLoopError
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.native import disk_cache, jit
from tests.core.plc.test_skipping import (
    EXAMPLE_FILES,
    Driver,
    binary_of,
    bytes_of,
    program_inputs,
    random_program,
)
from tests.hypothesis_profiles import examples
from tests.real_programs import WHOLE, real_programs_dir


@pytest.fixture(autouse=True)
def disk_cache_in_tmp(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Compiled programs go to a directory of the test's, not the user's cache."""
    monkeypatch.setenv(disk_cache.ENV, str(tmp_path / "native-cache"))


def pair(binary: BinaryProgram, divisions: int = 1,
         monitored: bool = False) -> tuple[ScanEngine, ScanEngine]:
    """A Python engine running every scan and a native one of the same program (skipping
    scans when not monitored: the skipper reads the native scan's states after every scan;
    every scan when monitored: they are written back only when `advance` returns)."""
    python = ScanEngine(binary, divisions=divisions, monitored=monitored)
    native = ScanEngine(binary, divisions=divisions, monitored=monitored, backend="native")
    python.every_scan = True
    native.every_scan = monitored
    assert native.backend_used == "native", native.backend_reason
    return python, native


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
@pytest.mark.parametrize("monitored", [False, True], ids=["fast", "monitored"])
def test_every_example_runs_the_same_on_the_native_scan(path: Path, monitored: bool) -> None:
    compiled = compile_program(parse_file(path).program)
    assert compiled.binary is not None
    binary = decode(compiled.binary)
    engines = pair(binary, monitored=monitored)
    inputs, used, coils = program_inputs(binary)
    rng = random.Random(path.stem)
    driver = Driver(engines, rng, inputs or bytes_of(Area.X, 4),
                    used, (inputs and [Address(a.area, a.byte, 0) for a in inputs[:2]]) + coils[:4])
    driver.run(1500, rate=0.1)
    for op in rng.sample(range(len(binary.ops)), k=min(2, len(binary.ops))):
        for engine in engines:
            engine.disable(op)
    driver.run(200, rate=0.2)
    for engine in engines:
        engine.release_all()
        engine.cold_start()
    driver.run(300, rate=0.2)


@settings(max_examples=examples(200), deadline=None)
@given(seed=st.integers(0, 10**9), divisions=st.sampled_from([1, 1, 2]),
       monitored=st.booleans())
def test_random_programs_run_the_same_on_the_native_scan(seed: int, divisions: int,
                                                        monitored: bool) -> None:
    rng = random.Random(seed)
    result = compile_program(parse(random_program(rng)).program)
    if result.binary is None:  # a range the generator left open across a level end
        return
    engines = pair(decode(result.binary), divisions, monitored)
    driver = Driver(engines, rng, bytes_of(Area.X, 2), bytes_of(Area.R, 6),
                    [Address(Area.X, 0, 1), Address(Area.R, 1, 2), Address(Area.R, 0, 0),
                     Address(Area.R, 9091, 5)])
    driver.run(300, rate=0.2)
    driver.run(1200, rate=0.02, longest=600)
    for op in rng.sample(range(len(engines[0].program.ops)), k=1):
        for engine in engines:
            engine.disable(op)
    driver.run(100, rate=0.2)
    for engine in engines:
        engine.release_all()
        engine.cold_start()
    driver.run(100, rate=0.2)


# -- structure: labels, JMPC, the loop guard, COM -------------------------------------------

LABELS = """
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
RD X0.1
CALL P1
RD R9091.1
WRT Y0.2
LBL L5
RD X0.2
COM 1
RD X0.3
WRT Y0.3
RD R9091.1
WRT Y0.4
END2
SP P1
RD X0.4
JMPC L5
RD R9091.1
WRT Y0.5
SPE
END
"""


def test_labels_jmpc_and_com_run_the_same() -> None:
    engines = pair(binary_of("%@3\n" + LABELS + "%\n"), monitored=True)
    driver = Driver(engines, random.Random(5), bytes_of(Area.X, 1), bytes_of(Area.D, 2),
                    [Address(Area.X, 0, 4)])
    driver.run(400, rate=0.5, longest=5)


def test_an_endless_loop_stops_the_native_scan_as_it_stops_the_python_one() -> None:
    binary = binary_of("%@3\nRD X0.0\nWRT Y0.0\nLBL L1\nRD R9091.1\nJMPB L1\n%\n")
    found = []
    for engine in pair(binary):
        engine.memory.set_bit(Address(Area.X, 0, 0), 1)
        with pytest.raises(ScanLoopError) as info:
            engine.scan()
        found.append(([(d.code, d.line, d.args["label"]) for d in info.value.diagnostics],
                      bytes(engine.memory.areas[Area.Y]), engine.memory.areas[Area.R][9091]))
    assert found[0] == found[1]
    assert found[0][0] == [("endless-loop", 4, 1)]  # line 1 is `%@3`


def test_an_error_in_a_called_back_function_reaches_the_caller(
        monkeypatch: pytest.MonkeyPatch) -> None:
    binary = binary_of("RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nDCNV D0 D2\n"
                       "WRT Y0.0\n")
    binary = dataclasses.replace(binary, ops=tuple(  # DCNV of D area's last byte: called back
        dataclasses.replace(op, params=(Address(Area.D, 9999), *op.params[1:]))
        if op.name == "DCNV" else op for op in binary.ops))
    engine = ScanEngine(binary, backend="native")
    assert engine.backend_used == "native"
    assert len(engine._current.callbacks) == 1

    def broken(*args: object) -> bool:
        raise ZeroDivisionError("broken timer")

    engine._current._sites[0] = (broken, *engine._current._sites[0][1:])
    with pytest.raises(ZeroDivisionError, match="broken timer"):
        engine.scan()
    assert engine.memory.areas[Area.R][9091] & 8  # stopped inside level 2, as Python stops


# -- choosing the backend ----------------------------------------------------------------------


def test_the_python_scan_runs_and_says_why_when_the_native_one_cannot_be_built(
        monkeypatch: pytest.MonkeyPatch) -> None:
    binary = binary_of("%@3\nRD X0.0\nWRT Y0.0\n%\n")
    monkeypatch.setattr(engine_module, "native_unavailable", lambda: "llvmlite is not here")
    engine = ScanEngine(binary, backend="native")
    assert (engine.backend_used, engine.backend_reason) == ("python", "llvmlite is not here")
    monkeypatch.undo()

    def failing(*args: object) -> object:
        raise RuntimeError("LLVM said no")

    jit.clear_cache()
    monkeypatch.setattr(jit, "compile_ir", failing)
    engine = ScanEngine(binary, backend="native")
    assert engine.backend_used == "python"
    assert engine.backend_reason == "the native compile failed: LLVM said no"
    engine.memory.set_bit(Address(Area.X, 0, 0), 1)
    engine.scan()
    assert engine.memory.bit(Address(Area.Y, 0, 0)) == 1
    with pytest.raises(ValueError):
        ScanEngine(binary, backend="fortran")


def test_a_program_loaded_again_comes_from_the_cache() -> None:
    binary = binary_of("%@3\nRD X0.0\nAND X0.1\nWRT Y0.0\n%\n")
    jit.clear_cache()
    first = ScanEngine(binary, backend="native")
    second = ScanEngine(binary, backend="native")
    assert not first._current.from_cache
    assert second._current.from_cache
    assert first._current.compiled is second._current.compiled
    second.memory.set_bit(Address(Area.X, 0, 0), 1)
    second.memory.set_bit(Address(Area.X, 0, 1), 1)
    second.scan()  # engines share the code, not the memory
    assert second.memory.bit(Address(Area.Y, 0, 0)) == 1
    first.scan()
    assert first.memory.bit(Address(Area.Y, 0, 0)) == 0


def test_a_new_process_loads_the_compiled_program_from_disk(tmp_path: Path) -> None:
    binary = binary_of("%@3\nRD X0.0\nTMRB 1 40\nWRT Y0.0\nRD X0.1\nDIFU 2\nWRT Y0.1\n%\n")
    jit.clear_cache()
    compiled = ScanEngine(binary, backend="native")
    assert not compiled._current.compiled.from_disk
    files = sorted(p.suffix for p in (tmp_path / "native-cache").iterdir())
    assert files == [".facts", ".o"]
    jit.clear_cache()  # as in a new process
    python, loaded = ScanEngine(binary), ScanEngine(binary, backend="native")
    assert loaded._current.compiled.from_disk
    driver = Driver((python, loaded), random.Random(3), bytes_of(Area.X, 1), [], [])
    driver.run(300, rate=0.3, longest=10)
    for path in (tmp_path / "native-cache").glob("*.o"):
        path.write_bytes(path.read_bytes()[:100])  # cut short: its hash differs
    jit.clear_cache()
    again = ScanEngine(binary, backend="native")  # a damaged file: compiled again
    assert again.backend_used == "native" and not again._current.compiled.from_disk


# -- the real programs ----------------------------------------------------------------------


@pytest.fixture(scope="session")
def real_binaries() -> dict[str, BinaryProgram]:
    """The three real programs, decoded once per session (their native code is then compiled
    once: the cache keeps it for every engine of the session)."""
    found = {}
    for name in WHOLE:
        compiled = compile_program(parse_file(real_programs_dir() / f"{name}.txt").program)
        assert compiled.binary is not None
        found[name] = decode(compiled.binary)
    return found


@pytest.mark.parametrize("name", WHOLE)
def test_real_programs_run_the_same_on_the_native_scan(
        name: str, real_binaries: dict[str, BinaryProgram]) -> None:
    binary = real_binaries[name]
    engines = pair(binary)
    inputs, used, coils = program_inputs(binary)
    driver = Driver(engines, random.Random(name), inputs, used[:200], coils[:20])
    driver.run(300, rate=0.2, longest=20)
    driver.run(600, rate=0.02, longest=600)


# -- the command line --------------------------------------------------------------------------

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples"


def test_cli_run_and_test_take_the_backend_and_say_which_ran(
        capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    from ladderworks.cli import main

    program = str(EXAMPLES / "timer_relay.LAD")
    scenario = str(EXAMPLES / "timer_relay.scenario.csv")
    outputs = []
    for backend, name in (("python", "Python"), ("native", "native")):
        assert main(["run", program, "--ms", "3000", "--set", "X0.0=1", "--print", "Y0.0,R0",
                     "--backend", backend]) == 0
        assert main(["test", program, scenario, "--backend", backend]) == 0
        captured = capsys.readouterr()
        outputs.append(captured.out.splitlines()[0])
        assert captured.err.splitlines() == [f"ladderworks-cli: the {name} scan runs",
                                             f"ladderworks-cli: {program}: the {name} scan runs"]
    assert outputs[0] == outputs[1]
    assert main(["run", program, "--ms", "100"]) == 0  # no --backend: nothing said
    assert main(["test", program, scenario]) == 0
    assert capsys.readouterr().err == ""
    monkeypatch.setattr(engine_module, "native_unavailable", lambda: "llvmlite is not here")
    assert main(["run", program, "--backend", "native"]) == 0
    assert main(["test", program, scenario, "--backend", "native"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == ["ladderworks-cli: the Python scan runs: llvmlite is not here",
                   f"ladderworks-cli: {program}: the Python scan runs: llvmlite is not here"]


@pytest.mark.parametrize("header", ["%@3\n", ""], ids=["fanuc", "seed"])
def test_tmr_reads_its_preset_and_precision_as_the_python_scan_does(header: str) -> None:
    text = "RD X0.0\nTMR 1\nWRT Y0.0\nRD X0.1\nTMR 9\nWRT Y0.1\nRD X0.2\nTMR 3\nWRT Y0.2\n"
    binary = binary_of(header + text + ("%\n" if header else ""))
    engines = pair(binary)
    assert engines[1]._current.callbacks == []
    presets = [Address(Area.T, byte) for byte in (0, 1, 4, 16, 17, 32, 33)]
    precision = [Address(Area.T, 9000 + byte) for byte in (0, 4, 16)]
    driver = Driver(engines, random.Random(header), bytes_of(Area.X, 1), presets + precision,
                    [])
    driver.run(2000, rate=0.3, longest=40)


@pytest.mark.parametrize("header", ["%@3\n", ""], ids=["fanuc", "seed"])
def test_tmrc_reads_its_preset_and_writes_its_register_as_the_python_scan_does(
        header: str) -> None:
    text = "RD X0.0\nTMRC 0 D0 D4\nWRT Y0.0\nRD X0.1\nTMRC 1 D2 D8\nWRT Y0.1\n" \
           "RD X0.2\nTMRC 6 D12 D14\nWRT Y0.2\n"
    binary = binary_of(header + text + ("%\n" if header else ""))
    engines = pair(binary)
    assert engines[1]._current.callbacks == []
    presets = [Address(Area.D, byte) for byte in (0, 1, 2, 12)]  # small presets: reached
    driver = Driver(engines, random.Random(7), bytes_of(Area.X, 1), presets, [])
    driver.run(1500, rate=0.3, longest=40)


def test_dcnvb_converts_as_the_python_scan_does() -> None:
    """Binary <-> BCD of 1, 2 and 4 bytes: signs, invalid digits, values too large, RST and
    ACT; the target, R9000 and W1 as in Python."""
    text = "".join(f"RD X{k}.0\nRD.STK X{k}.1\nRD.STK X{k}.2\nRD.STK X{k}.3\n"
                   f"DCNVB {width} D{8 * k} D{8 * k + 4}\nWRT Y0.{k}\n"
                   for k, width in enumerate((1, 2, 4)))
    engines = pair(binary_of("%@3\n" + text + "%\n"))
    assert engines[1]._current.callbacks == []
    sources = [Address(Area.D, 8 * k + byte) for k in range(3) for byte in range(4)]
    driver = Driver(engines, random.Random(11), bytes_of(Area.X, 3), sources, [])
    driver.run(1500, rate=0.5, longest=10)
    rng = random.Random(12)
    for _ in range(400):  # every scan with new data: BCD digits valid or not, signs
        data = bytes(rng.choice((0x99, 0x12, 0x9A, 0x80, 0xFF, 0x00, rng.randrange(256)))
                     for _ in range(24))
        inputs = bytes(rng.randrange(16) for _ in range(3))
        for engine in engines:
            engine.memory.areas[Area.D][:24] = data
            engine.memory.areas[Area.X][:3] = inputs
            engine.scan()
        assert engines[0].memory.areas == engines[1].memory.areas
        assert engines[1].call_states() == engines[0].call_states()


def test_scans_one_by_one_give_the_states_when_asked() -> None:
    """`scan()` (the real-time runner's) leaves the native states in their words; they reach
    the dicts when read: call_states(), export_state(), a variant switch, `advance`."""
    text = "%@3\nRD X0.0\nTMRB 1 40\nWRT Y0.0\nRD X0.0\nDIFU 3\nWRT Y0.1\n" \
           "RD X0.1\nRD.STK X0.0\nADDB 2 D0 1 D0\nWRT Y0.2\n%\n"
    python, native = pair(binary_of(text))
    for step in range(40):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = (step // 7) % 4
            engine.scan()
        assert native.call_states() == python._states
        assert native._ctx.edges == python._ctx.edges
        if step % 10 == 9:
            assert native.export_state() == python.export_state()
            for engine in (python, native):
                engine.monitored = not engine.monitored  # another variant from the next scan
    assert python.memory.areas == native.memory.areas


def test_decb_codb_and_arithmetic_errors_run_the_same() -> None:
    text = ("RD X0.0\nDECB 1 R10 3 R20\nRD X0.1\nRD.STK X0.2\nCODB 2 4 R11 D8 1000 -5 32767 "
            "70000 9\nWRT Y0.0\nRD X0.3\nRD.STK X0.4\nDIVB 2 D0 D2 D4\nWRT Y0.1\n"
            "RD X0.5\nRD.STK X0.6\nMULB 1 D6 D7 D6\nWRT Y0.2\n")
    engines = pair(binary_of(text))
    assert engines[1]._current.callbacks == []
    driver = Driver(engines, random.Random(11), bytes_of(Area.X, 1),
                    [Address(Area.R, 10), Address(Area.R, 11), *bytes_of(Area.D, 8)], [])
    driver.run(2000, rate=0.5, longest=5)


def test_the_scan_process_scans_natively_as_the_python_scan_here() -> None:
    from ladderworks.core.plc.session import PlcRun
    from tests.core.plc.test_scan_process import PRESET, PROGRAM, in_process, same, wait_until

    def make(realtime: bool, backend: str) -> PlcRun:
        run = PlcRun(realtime=realtime, period_ms=1, scan_process=realtime, backend=backend)
        assert run.load_program(parse(PROGRAM).program).binary is not None
        run.set_timer_preset(1, PRESET)
        return run

    live = make(True, "native")
    assert live.engine is not None and live.engine.backend_used == "native"
    try:
        assert live.start()
        assert in_process(live), live.process_error
        assert wait_until(lambda: live.status().scan_count >= 200)
        live.stop()
        reference = make(False, "python")
        reference.start()
        reference.run_scans(live.engine.scan_count)
        reference.stop()
        same(live, reference)
    finally:
        live.close()


def test_xmovb_reads_and_writes_its_table_as_the_python_scan_does() -> None:
    text = "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nXMOVB 2 6 D100 D20 D30\nWRT Y0.0\n" \
           "RD X0.3\nRD.STK X0.4\nRD.STK X0.5\nXMOVB 1 D40 D9990 D22 D30\nWRT Y0.1\n"
    engines = pair(binary_of(text))
    assert engines[1]._current.callbacks == []
    indices = [Address(Area.X, 0), Address(Area.D, 30), Address(Area.D, 40)]  # small values
    changed = [Address(Area.D, b) for b in (20, 21, 22, 31, 41, 100, 101, 104, 9995)]
    driver = Driver(engines, random.Random(12), indices, changed, [])
    for engine in engines:
        engine.memory.write(Address(Area.D, 40), 20, 2)
    driver.run(2000, rate=0.6, longest=4)


def test_fast_and_monitored_variants_share_their_state_words() -> None:
    binary = binary_of("%@3\nRD X0.0\nTMRB 1 40\nWRT Y0.0\nRD X0.0\nDIFU 3\nWRT Y0.1\n%\n")
    python, native = pair(binary)
    fast = native._current
    native.monitored = True
    native.scan()
    python.monitored = True
    python.scan()
    assert native._current is not fast and native._current._words is fast._words
    for step in range(60):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = (step // 5) % 2
            if step % 3 == 0:
                engine.monitored = not engine.monitored
            if step == 30:
                engine.disable(5)  # a variant of another layout: states through the dicts
            engine.scan()
        assert native.call_states() == python._states
        assert native._ctx.edges == python._ctx.edges
    assert python.memory.areas == native.memory.areas


@pytest.mark.parametrize("header", ["%@3\n", ""], ids=["fanuc", "seed"])
def test_counters_count_as_the_python_scan_counts(header: str) -> None:
    text = ("RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nCTR 2\nWRT Y0.0\n"
            "RD X0.4\nRD.STK X0.1\nRD.STK X0.5\nRD.STK X0.3\nCTRC D10 D20\nWRT Y0.1\n"
            "RD X0.6\nRD.STK X0.7\nRD.STK X0.2\nRD.STK X0.3\nCTRB 3 5\nWRT Y0.2\n")
    engines = pair(binary_of(header + text + ("%\n" if header else "")))
    assert engines[1]._current.callbacks == []
    presets = [Address(Area.C, 4), Address(Area.C, 5), Address(Area.D, 10), Address(Area.D, 11)]
    driver = Driver(engines, random.Random(header + "counters"), bytes_of(Area.X, 1), presets,
                    [])
    for engine in engines:
        engine.memory.write(Address(Area.C, 4), 3, 2)
        engine.memory.write(Address(Area.D, 10), 4, 2)
    driver.run(3000, rate=0.6, longest=3)


def test_an_unknown_sub_is_the_cnc_stub_natively() -> None:
    engines = pair(binary_of("RD X0.0\nSUB.250 R0 7\nWRT Y0.0\nRD X0.1\nSUB.251\nWRT Y0.1\n"))
    assert engines[1]._current.callbacks == []
    driver = Driver(engines, random.Random(4), bytes_of(Area.X, 1), [], [])
    driver.run(200, rate=0.5, longest=3)


def test_a_skip_writes_back_only_the_timers_it_moved_on() -> None:
    """The skipper moves the native timers on in their state words (native/helpers.py), not
    in the dicts: the timers then close at the Python scan's time, and the dicts have them
    when read."""
    text = "%@3\nRD X0.0\nTMRB 1 4000\nWRT Y0.0\nRD X0.0\nTMRB 2 9000\nWRT Y0.1\n" \
           "RD X0.1\nDIFU 3\nWRT Y0.2\n%\n"
    python, native = pair(binary_of(text))
    for until, inputs in ((1000, 1), (5000, 3), (7000, 1), (12000, 0), (13000, 1)):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = inputs
            engine.advance(until)
        assert not native._current.stale  # the moved-on timers only: nothing left to read
        assert native.call_states() == python._states
        assert native._ctx.edges == python._ctx.edges
        assert native.memory.areas == python.memory.areas, until
    assert native.skipped > 1000  # the timers ran on through skips


def test_a_native_skip_ends_inside_a_cycle_with_its_state_put_back() -> None:
    """A bit that flips every scan makes a cycle of two; a skip up to a clock's edge that
    leaves one scan of a cycle puts back the state of the cycle's first scan (memory, the
    DIFU memory and the timer's block) rather than running that scan: the scans after it
    and the states are the Python scan's, run every scan."""
    text = "%@3\nRD.NOT R0.0\nWRT R0.0\nRD R0.0\nDIFU 1\nWRT R0.3\nRD X0.0\n" \
           "TMRB 1 4000\nWRT Y0.0\nRD R9091.5\nAND R0.0\nWRT R0.1\n%\n"
    python, native = pair(binary_of(text))
    odd = 0
    for until in range(200, 9000, 104):
        for engine in (python, native):
            engine.memory.areas[Area.X][0] = until // 1000 % 2
        skipped = native.skipped
        for engine in (python, native):
            engine.advance(until)
        odd += (native.skipped - skipped) % 2
        assert native.memory.areas == python.memory.areas, until
        assert native.call_states() == python._states
        assert native._ctx.edges == python._ctx.edges
    assert odd > 20  # skips of an odd number of scans: ended inside a cycle of two
    assert native.skipped > 600


def test_the_skippers_native_comparison_finds_time_values_only() -> None:
    """`helpers.grown` gives the blocks whose elapsed time or last scan grew; anything else
    differing (an edge memory, the flags, the wake, CTRB's value, an elapsed time not set) is
    no repeat. `helpers.move` moves them on and lists each block once."""
    from ladderworks.core.plc.native import helpers, layout, state_block

    def state(edges: list[int], blocks: list[tuple[int, int, int, int]]) -> bytes:
        words = list(edges)
        for flags, elapsed, at, wake in blocks:
            words += [flags, 0, elapsed, 0, at, 0, wake, 0]
        return b"".join(w.to_bytes(4, "little", signed=True) for w in words)

    timing = state_block.HAS_ELAPSED | state_block.ELAPSED_SET | state_block.HAS_AT
    counter = state_block.HAS_VALUE | state_block.HAS_ELAPSED | state_block.ELAPSED_SET
    before = state([3, 2], [(timing, 40, 800, 5000), (counter, 7, 0, 0), (0, 0, 0, 0)])
    later = state([3, 2], [(timing, 56, 816, 5000), (counter, 7, 0, 0), (0, 0, 0, 0)])
    assert helpers.grown(before, later, 2, 3) == [(0, 16, 16)]
    assert helpers.grown(before, before, 2, 3) == []
    for changed in (state([3, 3], [(timing, 56, 816, 5000), (counter, 7, 0, 0), (0, 0, 0, 0)]),
                    state([3, 2], [(timing | 32, 56, 816, 5000), (counter, 7, 0, 0),
                                   (0, 0, 0, 0)]),
                    state([3, 2], [(timing, 56, 816, 5016), (counter, 7, 0, 0), (0, 0, 0, 0)]),
                    state([3, 2], [(timing, 40, 800, 5000), (counter, 8, 0, 0), (0, 0, 0, 0)]),
                    state([3, 2], [(timing, 40, 800, 5000), (counter, 7, 0, 0), (0, 1, 0, 0)])):
        assert helpers.grown(before, changed, 2, 3) is None
    first, marks, dirty = 30, 60, 70
    words = (ctypes.c_int32 * 80)()
    helpers.move(words, [(0, 16, 16), (2, 0, 8)], 10, first, marks, dirty)
    helpers.move(words, [(0, 16, 16)], 1, first, marks, dirty)
    assert state_block._get64(words, first + state_block.ELAPSED) == 176
    assert state_block._get64(words, first + state_block.AT) == 176
    assert state_block._get64(words, first + 16 + state_block.AT) == 80
    assert words[layout.DIRTY] == 2 and list(words[dirty:dirty + 2]) == [0, 2]
    assert (words[marks], words[marks + 1], words[marks + 2]) == (1, 0, 1)
