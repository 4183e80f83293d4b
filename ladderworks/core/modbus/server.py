"""ModbusServer: pymodbus's Modbus/TCP server over a PlcBridge, on its own asyncio thread.

pymodbus does the protocol (framing, function codes, exception answers, one connection per
client: a malformed frame costs that connection only); its datastore calls are answered by
`PlcDatastore` from the bridge. Any unit id is answered with the same PLC. The server listens
on loopback unless told otherwise (`DEFAULT_HOST`).
"""

from __future__ import annotations

import asyncio
import contextlib
import ipaddress
import logging
import threading
import time
from collections.abc import Sequence

from pymodbus.constants import ExcCodes
from pymodbus.datastore import ModbusServerContext
from pymodbus.pdu import ModbusPDU
from pymodbus.server import ModbusTcpServer
from pymodbus.server.requesthandler import ServerRequestHandler

from ladderworks.core.modbus.bridge import ModbusError, PlcBridge
from ladderworks.core.modbus.maps import TABLE_OF_FUNCTION

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 5020
STOP_SECONDS = 2.0
# pymodbus logs every frame it cannot decode, with a dump of the last ones: a client's
# garbage is that client's business (its connection is closed), not the console's
logging.getLogger("pymodbus").setLevel(logging.CRITICAL)


def is_loopback(host: str) -> bool:
    """True when `host` is a loopback address or `localhost` (nothing outside can connect)."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def exposure_warning(host: str) -> str | None:
    """What to tell the user when `host` lets other computers connect (None on loopback)."""
    if is_loopback(host):
        return None
    return (f"listening on {host}: other computers on the network can read and write"
            " this PLC")


def parse_endpoint(text: str) -> tuple[str, int]:
    """`HOST:PORT` (or `PORT`, or `[v6]:PORT`) as (host, port); ValueError when malformed."""
    host, sep, port_text = text.rpartition(":")
    if not sep:
        host, port_text = DEFAULT_HOST, text
    host = host.strip("[]") or DEFAULT_HOST
    try:
        port = int(port_text)
    except ValueError:
        raise ValueError(f"'{text}': expected HOST:PORT, e.g. 127.0.0.1:5020") from None
    if not 0 <= port <= 65535:
        raise ValueError(f"'{text}': the port must be 0 to 65535")
    return host, port


class PlcDatastore(ModbusServerContext):
    """The datastore pymodbus's request handlers call: the bridge, exceptions as codes."""

    def __init__(self, bridge: PlcBridge) -> None:
        # not ModbusServerContext.__init__: it builds pymodbus's own memory; this one answers
        # from the PLC (the server takes a context with no simdevices as it is)
        self.bridge = bridge
        self.old_simulator = True
        self.simdevices = []

    def device_ids(self) -> list[int]:
        """Every unit id is this PLC."""
        return [0]

    async def async_getValues(self, device_id: int, func_code: int, address: int,
                              count: int = 1) -> list[int] | list[bool] | ExcCodes:
        """Read coils, discrete inputs or registers."""
        table = TABLE_OF_FUNCTION.get(func_code)
        if table is None:
            return ExcCodes.ILLEGAL_FUNCTION
        try:
            if table.bits:
                return self.bridge.read_bits(table, address, count)
            return self.bridge.read_registers(table, address, count)
        except ModbusError as error:
            return ExcCodes(error.code)

    async def async_setValues(self, device_id: int, func_code: int, address: int,
                              values: Sequence[int] | Sequence[bool]) -> ExcCodes | None:
        """Write coils or holding registers."""
        table = TABLE_OF_FUNCTION.get(func_code)
        if table is None or not table.writable:
            return ExcCodes.ILLEGAL_FUNCTION
        try:
            if table.bits:
                self.bridge.write_bits(table, address, [bool(v) for v in values])
            else:
                self.bridge.write_registers(table, address, [int(v) for v in values])
        except ModbusError as error:
            return ExcCodes(error.code)
        return None


def header_ok(data: bytes) -> bool:
    """False when the buffer starts with what is no Modbus/TCP header (MBAP): protocol id
    not 0, or a length outside 2..254 (unit id and PDU)."""
    if len(data) < 6:
        return True  # not known yet
    return data[2:4] == b"\0\0" and 2 <= int.from_bytes(data[4:6], "big") <= 254


class _Connection(ServerRequestHandler):
    """One client's connection: a frame that is not Modbus/TCP closes it (and it only)."""

    def callback_data(self, data: bytes, addr: tuple | None = None) -> int:
        """Hand a well-formed frame on to pymodbus; close on a malformed one."""
        if not header_ok(data):
            self.close()
            return len(data)
        return int(super().callback_data(data, addr))


