"""Where an S7 program's names live in the engine's memory, and typed constants.

Tags with a logical address are at that address (%I → X, %Q → Y, %M → R: devices.py). Every
other name — members of the blocks' interfaces (Input, Output, InOut, Static, Temp), global DB
members, timer/counter instances, an instance DB named only by its use — is laid out by
LadderWorks in the D area from D0, in the order met, each at an even byte when wider than one
byte (optimized DBs have no fixed offsets, so any layout is faithful to the program's meaning).
A Bool takes a byte (bit 0). An IEC_TIMER takes 16 bytes (PT +0, ET +4, IN +8.0, Q +8.1), an
IEC_COUNTER 12 (CV +0, PV +4, CU +8.0, CD +8.1, R +8.2, LD +8.3, QU +8.4, QD +8.5).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ladderworks.core.address import Address, AddressError, Area
from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.dialects.s7.graph import Block, Member, Operand, OperandKind, S7Program
from ladderworks.core.dialects.s7.rows import COUNTER_BYTES, TIMER_BYTES
from ladderworks.core.plc import typed

D_BYTES = 10_000
TIMER_TYPES = frozenset({"iec_timer", "ton_time", "tof_time", "tp_time", "tonr_time"})
COUNTER_TYPES = frozenset({"iec_counter", "iec_ucounter", "iec_dcounter", "iec_udcounter",
                           "iec_scounter", "iec_uscounter", "ctu_int", "ctd_int", "ctud_int",
                           "ctu_dint", "ctd_dint", "ctud_dint", "ctu_uint", "ctu_sint"})
TIMER_MEMBERS = {"pt": (0, None, "Time"), "et": (4, None, "Time"), "in": (8, 0, "Bool"),
                  "q": (8, 1, "Bool")}
COUNTER_MEMBERS = {"cv": (0, None, "DInt"), "pv": (4, None, "DInt"), "cu": (8, 0, "Bool"),
                    "cd": (8, 1, "Bool"), "r": (8, 2, "Bool"), "ld": (8, 3, "Bool"),
                    "q": (8, 4, "Bool"), "qu": (8, 4, "Bool"), "qd": (8, 5, "Bool")}
_SIZES = {"bool": 1, "byte": 1, "sint": 1, "usint": 1, "char": 1, "int": 2, "uint": 2,
          "word": 2, "dint": 4, "udint": 4, "dword": 4, "real": 4, "time": 4, "lreal": 8,
          "lint": 8, "ulint": 8, "lword": 8, "ltime": 8, "date": 2, "tod": 4, "time_of_day": 4,
          "wchar": 2}
_ARRAY_RE = re.compile(r"^array\s*\[\s*(-?\d+)\s*\.\.\s*(-?\d+)\s*\]\s*of\s+(.+)$", re.I)
_STRING_RE = re.compile(r"^w?string(?:\s*\[\s*(\d+)\s*\])?$", re.I)
_TIME_RE = re.compile(r"(\d+(?:\.\d+)?)(ms|d|h|m|s)", re.I)
_UNIT_MS = {"d": 86_400_000, "h": 3_600_000, "m": 60_000, "s": 1000, "ms": 1}


@dataclass(frozen=True, slots=True)
class Place:
    """A name's place: its address (a bit for a Bool) and its type name as TIA writes it."""

    address: Address
    type_name: str

    @property
    def vtype(self) -> typed.ValueType | None:
        """Its elementary type (None for a struct, a timer, a counter …)."""
        return typed.type_of(self.type_name)


def size_of(type_name: str, members: tuple[Member, ...] = ()) -> int:
    """The bytes a value of the type takes in LadderWorks' layout."""
    low = type_name.strip().strip('"').lower()
    if low in TIMER_TYPES:
        return TIMER_BYTES
    if low in COUNTER_TYPES:
        return COUNTER_BYTES
    array = _ARRAY_RE.match(type_name.strip())
    if array is not None:  # an array of Struct: its elements' members
        step = _aligned(size_of("Struct", members) if members else size_of(array.group(3)))
        return max(0, int(array.group(2)) - int(array.group(1)) + 1) * step
    if low == "struct" or members:  # a Struct, a PLC data type's or an FB's members
        total = 0
        for member in members:  # as Layout places them
            size = size_of(member.type_name, member.members)
            total += (1 if size > 1 and total & 1 else 0) + _aligned(size)
        return max(2, _aligned(total))
    string = _STRING_RE.match(low)
    if string is not None:  # S7 strings: max length, actual length, the characters
        length = int(string.group(1) or 254)
        return (length + 2) * 2 if low.startswith("w") else length + 2
    return _SIZES.get(low, 16)


