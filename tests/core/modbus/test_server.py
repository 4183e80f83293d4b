"""The Modbus/TCP server with pymodbus's own client, on a free loopback port."""

from __future__ import annotations

import contextlib
import socket
import threading
import time

from pymodbus.client import ModbusTcpClient
from pymodbus.exceptions import ModbusException

from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.maps import PMC_MAP
from ladderworks.core.modbus.server import (
    DEFAULT_HOST,
    DEFAULT_PORT,
    ModbusServer,
    exposure_warning,
    header_ok,
    is_loopback,
    parse_endpoint,
)
from ladderworks.core.plc.session import PlcRun
from tests.core.modbus.conftest import TIMEOUT, client_of

G30 = 3030


def wait_for(check: object, seconds: float = TIMEOUT) -> bool:
    """Poll `check()` until it is true or `seconds` pass."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if check():  # type: ignore[operator]
            return True
        time.sleep(0.01)
    return False


def test_the_spindle_override_driven_over_modbus(client: ModbusTcpClient) -> None:
    assert not client.write_coils(17, [True, False, True]).isError()  # X2.1, X2.3 on
    assert wait_for(lambda: client.read_holding_registers(G30, count=1).registers == [60])
    assert client.read_coils(17, count=3).bits[:3] == [True, False, True]
    assert not client.write_coil(17, False).isError()  # X2.3 alone: position 2 = 40 %
    assert wait_for(lambda: client.read_holding_registers(G30, count=1).registers == [40])


def test_outside_the_map_answers_exception_02(client: ModbusTcpClient) -> None:
    for answer in (client.read_holding_registers(900, count=1),
                   client.read_coils(1024, count=1),
                   client.read_input_registers(0, count=1),
                   client.write_register(40000, 1)):
        assert answer.isError() and answer.exception_code == 2


def test_a_write_to_read_only_data_answers_02_and_a_too_wide_value_03(
        client: ModbusTcpClient, live_plc: PlcRun) -> None:
    answer = client.write_register(G30, 99)
    assert answer.isError() and answer.exception_code == 2
    answer = client.write_register(20000, 300)  # D0 is one byte
    assert answer.isError() and answer.exception_code == 3
    assert not client.write_registers(20000, [1, 2]).isError()
    assert client.read_holding_registers(20000, count=2).registers == [1, 2]


def test_four_clients_poll_while_the_plc_runs(server: ModbusServer, live_plc: PlcRun) -> None:
    clients = [client_of(server) for _ in range(4)]
    assert wait_for(lambda: server.clients == 4)
    problems: list[str] = []
    seen: list[set[int]] = [set() for _ in clients]

    def poll(number: int, client: ModbusTcpClient) -> None:
        for turn in range(60):
            if number == 0:  # one client turns the switch, the others watch
                client.write_coils(17, [bool(turn & 1), False, bool(turn & 2)])
            answer = client.read_holding_registers(G30, count=1)
            if answer.isError():
                problems.append(str(answer))
                return
            seen[number].add(answer.registers[0])

    threads = [threading.Thread(target=poll, args=(n, c)) for n, c in enumerate(clients)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(30)
    assert problems == [] and not any(t.is_alive() for t in threads)
    valid = {10, 20, 40, 60, 80, 100, 125, 150}  # G30 of each switch position
    assert all(s <= valid for s in seen) and len(set().union(*seen)) > 1
    assert server.requests >= 4 * 60 and live_plc.status().scan_count > 0
    for client in clients:
        client.close()
    assert wait_for(lambda: server.clients == 0)


def test_a_malformed_frame_closes_that_connection_only(
        server: ModbusServer, client: ModbusTcpClient) -> None:
    with socket.create_connection(("127.0.0.1", server.port), timeout=TIMEOUT) as raw:
        raw.sendall(b"GET / HTTP/1.1\r\n\r\n")
        assert raw.recv(100) == b""  # closed by the server
    assert not client.read_holding_registers(G30, count=1).isError()


def test_stop_closes_the_clients_and_frees_the_port(live_plc: PlcRun) -> None:
    served = ModbusServer(PlcBridge(live_plc, PMC_MAP), "127.0.0.1", 0)
    served.start()
    client = client_of(served)
    assert wait_for(lambda: served.clients == 1)
    served.stop()
    assert not served.running and served.clients == 0
    with contextlib.suppress(ModbusException):  # or the connection is closed under it
        assert client.read_holding_registers(G30, count=1).isError()
    client.close()
    again = ModbusServer(PlcBridge(live_plc, PMC_MAP), "127.0.0.1", served.port)
    again.start()  # the same port can be listened on again
    again.stop()


def test_a_port_in_use_is_an_os_error(server: ModbusServer, live_plc: PlcRun) -> None:
    other = ModbusServer(PlcBridge(live_plc, PMC_MAP), "127.0.0.1", server.port)
    try:
        other.start()
    except OSError:
        pass
    else:
        other.stop()
        raise AssertionError("a second server listened on a port in use")
    assert not other.running


def test_the_default_address_is_loopback() -> None:
    assert (DEFAULT_HOST, DEFAULT_PORT) == ("127.0.0.1", 5020)
    served = ModbusServer(PlcBridge(PlcRun(), PMC_MAP))
    assert (served.host, served.port) == ("127.0.0.1", 5020) and served.loopback
    assert exposure_warning(served.host) is None


def test_other_interfaces_are_named_loudly() -> None:
    assert is_loopback("localhost") and is_loopback("::1") and is_loopback("127.0.0.2")
    assert not is_loopback("0.0.0.0") and not is_loopback("192.168.1.10")
    warning = exposure_warning("0.0.0.0")
    assert warning is not None and "0.0.0.0" in warning and "other computers" in warning


def test_endpoints() -> None:
    assert parse_endpoint("0.0.0.0:502") == ("0.0.0.0", 502)
    assert parse_endpoint("5021") == ("127.0.0.1", 5021)
    assert parse_endpoint("[::1]:5020") == ("::1", 5020)
    for bad in ("host:port", "1.2.3.4:70000"):
        try:
            parse_endpoint(bad)
        except ValueError:
            continue
        raise AssertionError(bad)


def test_mbap_headers() -> None:
    assert header_ok(b"\x00\x01\x00\x00\x00\x06\x01\x03\x0b\xd6\x00\x01")
    assert header_ok(b"\x00\x01\x00")  # not known yet
    assert not header_ok(b"\x00\x01\x00\x05\x00\x06")  # protocol id 5
    assert not header_ok(b"\x00\x01\x00\x00\x01\x00")  # 256 bytes: longer than a frame
