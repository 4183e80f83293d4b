"""Fuzzing every CLI command: generated, mutated and huge inputs end in exit 0 or 1, never a
traceback; every crasher found is kept in tests/data/fuzz/ and run again here."""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.cli import main
from ladderworks.core.instructions import ALL, PMC_FUNCTIONS
from ladderworks.paths import EXAMPLES
from tests.hypothesis_profiles import examples

CRASHERS = Path(__file__).resolve().parent.parent / "data" / "fuzz"
COMMANDS = ("check", "format", "ladder", "mnemonic", "compile", "run", "xref")

_NAMES = [spec.text_name for spec in ALL] + ["SUB", "FOO", "RD.XX", "SP", "SPE", "CALL"]
_SUBS = [str(spec.sub) for spec in PMC_FUNCTIONS if spec.sub] + ["1", "2", "64", "219", "999"]
_BREAKS = ["\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029", "\r", "\r\n"]
_WORDS = st.one_of(
    st.sampled_from(_NAMES),
    st.from_regex(r"[XYFGRADTCKEPL][0-9]{1,5}(\.[0-9]{1,2})?", fullmatch=True),
    st.integers(-10**12, 10**12).map(str),
    st.integers(200, 5000).map(lambda n: "9" * n),  # numbers of thousands of digits
    st.sampled_from(["SUB", "//", ";", ",", "%", "%@3", "%@1", "%@A", "%@E", "%@2-C", "%@4",
                     "N00012:", "0011", "İŞ", "P5", "L3", "\t", *_BREAKS]),
)
_LINE = st.one_of(
    st.lists(_WORDS, max_size=6).map(" ".join),
    st.tuples(st.just("SUB"), st.sampled_from(_SUBS)).map(" ".join),
)
_TEXT = st.lists(_LINE, max_size=40).map("\n".join)
_EXAMPLES = [p.read_bytes() for p in sorted(EXAMPLES.glob("*.LAD"))]


def run_cli(command: str, path: Path, tmp: Path) -> tuple[int, str]:
    """Run `ladderworks-cli COMMAND FILE` in-process; (exit code, stdout + stderr)."""
    argv = [command, str(path)]
    if command == "compile":
        argv += ["-o", str(tmp / "out.bin")]
    elif command == "run":
        argv += ["--scans", "2"]
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse usage errors
            code = int(exc.code or 0)
    return code, out.getvalue() + err.getvalue()


def assert_clean(command: str, data: bytes, tmp: Path) -> None:
    """The command ends with 0 or 1 and prints no traceback for `data`."""
    path = tmp / "input.LAD"
    path.write_bytes(data)
    code, output = run_cli(command, path, tmp)
    assert code in (0, 1), (command, code, output[-2000:])
    assert "Traceback" not in output


def _mutate(data: bytes, draw: st.DrawFn) -> bytes:
    chunk = bytearray(data)
    for _ in range(draw(st.integers(1, 12))):
        position = draw(st.integers(0, len(chunk)))
        action = draw(st.sampled_from(["insert", "delete", "replace", "duplicate"]))
        if action == "insert":
            chunk[position:position] = draw(st.sampled_from(
                [b"\x00", b"\xff", b"\x0c", b"\xc2\x85", b"\xe2\x80\xa8", b"9" * 5000,
                 b"\nSUB 71\nP1\n", b"\nSUB 72\n", b"\nSUB 65\nP9\n", b"\nJMPE\n",
                 b"\nSET R1.1\n", b"\n%@3\n", b"\n%\n", "İ".encode()]))
        elif action == "duplicate" and chunk:
            end = min(len(chunk), position + draw(st.integers(1, 400)))
            chunk[position:position] = chunk[position:end] * draw(st.integers(1, 5))
        elif chunk and position < len(chunk):
            if action == "delete":
                del chunk[position:position + draw(st.integers(1, 20))]
            else:
                chunk[position] = draw(st.integers(0, 255))
    return bytes(chunk)


_SETTINGS = settings(max_examples=examples(200), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture, HealthCheck.data_too_large])


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(text=_TEXT)
def test_generated_texts(command: str, text: str, tmp_path: Path) -> None:
    assert_clean(command, ("%@3\n" + text + "\n%\n").encode("utf-8", "surrogatepass"),
                 tmp_path)


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(data=st.data())
def test_mutated_examples(command: str, data: st.DataObject, tmp_path: Path) -> None:
    source = data.draw(st.sampled_from(_EXAMPLES))
    assert_clean(command, _mutate(source, data.draw), tmp_path)


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(data=st.binary(max_size=2000))
def test_random_bytes(command: str, data: bytes, tmp_path: Path) -> None:
    assert_clean(command, data, tmp_path)


def _nested(depth: int, begin: str, end: str) -> str:
    body = "RD R0.0\nWRT R1.0\n"
    for _ in range(depth):
        body = f"RD R0.1\n{begin}\n{body}{end}\n"
    return body


HUGE = {
    "nested-jmp": _nested(150, "SUB 10\n0", "SUB 30"),
    "nested-com": _nested(150, "SUB 9\n0", "SUB 29"),
    "long-network": "RD R0.0\n" + "AND R0.1\n" * 70_000 + "WRT R1.0\n",
    "long-or": "RD R0.0\n" + "OR R0.1\n" * 20_000 + "WRT R1.0\n",
    "deep-stack": "RD R0.0\n" + "RD.STK R0.1\n" * 9 + "AND.STK\n" * 9 + "WRT R1.0\n",
    "many-networks": "RD R0.0\nWRT R1.0\n" * 40_000,
    "big-numbers": "RD R0.0\nSUB 3\n" + "9" * 5000 + "\nWRT R1.0\n",
    "codb-256": "RD R0.0\nRD.STK R0.1\nSUB 27\n2\n256\nR10\nR12\n" + "7\n" * 256 + "WRT R1.0\n",
}


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("name", sorted(HUGE))
def test_huge_inputs(command: str, name: str, tmp_path: Path) -> None:
    assert_clean(command, ("%@3\n" + HUGE[name] + "%\n").encode(), tmp_path)


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("crasher", sorted(CRASHERS.glob("*")), ids=lambda p: p.name)
def test_kept_crashers(command: str, crasher: Path, tmp_path: Path) -> None:
    assert_clean(command, crasher.read_bytes(), tmp_path)


def test_lines_end_only_at_cr_and_lf(tmp_path: Path) -> None:
    code, output = run_cli("check", CRASHERS / "line-breaks-in-comments.LAD", tmp_path)
    assert code == 1
    assert output.strip().splitlines() == [f"{CRASHERS / 'line-breaks-in-comments.LAD'}:8:8: "
                                           "extra-operand WRT takes no operand, found 'extra'"]


@pytest.mark.parametrize("name", ["not-a-program.png", "not-a-program.svg"])
def test_a_file_that_is_not_a_program_says_so(name: str, tmp_path: Path) -> None:
    code, output = run_cli("check", CRASHERS / name, tmp_path)
    lines = output.strip().splitlines()
    assert code == 1 and 1 <= len(lines) <= 3
    assert "not-a-program" in lines[0]