def element(place: Place, index_text: str, step: int = 0) -> Place | None:
    """The element `[i]` of an array's place (a constant index in its bounds; `step` its
    elements' size when they have members), else None."""
    array = _ARRAY_RE.match(place.type_name.strip())
    if array is None:
        return None
    try:
        index = int(index_text.strip())
    except ValueError:
        return None
    low, high, of = int(array.group(1)), int(array.group(2)), array.group(3).strip()
    if not low <= index <= high:
        return None
    step = step or _aligned(size_of(of))
    base = place.address
    byte = base.byte + (index - low) * step
    return Place(Address(base.area, byte, 0 if of.lower() == "bool" else None), of)


def _aligned(size: int) -> int:
    return size + (size & 1) if size > 1 else size


def time_ms(text: str) -> int | None:
    """A Time constant's milliseconds (`T#10s`, `T#1m30s`, `TIME#500ms`, `T#-2s`), None if not."""
    head, sep, body = text.partition("#")
    if not sep or head.upper() not in ("T", "TIME", "LT", "LTIME"):
        return None
    sign = -1 if body.startswith("-") else 1
    body = body.lstrip("+-").replace("_", "")
    total, at = 0.0, 0
    for match in _TIME_RE.finditer(body):
        if match.start() != at:
            return None
        total += float(match.group(1)) * _UNIT_MS[match.group(2).lower()]
        at = match.end()
    return sign * round(total) if at == len(body) and body else None


def constant_type(text: str) -> typed.ValueType | None:
    """The type a constant's spelling gives (`T#5s` Time, `1.5` Real, `INT#3` Int)."""
    chars = string_value(text)
    if chars is not None:
        return typed.ValueType.CHAR if len(chars) == 1 else None
    head, sep, _ = text.partition("#")
    if sep and not head.isdigit():
        if time_ms(text) is not None:
            return typed.ValueType.TIME
        return typed.type_of(head)
    if re.fullmatch(r"[+-]?\d[\d_]*\.\d[\d_]*(?:[eE][+-]?\d+)?|[+-]?\d+[eE][+-]?\d+", text):
        return typed.ValueType.REAL
    return None


def constant_value(text: str, vtype: typed.ValueType) -> int | None:
    """A constant as a parameter int of `vtype` (a Real as its IEEE bits), None if unreadable."""
    upper = text.strip().upper()
    if upper in ("TRUE", "FALSE"):
        return int(upper == "TRUE")
    chars = string_value(text)
    if chars is not None:  # a Char constant 'A' (a String's are written by starts.py)
        return ord(chars[0]) if len(chars) == 1 and vtype is typed.ValueType.CHAR else None
    ms = time_ms(text)
    if ms is not None:
        return ms
    head, sep, body = text.partition("#")
    if sep and not head.isdigit():  # INT#5, DINT#16#FF
        text = body
    number = text.replace("_", "")
    try:
        if "#" in number:
            base, digits = number.split("#", 1)
            value: float = int(digits, int(base))
        elif vtype is typed.ValueType.REAL or re.search(r"[.eE]", number):
            value = float(number)
        else:
            value = int(number)
    except ValueError:
        return None
    if vtype is typed.ValueType.REAL:
        return typed.real_bits(float(value))
    if vtype is typed.ValueType.LREAL:  # 32-bit parameters: a Real's bits when exact
        bits = typed.real_bits(float(value))
        exact = typed.bits_real(bits) == float(value) or not math.isfinite(float(value))
        return bits if exact else None
    return int(value)


_TYPED_STRING = re.compile(r"(?i)^(?:w?string|w?char)\s*#\s*(?=')")
_ESCAPES = {"$": "$", "'": "'", "L": "\n", "N": "\n", "P": "\f", "R": "\r", "T": "\t"}


def string_value(text: str) -> str | None:
    """A quoted S7 string constant's characters (`'It''s'`, `'a$Nb'`, `'$41'`), else None."""
    text = text.strip()
    typed_prefix = _TYPED_STRING.match(text)  # STRING#'…', WSTRING#'…', CHAR#'…'
    if typed_prefix is not None:
        text = text[typed_prefix.end():]
    if len(text) < 2 or text[0] != "'" or text[-1] != "'":
        return None
    body, out, at = text[1:-1].replace("''", "'"), [], 0
    while at < len(body):
        char = body[at]
        if char == "$" and at + 1 < len(body):
            code = body[at + 1:at + 3]
            if re.fullmatch(r"[0-9A-Fa-f]{2}", code):
                out.append(chr(int(code, 16)))
                at += 3
                continue
            out.append(_ESCAPES.get(body[at + 1].upper(), body[at + 1]))
            at += 2
            continue
        out.append(char)
        at += 1
    return "".join(out)


