"""The CLI's table of which module adds each command, and the light `check` start (the
compiler's checks, without lark or the scan engine)."""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

import pytest

from ladderworks.cli import COMMANDS, build_parser, main
from ladderworks.paths import CHECKOUT


def _commands(parser: argparse.ArgumentParser) -> set[str]:
    """The subcommand names a parser knows."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return set(action.choices)
    return set()


def test_the_table_names_every_command_of_every_module() -> None:
    assert _commands(build_parser()) == set(COMMANDS)


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_the_module_of_a_command_adds_it(command: str) -> None:
    assert command in _commands(build_parser(command))


def test_version_is_printed_on_stdout(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    out = capsys.readouterr()
    assert out.out.startswith("ladderworks-cli ") and out.err == ""


def test_an_unknown_command_lists_them_all(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["nosuch"])
    err = capsys.readouterr().err
    assert "invalid choice: 'nosuch'" in err and "'signals'" in err and "'check'" in err


CHECK_SCRIPT = """
import sys
from ladderworks.cli import main
code = main(["check", sys.argv[1]])
heavy = ("lark", "ladderworks.core.plc.engine", "importlib.metadata",
         "ladderworks.core.plc.functions", "ladderworks.core.compiler.binary",
         "ladderworks.core.il.printer")
print(code, " ".join(m for m in heavy if m in sys.modules))
"""


def test_check_loads_neither_lark_nor_the_plc(tmp_path: Path) -> None:
    program = tmp_path / "a.LAD"  # a functional instruction: its implementation is asked for
    program.write_text("%@3\nRD X0.1\nTMR 1\nWRT Y0.1\n%\n")
    done = subprocess.run([sys.executable, "-c", CHECK_SCRIPT, str(program)], cwd=CHECKOUT,
                          capture_output=True, text=True, timeout=120, check=True)
    assert done.stdout.strip() == "0"  # passed, and none of the heavy modules was loaded


def test_the_program_exits_with_main_s_code_and_all_its_output(tmp_path: Path) -> None:
    bad = tmp_path / "bad.LAD"
    bad.write_text("%@3\n" + "RD X1.0\nWRT X2.0\n" * 500 + "%\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "ladderworks.cli", "check", str(bad)],
                          cwd=CHECKOUT, capture_output=True, text=True, check=False)
    lines = done.stdout.splitlines()
    assert done.returncode == 1 and done.stderr == ""
    assert len(lines) == 500 and all("write-input" in line for line in lines)  # all flushed
    good = tmp_path / "good.LAD"
    good.write_text("%@3\nRD X1.0\nWRT Y2.0\n%\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "ladderworks.cli", "check", str(good)],
                          cwd=CHECKOUT, capture_output=True, text=True, check=False)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")


def test_a_reader_that_stops_early_gets_no_traceback(tmp_path: Path) -> None:
    bad = tmp_path / "bad.LAD"
    bad.write_text("%@3\n" + "RD X1.0\nWRT X2.0\n" * 20000 + "%\n", encoding="utf-8")
    with subprocess.Popen([sys.executable, "-m", "ladderworks.cli", "check", str(bad)],
                          cwd=CHECKOUT, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as cli:
        assert cli.stdout is not None and cli.stderr is not None
        first = cli.stdout.readline()
        cli.stdout.close()  # as `| head -1` does
        errors = cli.stderr.read()
        cli.wait(timeout=60)
    assert b"write-input" in first
    assert b"Traceback" not in errors and b"BrokenPipe" not in errors
