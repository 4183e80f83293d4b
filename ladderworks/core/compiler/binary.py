"""The binary PLC program format: header, op records, parameter data and the source map."""

from __future__ import annotations

import struct
import zlib
from dataclasses import dataclass

from ladderworks.core import dialects
from ladderworks.core.address import Address, Area
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.il.program import ParamValue
from ladderworks.core.instructions import (
    BASIC,
    BY_OPCODE,
    BY_SUB,
    FUNCTION_OPCODE,
    InstructionSpec,
    Kind,
    ParamKind,
    spec_for,
    unknown_sub,
)

MAGIC = b"LWPC"
FORMAT_VERSION = 3

# Older versions this LadderWorks refuses, with what changed (the program must be compiled again).
RETIRED_VERSIONS: dict[int, str] = {
    1: "JMP had no coil count then",
    2: "16-bit network sizes and source lines, no area E, no dialect flag",
}

_PREFIX = struct.Struct("<4sH")  # magic, version: the same in every version
# magic, version, header size, ops, param bytes, flags, reserved, crc32
_HEADER = struct.Struct("<4sHHIIHHI")
_OP = struct.Struct("<BBHII")  # opcode, a, b, c, d
_PARAM = struct.Struct("<Bq")  # tag, payload
_PARAM_ADDRESS = struct.Struct("<BIB2x")  # area code, byte, bit (0xFF = none)
_SOURCE = struct.Struct("<IIII")  # network, instruction index, line, column

HEADER_SIZE = _HEADER.size
OP_SIZE = _OP.size
PARAM_SIZE = _PARAM.size
SOURCE_SIZE = _SOURCE.size

FLAG_FANUC = 0x0001  # header flag: the program is in the FANUC (LADDER-III) dialect
DIALECT_SHIFT = 8  # header flags bits 8-15: a registered dialect's code (core/dialects)
U32 = 2**32 - 1

# Opcodes of the basic instructions (from the table); a functional one or END is FUNCTION_OPCODE.
BASIC_OPCODES: dict[str, int] = {spec.name: spec.opcode for spec in BASIC}
BASIC_NAMES: dict[int, str] = {code: name for name, code in BASIC_OPCODES.items()}

_FIRST_AREAS = "XYFGRADTCK"  # the codes of format version 2; new areas are appended
AREA_CODES: str = _FIRST_AREAS + "".join(a.value for a in Area if a.value not in _FIRST_AREAS)

_SIZES = dialects.memory_sizes()  # the bytes of each area of the memory image
_TAG_INT = 0
_TAG_ADDRESS = 1
_TAG_PROGRAM = 2
_TAG_LABEL = 3
_NO_BIT = 0xFF


class BinaryFormatError(DiagnosticError):
    """The bytes are not a valid LadderWorks binary (diagnostic code bad-binary)."""

    def __init__(self, reason: str) -> None:
        self.reason = reason
        super().__init__([Diagnostic("bad-binary", {"reason": reason})])


@dataclass(frozen=True, slots=True)
class SourcePosition:
    """Where an op came from: network index, instruction index in the network, line, column."""

    network: int
    instruction: int
    line: int
    column: int


@dataclass(frozen=True, slots=True)
class Op:
    """One decoded op: the mnemonic with its operand or parameters, and its source position."""

    name: str
    operand: Address | None
    params: tuple[ParamValue, ...]
    source: SourcePosition

    @property
    def spec(self) -> InstructionSpec:
        """The instruction table row."""
        spec = spec_for(self.name, len(self.params))
        assert spec is not None
        return spec


@dataclass(frozen=True, slots=True)
class BinaryProgram:
    """A decoded binary: the ops in program order (the source map is in each op)."""

    ops: tuple[Op, ...]
    version: int = FORMAT_VERSION
    dialect: str = "seed"  # "fanuc" for a LADDER-III program (header flag), else "seed"

    def op_at_line(self, line: int) -> int | None:
        """Index of the first op compiled from source line `line`, or None."""
        for index, op in enumerate(self.ops):
            if op.source.line == line:
                return index
        return None


def _encode_param(value: ParamValue, kind: ParamKind | None) -> bytes:
    if isinstance(value, Address):
        payload = _PARAM_ADDRESS.pack(
            AREA_CODES.index(value.area.value), value.byte,
            _NO_BIT if value.bit is None else value.bit)
        return bytes([_TAG_ADDRESS]) + payload
    tag = _TAG_PROGRAM if kind is ParamKind.PROGRAM else (
        _TAG_LABEL if kind is ParamKind.LABEL else _TAG_INT)
    return _PARAM.pack(tag, value if isinstance(value, int) else value.number)