@dataclass(slots=True)
class Layout:
    """The places of one program's names, laid out on first use."""

    program: S7Program
    next_byte: int = 0
    places: dict[tuple[str, ...], Place] = field(default_factory=dict)
    members: dict[tuple[str, ...], Member] = field(default_factory=dict)
    full: bool = False  # a name found no room in the D area (lowering: s7-memory-full)
    # LReal constants a Real does not hold: their place and IEEE double bits (starts.py
    # writes them in the first scan)
    constants: dict[int, Address] = field(default_factory=dict)

    def lreal_constant(self, value: float) -> Address | None:
        """The place holding an LReal constant (laid out once per value)."""
        bits = typed.lreal_bits(value)
        if bits not in self.constants:
            address = self._allocate(8)
            if address is None:
                return None
            self.constants[bits] = address
        return self.constants[bits]

    def _allocate(self, size: int) -> Address | None:
        """Room for `size` bytes, None (and `full` set) when the D area has none left."""
        start = self.next_byte + (1 if size > 1 and self.next_byte & 1 else 0)
        if start + size > D_BYTES:
            self.full = True
            return None
        self.next_byte = start + size
        return Address(Area.D, start)

    def typed(self, member: Member) -> Member:
        """A member typed by a PLC data type (`"Motor_UDT"`) with that type's members."""
        if member.members:
            return member
        udt = self.program.block(member.type_name.strip().strip('"'))
        if udt is None or udt.kind != "Type":
            return member
        return Member(member.name, member.type_name, member.start, member.comment,
                      tuple(udt.members("Static")))

    def size(self, member: Member) -> int:
        """size_of a member, its PLC data types' members counted."""
        member = self.typed(member)
        array = _ARRAY_RE.match(member.type_name.strip())
        if array is not None:
            count = int(array.group(2)) - int(array.group(1)) + 1
            return max(0, count) * self.element_size(member)
        if not member.members or member.type_name.strip('"').lower() in TIMER_TYPES | \
                COUNTER_TYPES:
            return size_of(member.type_name, member.members)
        total = 0
        for inner in member.members:
            size = self.size(inner)
            total += (1 if size > 1 and total & 1 else 0) + _aligned(size)
        return max(2, _aligned(total))

    def element_member(self, member: Member) -> Member:
        """An array member's element as a member (its type; a Struct's or PLC data type's
        members)."""
        array = _ARRAY_RE.match(member.type_name.strip())
        of = array.group(3).strip() if array is not None else member.type_name
        return self.typed(Member(member.name, "Struct" if member.members else of,
                                 members=member.members))

    def element_size(self, member: Member) -> int:
        """The bytes between an array member's elements."""
        return _aligned(self.size(self.element_member(member)))

    def member_at(self, place: Place, member: Member, name: str) -> tuple[Place, Member] | None:
        """A struct's member `name` (lower case) at its offset from the struct's place (an
        array element's members, which have no places of their own)."""
        offset = 0
        for inner in self.typed(member).members:
            size = self.size(inner)
            if size > 1 and offset & 1:
                offset += 1
            if inner.name.lower() == name:
                base = place.address
                bit = 0 if inner.type_name.lower() == "bool" else None
                return (Place(Address(base.area, base.byte + offset, bit), inner.type_name),
                        self.typed(inner))
            offset += _aligned(size)
        return None

    def _lay(self, key: tuple[str, ...], member: Member) -> Place | None:
        """Place `member` (and its struct members) under `key`; None when there is no room."""
        found = self.places.get(key)
        if found is not None:
            return found
        base = self._allocate(self.size(member))
        if base is None:
            return None
        self._place_inner(key, member, base)
        return self.places[key]

    def _place_inner(self, key: tuple[str, ...], member: Member, at: Address) -> None:
        member = self.typed(member)
        bit = 0 if member.type_name.lower() == "bool" else None
        self.places[key] = Place(Address(at.area, at.byte, bit), member.type_name)
        self.members[key] = member
        if _ARRAY_RE.match(member.type_name.strip()):
            return  # an array of Struct's members are found by offset (`sub`)
        offset = 0
        for inner in member.members:
            size = self.size(inner)
            if size > 1 and offset & 1:
                offset += 1
            self._place_inner((*key, inner.name.lower()), inner,
                              Address(at.area, at.byte + offset))
            offset += _aligned(size)

    def local(self, block: Block, path: tuple[str, ...],
              scope: tuple[str, ...] = ()) -> Place | None:
        """A `#member[.sub…]` of `block`'s interface, in `scope` (an FB instance's: its
        instance DB `("motor_db",)`; by default the block's own `("#name",)`)."""
        stem, bracket, index = path[0].partition("[")  # `#Flags[3]`: an element of a member
        found = block.member(stem)
        if found is None:
            return None
        scope = scope or (f"#{block.name.lower()}",)
        if scope not in self.places:  # the instance itself: named, its members under it
            self.places[scope] = Place(Address(Area.D, self.next_byte), "Struct")
        key = (*scope, stem.lower())
        if self._lay(key, found[1]) is None:
            return None
        if not bracket:
            return self.sub(key, path[1:])
        place: Place | None = self.places[key]
        member = self.members.get(key)
        for each in index.rstrip("]").split("]["):
            if member is None or place is None:
                return None
            place = element(place, each, self.element_size(member))
            member = self.element_member(member)
        for name in path[1:]:  # a member of a struct element, by its offset
            pair = self.member_at(place, member, name.lower()) \
                if place is not None and member is not None else None
            if pair is None:
                return None
            place, member = pair
        return place

    def global_name(self, path: tuple[str, ...], as_instance: str = "") -> Place | None:
        """A tag (`"Start"`), a global DB member (`"DB".a.b`), or an instance named by use."""
        tag = self.program.tag(path[0]) if len(path) == 1 else None
        if tag is None and len(path) > 1 and self.program.block(path[0]) is None:
            tag = self.program.tag(".".join(path))  # a member of a DB not read, as one name
            path = (tag.name,) if tag is not None else path
        if tag is not None and tag.address:
            try:
                address, _width = parse_absolute(tag.address)
            except AddressError:
                return None
            return Place(address, tag.type_name)
        key: tuple[str, ...] = (path[0].lower(),)
        db = self.program.block(path[0])
        if key not in self.places:
            if db is not None and db.kind in ("GlobalDB", "InstanceDB"):
                members = tuple(m for s in ("Input", "Output", "InOut", "Static")
                                for m in db.members(s))
                type_name = db.instance_of or "Struct"
                if db.instance_of and typed.type_of(db.instance_of) is None \
                        and db.instance_of.lower() in TIMER_TYPES | COUNTER_TYPES:
                    members = ()
                self._lay(key, Member(db.name, type_name, members=members))
            elif as_instance:
                self._lay(key, Member(path[0], as_instance))
            elif tag is not None:  # a tag without an address: laid out as a value
                self._lay(key, Member(tag.name, tag.type_name))
            else:
                return None
        return self.sub(key, path[1:])

    def sub(self, key: tuple[str, ...], rest: tuple[str, ...]) -> Place | None:
        """The place of member path `rest` under the laid-out name `key` (an instance's Q,
        a struct's member), None if there is none."""
        place = self.places.get(key)
        member = self.members.get(key)
        by_offset = False  # inside an array element: members by their offsets
        if place is None:
            return None
        for name in rest:
            low = name.lower()
            kind = place.type_name.lower()
            table = TIMER_MEMBERS if kind in TIMER_TYPES else \
                COUNTER_MEMBERS if kind in COUNTER_TYPES else None
            if table is not None:
                if low not in table:
                    return None
                offset, bit, type_name = table[low]
                base = place.address
                place = Place(Address(base.area, base.byte + offset, bit), type_name)
                continue
            stem, bracket, index = low.partition("[")
            if by_offset:
                pair = self.member_at(place, member, stem) if member is not None else None
                if pair is None:
                    return None
                place, member = pair
            else:
                key = (*key, stem)
                found = self.places.get(key)
                if found is None:
                    return None
                place, member = found, self.members.get(key)
            for each in index.rstrip("]").split("][") if bracket else ():
                if member is None:
                    return None
                inner = element(place, each, self.element_size(member))  # Arr[2], Arr[1][2]
                if inner is None:
                    return None
                place, member, by_offset = inner, self.element_member(member), True
        return place

    def resolve(self, block: Block, operand: Operand, as_instance: str = "",
                scope: tuple[str, ...] = ()) -> Place | None:
        """The place an operand names, None when it names none (a constant included)."""
        if operand.kind is OperandKind.ABSOLUTE:
            try:
                address, width = parse_absolute(operand.path[0])
            except AddressError:
                return None
            names = {1: "Byte", 2: "Int", 4: "DInt"}
            return Place(address, "Bool" if address.bit is not None else names[width])
        if operand.kind is OperandKind.LOCAL:
            found = self.local(block, operand.path, scope)
            if found is not None or operand.text.startswith("#"):
                return found
        if operand.kind is OperandKind.CONSTANT or not operand.path:
            return None
        return self.global_name(operand.path, as_instance)
