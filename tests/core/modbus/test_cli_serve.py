"""`ladderworks-cli serve`: a subprocess served to a real client and stopped by SIGTERM."""

from __future__ import annotations

import re
import signal
import socket
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from pymodbus.client import ModbusTcpClient

from ladderworks.cli import build_parser, main
from ladderworks.paths import CHECKOUT
from tests.core.modbus.conftest import SPINDLE, STOP, TIMEOUT
from tests.core.modbus.test_server import wait_for

SERVING = re.compile(r"on 127\.0\.0\.1:(\d+), Modbus/TCP")


@contextmanager
def served(program: Path, *extra: str
           ) -> Iterator[tuple[subprocess.Popen[str], str, ModbusTcpClient]]:
    """`ladderworks-cli serve PROGRAM` on a free loopback port: the process, the line it printed
    first and a client connected to it; the process is killed at the end if it still runs."""
    with subprocess.Popen([sys.executable, "-m", "ladderworks.cli", "serve", str(program),
                           "--modbus", "127.0.0.1:0", *extra], cwd=CHECKOUT, text=True,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE) as process:
        try:
            assert process.stdout is not None
            first = process.stdout.readline()
            found = SERVING.search(first)
            assert found, first
            client = ModbusTcpClient("127.0.0.1", port=int(found.group(1)), timeout=TIMEOUT)
            assert client.connect()
            yield process, first, client
        finally:
            if process.poll() is None:
                process.kill()
                process.wait()


def test_serve_answers_until_sigterm_then_exits_0() -> None:
    with served(SPINDLE) as (process, _first, client):
        assert not client.write_coils(17, [True, False, True]).isError()
        assert wait_for(lambda: client.read_holding_registers(3030, count=1).registers
                        == [60])
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=STOP) == 0  # stops on SIGTERM, exit 0 (no wall-clock claim)
        client.close()
        out, err = process.communicate()
    assert "stopped" in out and err == ""


def test_serve_listens_on_loopback_unless_told() -> None:
    args = build_parser("serve").parse_args(["serve", "program.LAD"])
    assert args.modbus == "127.0.0.1:5020"


def test_a_bad_map_line_is_reported_at_its_line(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    own = tmp_path / "hmi.csv"
    own.write_text("coils,0,8,X2.0,rw\nholding,0,4,D0,rw\nholding,10,4,Z9,rw\n",
                   encoding="utf-8")
    assert main(["serve", str(SPINDLE), "--map", str(own), "--modbus", "127.0.0.1:0"]) == 2
    err = capsys.readouterr().err
    assert err.splitlines() == [
        f"{own}:3:1: unknown-area 'Z9': unknown area 'Z' (use X, Y, F, G, R, A, D, T, C or K)"]


@pytest.mark.parametrize(("option", "text"), [
    (["--modbus", "nowhere"], "expected HOST:PORT"),
    (["--modbus", "127.0.0.1:99999"], "the port must be 0 to 65535"),
    (["--scan-period", "0"], "at least 1 ms"),
])
def test_bad_options_are_refused(option: list[str], text: str,
                                 capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["serve", str(SPINDLE), *option]) == 2
    assert text in capsys.readouterr().err


def test_serve_takes_a_delta_program_s_period_and_map() -> None:
    program = CHECKOUT / "resources" / "examples" / "delta" / "cmp_d10.txt"
    with served(program) as (process, first, client):
        assert "(delta, 10 ms scans)" in first and "map delta" in first
        assert not client.write_register(0x1000 + 10, 30).isError()  # D10
        assert not client.write_coil(0x0400, True).isError()  # X0
        assert wait_for(lambda: client.read_coils(0x0502, count=1).bits[0])  # Y2
        client.close()
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=STOP) == 0


def test_a_port_in_use_is_said_and_exit_2(capsys: pytest.CaptureFixture[str]) -> None:
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        assert main(["serve", str(SPINDLE), "--modbus", f"127.0.0.1:{port}"]) == 2
    assert f"Modbus server on 127.0.0.1:{port}: cannot listen" in capsys.readouterr().err