class _TcpServer(ModbusTcpServer):
    """pymodbus's TCP server with `_Connection` for each client."""

    def callback_new_connection(self) -> _Connection:
        """Handle a new client."""
        return _Connection(self, self.trace_packet, self.trace_pdu, self.trace_connect)


class ModbusServer:
    """A Modbus/TCP server for one PLC, run by `start()` on a thread until `stop()`."""

    def __init__(self, bridge: PlcBridge, host: str = DEFAULT_HOST,
                 port: int = DEFAULT_PORT) -> None:
        self.bridge = bridge
        self.host = host
        self.port = port  # 0: a free port, known once started
        self.requests = 0  # requests answered since the start
        self._thread: threading.Thread | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._server: ModbusTcpServer | None = None
        self._done: asyncio.Event | None = None
        self._error: BaseException | None = None
        self._rate = (time.monotonic(), 0)

    @property
    def running(self) -> bool:
        """True while the server thread listens."""
        return self._thread is not None and self._thread.is_alive()

    @property
    def clients(self) -> int:
        """The connections open now."""
        server = self._server
        return len(server.active_connections) if server is not None else 0

    @property
    def loopback(self) -> bool:
        """True when only this computer can connect."""
        return is_loopback(self.host)

    def start(self, timeout: float = 5.0) -> None:
        """Listen (OSError when the address cannot be bound); returns once listening."""
        if self.running:
            return
        ready = threading.Event()
        self._error = None
        self.requests = 0
        self._rate = (time.monotonic(), 0)
        self._thread = threading.Thread(target=self._run, args=(ready,), name="modbus-server",
                                        daemon=True)
        self._thread.start()
        if not ready.wait(timeout):
            self.stop()
            raise OSError(f"the Modbus server did not start on {self.host}:{self.port}")
        if self._error is not None:
            self._thread.join(STOP_SECONDS)
            self._thread = None
            error = self._error
            raise error if isinstance(error, OSError) else OSError(str(error))

    def stop(self) -> None:
        """Close every connection and the listener; returns within STOP_SECONDS."""
        loop, done, thread = self._loop, self._done, self._thread
        if loop is not None and done is not None and not loop.is_closed():
            with contextlib.suppress(RuntimeError):  # the loop has just closed
                loop.call_soon_threadsafe(done.set)
        if thread is not None:
            thread.join(STOP_SECONDS)
        self._thread = None

    def requests_per_second(self) -> float:
        """Requests a second since the previous call (or the start)."""
        now, requests = time.monotonic(), self.requests
        then, before = self._rate
        self._rate = (now, requests)
        return (requests - before) / (now - then) if now > then else 0.0

    # -- the server thread -----------------------------------------------------------------

    def _run(self, ready: threading.Event) -> None:
        loop = asyncio.new_event_loop()
        self._loop = loop
        try:
            loop.run_until_complete(self._serve(ready))
        except BaseException as error:  # handed to start()
            self._error = error
        finally:
            ready.set()
            loop.close()
            self._loop = None

    async def _serve(self, ready: threading.Event) -> None:
        self._done = asyncio.Event()
        server = _TcpServer(PlcDatastore(self.bridge), address=(self.host, self.port),
                            trace_pdu=self._counted)
        self._server = server
        try:
            if not await server.listen():
                raise OSError(f"cannot listen on {self.host}:{self.port}"
                              " (the address is in use or not this computer's)")
            sockets = getattr(server.transport, "sockets", None) or ()
            if sockets:
                self.port = sockets[0].getsockname()[1]
            ready.set()
            await self._done.wait()
        finally:
            for _ in range(3):  # the accepts under way end first (asyncio 3.11 would leak them)
                await asyncio.sleep(0)
            await server.shutdown()
            self._server = None
            # the closed connections' sockets are let go on the loop's next turns; a client
            # accepted while closing (its task still running) is closed too
            for _ in range(3):
                await asyncio.sleep(0)
                tasks = [t for t in asyncio.all_tasks() if t is not asyncio.current_task()]
                if tasks:
                    await asyncio.wait(tasks, timeout=0.2)
                for connection in list(server.active_connections.values()):
                    connection.close()
            tasks = [t for t in asyncio.all_tasks() if t is not asyncio.current_task()]
            for task in tasks:
                task.cancel()
            await asyncio.gather(*tasks, return_exceptions=True)

    def _counted(self, sending: bool, pdu: ModbusPDU) -> ModbusPDU:
        if not sending:
            self.requests += 1
        return pdu
