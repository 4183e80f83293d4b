"""SimaticML's spellings: namespaces, pin names and absolute addresses, both ways.

The XML reader (xml_reader.py) maps them onto the S7 graph's spellings (graph.py: lower-case
pins, a part's power input named as the SD reader names it); the writer (xml_writer.py) maps
them back. docs/dialects.md, "SimaticML XML".
"""

from __future__ import annotations

import re

OPENNESS = "http://www.siemens.com/automation/Openness/SW/"
# the versions read (unversioned, v1 … v5); V16 writes v3, V17 v4, V19–V21 v5
KNOWN_VERSIONS = (0, 1, 2, 3, 4, 5)
_NS_RE = re.compile(re.escape(OPENNESS) + r"(?P<kind>[A-Za-z/]+?)(?:/v(?P<version>\d+))?$")

# parts whose power input SimaticML calls "pre" (LAD comparison contacts and ranges)
PRE_PARTS = frozenset({"Eq", "Ne", "Gt", "Lt", "Ge", "Le", "InRange", "OutRange", "Ok", "NotOk"})
# parts whose power input SimaticML calls "in" where the SD reader says "en"
EN_PARTS = frozenset({"Jump", "JumpN", "Return"})
# parts whose pins TIA writes in capitals (IN, PT, Q, ET; CU, R, PV, CV …)
UPPER_PINS = frozenset({"TP", "TON", "TOF", "TONR", "CTU", "CTD", "CTUD", "PTCoil", "RTCoil"})

_AREAS = {"Input": "I", "Output": "Q", "Memory": "M", "PeripheryInput": "I",
          "PeripheryOutput": "Q", "DB": "DB", "DI": "DI", "Local": "L"}
_WIDTHS = {"Bool": "", "Byte": "B", "Char": "B", "SInt": "B", "USInt": "B", "Word": "W",
           "Int": "W", "UInt": "W", "DWord": "D", "DInt": "D", "UDInt": "D", "Real": "D",
           "Time": "D"}
_ABS_RE = re.compile(r"^%(?:(?P<db>DB|DI)(?P<num>\d+)\.DB(?P<dw>[XBWD])|(?P<area>[IQML])"
                     r"(?P<w>[BWD]?))(?P<byte>\d+)(?:\.(?P<bit>[0-7]))?(?P<p>:P)?$", re.I)


def namespace(uri: str) -> tuple[str, int] | None:
    """(kind, version) of an Openness namespace ("NetworkSource/FlgNet", 4); None if foreign."""
    found = _NS_RE.match(uri)
    if found is None:
        return None
    return found.group("kind"), int(found.group("version") or 0)


# SimaticML's names of LAD parts the graph names otherwise (P_TRIG/N_TRIG as LAD boxes)
_PARTS_IN = {"PBox": "PTrig", "NBox": "NTrig"}
_PARTS_OUT = {graph: xml for xml, graph in _PARTS_IN.items()}


def part_in(name: str) -> str:
    """A SimaticML `Part Name` as the graph names it."""
    return _PARTS_IN.get(name, name)


def part_out(name: str) -> str:
    """A graph part name as SimaticML's LAD spells it."""
    return _PARTS_OUT.get(name, name)


def pin_in(part_name: str, pin: str) -> str:
    """A SimaticML pin name as the graph spells it."""
    low = pin.lower()
    if low == "pre" and part_name in PRE_PARTS:
        return "in"
    if low == "in" and part_name in EN_PARTS:
        return "en"
    return low


def pin_out(part_name: str, pin: str) -> str:
    """A graph pin name as SimaticML spells it."""
    if pin == "in" and part_name in PRE_PARTS:
        return "pre"
    if pin == "en" and part_name in EN_PARTS:
        return "in"
    if part_name in UPPER_PINS and pin not in ("en", "eno"):
        return pin.upper()
    return pin


def address_text(attrs: dict[str, str]) -> str:
    """An `<Address Area= Type= BitOffset= BlockNumber=>` as TIA writes it: %I0.0, %MW2,
    %DB1.DBW4; "" when it cannot be spelled."""
    area = _AREAS.get(attrs.get("Area", ""))
    offset = attrs.get("BitOffset", "")
    if area is None or not offset.isdigit():
        return ""
    byte, bit = divmod(int(offset), 8)
    kind = attrs.get("Type", "Bool")
    width = _WIDTHS.get(kind, "B")
    suffix = ":P" if attrs.get("Area", "").startswith("Periphery") else ""
    if area in ("DB", "DI"):
        number = attrs.get("BlockNumber", "")
        dw = width or "X"
        place = f"{byte}.{bit}" if dw == "X" else str(byte)
        return f"%{area}{number}.DB{dw}{place}"
    if width:
        return f"%{area}{width}{byte}{suffix}"
    return f"%{area}{byte}.{bit}{suffix}"


def address_attrs(text: str) -> dict[str, str] | None:
    """The `<Address>` attributes of an absolute address text (the inverse of address_text)."""
    found = _ABS_RE.match(text.strip())
    if found is None:
        return None
    byte, bit = int(found.group("byte")), int(found.group("bit") or 0)
    names = {"B": "Byte", "W": "Word", "D": "DWord", "X": "Bool", "": "Bool"}
    if found.group("db"):
        return {"Area": found.group("db").upper(), "Type": names[found.group("dw").upper()],
                "BlockNumber": found.group("num"), "BitOffset": str(byte * 8 + bit)}
    area = {"I": "Input", "Q": "Output", "M": "Memory", "L": "Local"}[found.group("area").upper()]
    if found.group("p"):
        area = "Periphery" + area
    return {"Area": area, "Type": names[found.group("w").upper()],
            "BitOffset": str(byte * 8 + bit)}
