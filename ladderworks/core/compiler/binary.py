"""The binary PLC program format: header, op records, parameter data and the source map."""

from __future__ import annotations

import struct
import zlib
from dataclasses import dataclass

from ladderworks.core.address import AREA_SIZES, Address, Area
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.il.program import ParamValue
from ladderworks.core.instructions import BY_SUB, InstructionSpec, Kind, lookup

MAGIC = b"LWPC"
FORMAT_VERSION = 2

# Older versions this LadderWorks refuses, with what changed (the program must be compiled again).
RETIRED_VERSIONS: dict[int, str] = {
    1: "JMP had no coil count then",
}

_HEADER = struct.Struct("<4sHHIII")  # magic, version, header size, ops, param bytes, crc32
_OP = struct.Struct("<BBHI")  # opcode, a, b, c
_PARAM = struct.Struct("<Bi")  # tag, payload
_PARAM_ADDRESS = struct.Struct("<BHB")  # area code, byte, bit (0xFF = none)
_SOURCE = struct.Struct("<IHIH")  # network, instruction index, line, column

HEADER_SIZE = _HEADER.size
OP_SIZE = _OP.size
PARAM_SIZE = _PARAM.size
SOURCE_SIZE = _SOURCE.size

# Opcodes of the basic instructions; a functional instruction or END is FUNCTION_OPCODE + SUB.
BASIC_OPCODES: dict[str, int] = {
    "RD": 1, "RD.NOT": 2, "WRT": 3, "WRT.NOT": 4, "AND": 5, "AND.NOT": 6, "OR": 7,
    "OR.NOT": 8, "RD.STK": 9, "RD.NOT.STK": 10, "AND.STK": 11, "OR.STK": 12,
}
BASIC_NAMES: dict[int, str] = {code: name for name, code in BASIC_OPCODES.items()}
FUNCTION_OPCODE = 0x80

AREA_CODES: str = "XYFGRADTCK"  # area code n is AREA_CODES[n]

_TAG_INT = 0
_TAG_ADDRESS = 1
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
        spec = lookup(self.name)
        assert spec is not None
        return spec


@dataclass(frozen=True, slots=True)
class BinaryProgram:
    """A decoded binary: the ops in program order (the source map is in each op)."""

    ops: tuple[Op, ...]
    version: int = FORMAT_VERSION

    def op_at_line(self, line: int) -> int | None:
        """Index of the first op compiled from source line `line`, or None."""
        for index, op in enumerate(self.ops):
            if op.source.line == line:
                return index
        return None


def _encode_param(value: ParamValue) -> bytes:
    if isinstance(value, Address):
        payload = _PARAM_ADDRESS.pack(
            AREA_CODES.index(value.area.value), value.byte,
            _NO_BIT if value.bit is None else value.bit)
        return bytes([_TAG_ADDRESS]) + payload
    return _PARAM.pack(_TAG_INT, value)


def encode(ops: list[Op] | tuple[Op, ...]) -> bytes:
    """The bytes of a binary holding `ops`."""
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
            records += _OP.pack(BASIC_OPCODES[spec.name], area, byte, bit)
        else:
            assert spec.sub is not None
            records += _OP.pack(FUNCTION_OPCODE, len(op.params), spec.sub, len(params))
            for value in op.params:
                params += _encode_param(value)
        src = op.source
        sources += _SOURCE.pack(src.network, src.instruction, src.line, src.column)
    body = bytes(records) + bytes(params) + bytes(sources)
    header = _HEADER.pack(MAGIC, FORMAT_VERSION, HEADER_SIZE, len(ops), len(params),
                          zlib.crc32(body))
    return header + body


def _decode_area(code: int, where: str) -> Area:
    if code >= len(AREA_CODES):
        raise BinaryFormatError(f"unknown area code {code} in {where}")
    return Area(AREA_CODES[code])


def _decode_param(data: bytes, offset: int, where: str) -> ParamValue:
    tag, number = _PARAM.unpack_from(data, offset)
    if tag == _TAG_INT:
        return number
    if tag != _TAG_ADDRESS:
        raise BinaryFormatError(f"unknown parameter tag {tag} in {where}")
    code, byte, bit = _PARAM_ADDRESS.unpack_from(data, offset + 1)
    area = _decode_area(code, where)
    if byte >= AREA_SIZES[area] or (bit != _NO_BIT and bit > 7):
        raise BinaryFormatError(f"address out of range in {where}")
    return Address(area, byte, None if bit == _NO_BIT else bit)


def decode(data: bytes) -> BinaryProgram:
    """Decode and verify a binary; raises BinaryFormatError with the reason."""
    if not isinstance(data, bytes | bytearray | memoryview):
        raise BinaryFormatError("not bytes")
    data = bytes(data)
    if len(data) < HEADER_SIZE:
        raise BinaryFormatError(f"too short ({len(data)} bytes)")
    magic, version, header_size, count, param_bytes, crc = _HEADER.unpack_from(data)
    if magic != MAGIC:
        raise BinaryFormatError("wrong magic number (not a compiled LadderWorks program)")
    if version in RETIRED_VERSIONS:
        raise BinaryFormatError(
            f"format version {version} is no longer supported ({RETIRED_VERSIONS[version]}): "
            f"compile the program again (this LadderWorks reads version {FORMAT_VERSION})")
    if version != FORMAT_VERSION:
        raise BinaryFormatError(f"format version {version} is not supported "
                                f"(this LadderWorks reads version {FORMAT_VERSION})")
    if header_size != HEADER_SIZE:
        raise BinaryFormatError(f"unexpected header size {header_size}")
    expected = HEADER_SIZE + count * (OP_SIZE + SOURCE_SIZE) + param_bytes
    if len(data) != expected:
        raise BinaryFormatError(f"length {len(data)} bytes, the header says {expected}")
    body = data[HEADER_SIZE:]
    if zlib.crc32(body) != crc:
        raise BinaryFormatError("checksum mismatch (the file is damaged)")
    params_at = HEADER_SIZE + count * OP_SIZE
    sources_at = params_at + param_bytes
    ops: list[Op] = []
    for index in range(count):
        where = f"op {index}"
        opcode, a, b, c = _OP.unpack_from(data, HEADER_SIZE + index * OP_SIZE)
        network, instruction, line, column = _SOURCE.unpack_from(
            data, sources_at + index * SOURCE_SIZE)
        source = SourcePosition(network, instruction, line, column)
        if opcode in BASIC_NAMES:
            name = BASIC_NAMES[opcode]
            spec = lookup(name)
            assert spec is not None
            operand: Address | None = None
            if spec.operand:
                area = _decode_area(a, where)
                if b >= AREA_SIZES[area] or c > 7:
                    raise BinaryFormatError(f"address out of range in {where}")
                operand = Address(area, b, c)
            ops.append(Op(name, operand, (), source))
            continue
        if opcode != FUNCTION_OPCODE:
            raise BinaryFormatError(f"unknown opcode {opcode} in {where}")
        fspec = BY_SUB.get(b)
        if fspec is None:
            raise BinaryFormatError(f"unknown SUB number {b} in {where}")
        if c % PARAM_SIZE or c + a * PARAM_SIZE > param_bytes:
            raise BinaryFormatError(f"parameter data out of bounds in {where}")
        values = tuple(_decode_param(data, params_at + c + k * PARAM_SIZE, where)
                       for k in range(a))
        ops.append(Op(fspec.name, None, values, source))
    return BinaryProgram(tuple(ops), version)
