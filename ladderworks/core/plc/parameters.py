"""PMC parameters (T, C, K, D values set by the user), kept in a text file beside the program.

`PROGRAM.LAD` keeps its parameters in `PROGRAM.LAD.prm`: one `ADDRESS[:WIDTH] = VALUE` line per
non-default value, sorted by area (T, C, K, D) and address; `#` or `;` start a comment. Lines
that cannot be read are reported with their line number and kept, as read, at the end of the
file when it is written again (docs/file-format.md, "PMC parameter file").
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core.address import Address, AddressError, Area, parse_address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.textform import split_lines
from ladderworks.core.plc.functions.counters import COUNTER_BYTES
from ladderworks.core.plc.memory import Memory
from ladderworks.core.plc.timer_table import SEED, timer_layout

SUFFIX = ".prm"
PARAMETER_AREAS: tuple[Area, ...] = (Area.T, Area.C, Area.K, Area.D)
WIDTHS = (1, 2, 4)
HEADER = "# LadderWorks PMC parameters: ADDRESS[:BYTES] = VALUE (T, C, K, D); # or ; comment"
KEPT_HEADER = "# lines not understood when read (kept as they were):"

_LINE_RE = re.compile(r"^\s*([A-Za-z]\d+(?:\.\d+)?)(?::(\d+))?\s*=\s*(\S+)\s*$")


@dataclass(frozen=True, slots=True, order=True)
class ParameterValue:
    """`width` bytes from T/C/K/D `byte`, as an unsigned little-endian value."""

    area_order: int
    byte: int
    width: int = field(compare=False)
    value: int = field(compare=False)

    @property
    def area(self) -> Area:
        """The area (T, C, K or D)."""
        return PARAMETER_AREAS[self.area_order]

    @property
    def address(self) -> Address:
        """The first byte."""
        return Address(self.area, self.byte)


def parameter_value(address: Address, value: int, width: int = 1) -> ParameterValue:
    """A parameter value at a byte address, wrapped to `width` bytes."""
    if address.area not in PARAMETER_AREAS:
        raise ValueError(f"{address}: PMC parameters are in T, C, K and D only")
    if width not in WIDTHS:
        raise ValueError(f"width {width}: a value has 1, 2 or 4 bytes")
    return ParameterValue(PARAMETER_AREAS.index(address.area), address.byte, width,
                          value & ((1 << 8 * width) - 1))


class PmcParameters:
    """The non-default PMC parameter values of a program, plus lines kept from its file."""

    def __init__(self, values: Iterable[ParameterValue] = (), kept: Iterable[str] = ()) -> None:
        self._values: dict[tuple[int, int], ParameterValue] = {}
        for item in values:
            self._put(item)
        self.kept: list[str] = list(kept)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, PmcParameters):
            return NotImplemented
        return self._key() == other._key()

    def _key(self) -> tuple[object, ...]:
        return (tuple((v.area_order, v.byte, v.width, v.value) for v in self.values()),
                tuple(self.kept))

    def __bool__(self) -> bool:
        return bool(self._values or self.kept)

    def __repr__(self) -> str:
        return f"PmcParameters({self.values()!r}, kept={self.kept!r})"

    def copy(self) -> PmcParameters:
        """An independent copy."""
        return PmcParameters(self.values(), self.kept)

    def values(self) -> list[ParameterValue]:
        """The values, sorted by area (T, C, K, D) and byte."""
        return sorted(self._values.values())

    def __iter__(self) -> Iterator[ParameterValue]:
        return iter(self.values())

    def _byte(self, area_order: int, byte: int) -> int:
        for item in self._overlapping(area_order, byte, 1):
            return item.value >> 8 * (byte - item.byte) & 0xFF
        return 0

    def _overlapping(self, area_order: int, byte: int, width: int) -> list[ParameterValue]:
        return [item for (order, start), item in self._values.items()
                if order == area_order and start < byte + width and byte < start + item.width]

    def _put(self, item: ParameterValue) -> None:
        for old in self._overlapping(item.area_order, item.byte, item.width):
            del self._values[(old.area_order, old.byte)]
            for byte in range(old.byte, old.byte + old.width):  # bytes outside the new value
                if not item.byte <= byte < item.byte + item.width:
                    rest = old.value >> 8 * (byte - old.byte) & 0xFF
                    if rest:
                        self._values[(old.area_order, byte)] = ParameterValue(
                            old.area_order, byte, 1, rest)
        if item.value:
            self._values[(item.area_order, item.byte)] = item

    def set(self, address: Address, value: int, width: int = 1) -> None:
        """Set a value (0, the default, removes it); a bit address sets one bit."""
        if address.bit is not None:
            old = self.get(Address(address.area, address.byte))
            mask = 1 << address.bit
            value = old | mask if value else old & ~mask
            address, width = Address(address.area, address.byte), 1
        self._put(parameter_value(address, value, width))

    def get(self, address: Address, width: int = 1) -> int:
        """The value of `width` bytes at a byte address (0 where nothing is set)."""
        order = PARAMETER_AREAS.index(address.area)
        return sum(self._byte(order, address.byte + i) << 8 * i for i in range(width))

    def apply(self, memory: Memory) -> None:
        """Write every value into the memory image (other bytes are left as they are)."""
        for item in self._values.values():
            memory.write(item.address, item.value, item.width)


# -- the text file ------------------------------------------------------------------------


@dataclass(slots=True)
class ParameterFile:
    """A parameter file read: its values and the lines it could not read."""

    parameters: PmcParameters
    diagnostics: list[Diagnostic]
    path: Path | None = None


def parameter_path(program_path: str | Path) -> Path:
    """The parameter file of a program: `PROGRAM.LAD` -> `PROGRAM.LAD.prm`."""
    path = Path(program_path)
    return path.with_name(path.name + SUFFIX)


def _value(text: str, width: int) -> int | None:
    spelled = text.replace("_", "")
    try:
        value = int(spelled, 0) if spelled.lower().lstrip("-").startswith(("0x", "0b")) \
            else int(spelled, 10)
    except ValueError:
        return None
    bits = 8 * width
    return value if -(1 << bits - 1) <= value < 1 << bits else None


def _read_line(text: str, number: int) -> tuple[Address, int, int] | Diagnostic | None:
    body = re.split(r"[#;]", text, maxsplit=1)[0]
    if not body.strip():
        return None
    match = _LINE_RE.match(body)
    if not match:
        return Diagnostic("prm-line", {"text": body.strip()}, number, 1)
    spelled, width_text, value_text = match.groups()
    width = int(width_text) if width_text else 1
    if width not in WIDTHS:
        return Diagnostic("prm-value", {"text": value_text, "width": width_text}, number, 1)
    try:
        address = parse_address(spelled, width=width)
    except AddressError as error:
        return Diagnostic(error.code, error.args_map, number, 1)
    if address.area not in PARAMETER_AREAS:
        return Diagnostic("prm-area", {"text": spelled}, number, 1)
    if address.bit is not None and (width_text or value_text not in ("0", "1")):
        return Diagnostic("prm-value", {"text": value_text, "width": "bit"}, number, 1)
    value = _value(value_text, width)
    if value is None:
        return Diagnostic("prm-value", {"text": value_text, "width": width}, number,
                          body.index(value_text) + 1)
    return address, value, width


def parse_parameters(text: str) -> ParameterFile:
    """Read parameter-file text; a bad line gives a diagnostic (with its line) and is kept."""
    parameters = PmcParameters()
    diagnostics: list[Diagnostic] = []
    for number, line in enumerate(split_lines(text), start=1):
        if line.strip() == KEPT_HEADER:
            continue
        item = _read_line(line, number)
        if isinstance(item, Diagnostic):
            diagnostics.append(item)
            parameters.kept.append(line.rstrip())
        elif item is not None:
            parameters.set(*item)
    return ParameterFile(parameters, diagnostics)


def _comment(item: ParameterValue, dialect: str) -> str:
    """What a value is, for people reading the file."""
    if item.area is Area.T:
        layout = timer_layout(dialect)
        number, offset = divmod(item.byte, layout.width)
        if offset == 0 and item.width == layout.width and number < layout.count:
            return f"TMR {number + 1} preset ({layout.unit})"
        for n in range(1, layout.count + 1):
            if layout.precision_address(n) == item.address:
                return f"TMR {n} precision"
    elif item.area is Area.C and item.width == 2 and item.byte % 2 == 0:
        number, offset = divmod(item.byte, COUNTER_BYTES)
        return f"CTR {number + 1} {'preset' if offset == 0 else 'current value'}"
    return ""


def _spelled(item: ParameterValue) -> str:
    if item.area is Area.K and item.width == 1:
        return f"0b{item.value:08b}"
    if item.area is Area.D:
        return f"0x{item.value:0{2 * item.width}X}"
    return str(item.value)


def format_parameters(parameters: PmcParameters, dialect: str = SEED) -> str:
    """The file text: a header, one sorted line per value, then the kept lines."""
    lines = [HEADER]
    for item in parameters.values():
        width = f":{item.width}" if item.width > 1 else ""
        line = f"{item.address}{width} = {_spelled(item)}"
        comment = _comment(item, dialect)
        lines.append(f"{line:<20} # {comment}" if comment else line)
    if parameters.kept:
        lines += [KEPT_HEADER, *parameters.kept]
    return "\n".join(lines) + "\n"


def read_parameter_file(path: str | Path) -> ParameterFile:
    """Read a parameter file (UTF-8, or cp1254 when not UTF-8); OSError if it cannot be read."""
    data = Path(path).read_bytes()
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        text = data.decode("cp1254", errors="replace")
    result = parse_parameters(text)
    result.path = Path(path)
    return result


def parameters_beside(program_path: str | Path) -> ParameterFile:
    """The parameter file beside a program, or the defaults (no values) when there is none."""
    path = parameter_path(program_path)
    if not path.exists():
        return ParameterFile(PmcParameters(), [])
    return read_parameter_file(path)