def encode(ops: list[Op] | tuple[Op, ...], dialect: str = "seed") -> bytes:
    """The bytes of a binary holding `ops` (`dialect` goes in the header's flags)."""
    records = bytearray()
    params = bytearray()
    sources = bytearray()
    for op in ops:
        spec = op.spec
        if spec.kind is Kind.BASIC:
            area = byte = bit = 0
            if op.operand is not None:
                area = AREA_CODES.index(op.operand.area.value)
                byte = op.operand.byte
                bit = op.operand.bit or 0
            # a basic row's one number (Fatek's branch point TR n) in the record's last field
            number = op.params[0] if spec.params and op.params else 0
            records += _OP.pack(spec.opcode, area, bit, byte,
                                number if isinstance(number, int) else 0)
        else:
            assert spec.sub is not None
            records += _OP.pack(spec.opcode, 0, spec.sub, len(op.params), len(params))
            kinds = [p.kind for p in spec.params]
            for k, value in enumerate(op.params):
                params += _encode_param(value, kinds[k] if k < len(kinds) else None)
        src = op.source
        sources += _SOURCE.pack(*(min(max(v, 0), U32) for v in (
            src.network, src.instruction, src.line, src.column)))
    body = bytes(records) + bytes(params) + bytes(sources)
    other = dialects.get(dialect)
    flags = FLAG_FANUC if dialect == "fanuc" else (
        other.code << DIALECT_SHIFT if other is not None else 0)
    fields = (MAGIC, FORMAT_VERSION, HEADER_SIZE, len(ops), len(params), flags, 0)
    head = _HEADER.pack(*fields, 0)[:-4]
    return head + zlib.crc32(body, zlib.crc32(head)).to_bytes(4, "little") + body


def _decode_area(code: int, where: str) -> Area:
    if code >= len(AREA_CODES):
        raise BinaryFormatError(f"unknown area code {code} in {where}")
    return Area(AREA_CODES[code])


def _decode_param(data: bytes, offset: int, where: str) -> ParamValue:
    tag, number = _PARAM.unpack_from(data, offset)
    if tag in (_TAG_INT, _TAG_PROGRAM, _TAG_LABEL):
        return int(number)
    if tag != _TAG_ADDRESS:
        raise BinaryFormatError(f"unknown parameter tag {tag} in {where}")
    code, byte, bit = _PARAM_ADDRESS.unpack_from(data, offset + 1)
    area = _decode_area(code, where)
    if byte >= _SIZES[area] or (bit != _NO_BIT and bit > 7):
        raise BinaryFormatError(f"address out of range in {where}")
    return Address(area, byte, None if bit == _NO_BIT else bit)


def decode(data: bytes) -> BinaryProgram:
    """Decode and verify a binary; raises BinaryFormatError with the reason."""
    if not isinstance(data, bytes | bytearray | memoryview):
        raise BinaryFormatError("not bytes")
    data = bytes(data)
    if len(data) < _PREFIX.size:
        raise BinaryFormatError(f"too short ({len(data)} bytes)")
    magic, version = _PREFIX.unpack_from(data)
    if magic != MAGIC:
        raise BinaryFormatError("wrong magic number (not a compiled LadderWorks program)")
    if version in RETIRED_VERSIONS:
        raise BinaryFormatError(
            f"format version {version} is no longer supported ({RETIRED_VERSIONS[version]}): "
            f"compile the program again (this LadderWorks reads version {FORMAT_VERSION})")
    if version != FORMAT_VERSION:
        raise BinaryFormatError(f"format version {version} is not supported "
                                f"(this LadderWorks reads version {FORMAT_VERSION})")
    if len(data) < HEADER_SIZE:
        raise BinaryFormatError(f"too short ({len(data)} bytes)")
    _, _, header_size, count, param_bytes, flags, _, crc = _HEADER.unpack_from(data)
    if header_size != HEADER_SIZE:
        raise BinaryFormatError(f"unexpected header size {header_size}")
    expected = HEADER_SIZE + count * (OP_SIZE + SOURCE_SIZE) + param_bytes
    if len(data) != expected:
        raise BinaryFormatError(f"length {len(data)} bytes, the header says {expected}")
    body = data[HEADER_SIZE:]
    if zlib.crc32(body, zlib.crc32(data[:HEADER_SIZE - 4])) != crc:
        raise BinaryFormatError("checksum mismatch (the file is damaged)")
    params_at = HEADER_SIZE + count * OP_SIZE
    sources_at = params_at + param_bytes
    ops: list[Op] = []
    for index in range(count):
        where = f"op {index}"
        opcode, a, b, c, d = _OP.unpack_from(data, HEADER_SIZE + index * OP_SIZE)
        source = SourcePosition(*_SOURCE.unpack_from(data, sources_at + index * SOURCE_SIZE))
        basic = BY_OPCODE.get(opcode)
        if basic is not None:
            operand: Address | None = None
            if basic.operand:
                area = _decode_area(a, where)
                if c >= _SIZES[area] or b > 7:
                    raise BinaryFormatError(f"address out of range in {where}")
                operand = Address(area, c, b)
            ops.append(Op(basic.name, operand, (d,) if basic.params else (), source))
            continue
        if opcode != FUNCTION_OPCODE:
            raise BinaryFormatError(f"unknown opcode {opcode} in {where}")
        fspec = BY_SUB.get(b) or unknown_sub(b, c)
        if d % PARAM_SIZE or d + c * PARAM_SIZE > param_bytes:
            raise BinaryFormatError(f"parameter data out of bounds in {where}")
        values = tuple(_decode_param(data, params_at + d + k * PARAM_SIZE, where)
                       for k in range(c))
        ops.append(Op(fspec.name, None, values, source))
    code = flags >> DIALECT_SHIFT & 0xFF
    other = dialects.by_code(code) if code else None
    if code and other is None:
        raise BinaryFormatError(f"unknown dialect code {code}")
    name = "fanuc" if flags & FLAG_FANUC else (other.name if other is not None else "seed")
    return BinaryProgram(tuple(ops), version, name)
