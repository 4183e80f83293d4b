"""Small SimaticML documents the XML reader tests build (the project's own, in TIA's form),
and a comparison of S7 graphs that ignores what differs between forms by nature (UIds,
source lines, a non-constant operand's text)."""

from __future__ import annotations

from ladderworks.core.dialects.s7.graph import Block, End, Operand, OperandKind, Part, S7Network

FLGNET = "http://www.siemens.com/automation/Openness/SW/NetworkSource/FlgNet/v4"
INTERFACE = "http://www.siemens.com/automation/Openness/SW/Interface/v4"
_TYPE_KEYS = ("srctype", "time_type", "value_type", "counttype", "count_type", "type")


def document(networks: list[str], *, interface: str = "", kind: str = "OB",
             name: str = "Main", flgnet: str = FLGNET, language: str = "LAD",
             interface_ns: str = INTERFACE, head: str = "") -> str:
    """A block export: `networks` are the inner XML of each FlgNet (Parts, Wires …)."""
    units = []
    scl = "SCL"
    for n, body in enumerate(networks, start=1):
        text = body.lstrip().startswith(("<StructuredText", "<StatementList"))
        source = body if text else f'<FlgNet xmlns="{flgnet}">{body}</FlgNet>'
        kind_of = language if not text else scl if "StructuredText" in body[:20] else "STL"
        units.append(f"""
      <SW.Blocks.CompileUnit ID="{n + 10:X}" CompositionName="CompileUnits">
        <AttributeList>
          <NetworkSource>{source}</NetworkSource>
          <ProgrammingLanguage>{kind_of}</ProgrammingLanguage>
        </AttributeList>
        <ObjectList>
          <MultilingualText ID="{n + 40:X}" CompositionName="Title">
            <ObjectList>
              <MultilingualTextItem ID="{n + 60:X}" CompositionName="Items">
                <AttributeList><Culture>de-DE</Culture><Text>Netzwerk {n}</Text></AttributeList>
              </MultilingualTextItem>
              <MultilingualTextItem ID="{n + 80:X}" CompositionName="Items">
                <AttributeList><Culture>tr-TR</Culture>
                <Text>Network {n} başlığı</Text></AttributeList>
              </MultilingualTextItem>
            </ObjectList>
          </MultilingualText>
        </ObjectList>
      </SW.Blocks.CompileUnit>""")
    return f"""<?xml version="1.0" encoding="utf-8"?>{head}
<Document>
  <Engineering version="V17" />
  <SW.Blocks.{kind} ID="0">
    <AttributeList>
      <Interface><Sections xmlns="{interface_ns}">{interface}</Sections></Interface>
      <Name>{name}</Name>
      <Number>1</Number>
      <ProgrammingLanguage>{language}</ProgrammingLanguage>
    </AttributeList>
    <ObjectList>{"".join(units)}
    </ObjectList>
  </SW.Blocks.{kind}>
</Document>
"""


def tag(uid: int, *names: str, scope: str = "GlobalVariable") -> str:
    """An Access of a symbol (components `names`)."""
    parts = "".join(f'<Component Name="{n}" />' for n in names)
    return f'<Access Scope="{scope}" UId="{uid}"><Symbol>{parts}</Symbol></Access>'


def const(uid: int, value: str, typed: str = "") -> str:
    """An Access of a constant: typed (T#5s) or literal (with its ConstantType)."""
    if not typed:
        return (f'<Access Scope="TypedConstant" UId="{uid}"><Constant><ConstantValue>{value}'
                "</ConstantValue></Constant></Access>")
    return (f'<Access Scope="LiteralConstant" UId="{uid}"><Constant><ConstantType>{typed}'
            f"</ConstantType><ConstantValue>{value}</ConstantValue></Constant></Access>")


def wire(uid: int, *ends: str) -> str:
    """A Wire of its ends: "rail", "uid" (an IdentCon), "uid:pin" (a NameCon), "open"."""
    out = []
    for end in ends:
        if end == "rail":
            out.append("<Powerrail />")
        elif end == "open":
            out.append(f'<OpenCon UId="{uid + 500}" />')
        elif ":" in end:
            part, pin = end.split(":")
            out.append(f'<NameCon UId="{part}" Name="{pin}" />')
        else:
            out.append(f'<IdentCon UId="{end}" />')
    return f'<Wire UId="{uid}">{"".join(out)}</Wire>'


def _operand(op: Operand) -> tuple:
    if op.kind is OperandKind.CONSTANT:
        return (op.kind.value, op.text, op.type_name)
    return (op.kind.value, op.path)


def _template(part: Part) -> tuple:
    found = []
    for key, value in part.template.items():
        low = key.lower()
        if low == "card":
            continue
        found.append(("type" if low in _TYPE_KEYS else key, value))
    return tuple(sorted(found))


def canonical(network: S7Network) -> list:
    """The network as a sorted list of part signatures: each part with its operands and,
    recursively, the parts (or the rail) that feed each of its pins."""
    parts = {p.uid: p for p in network.parts}
    feeds: dict[str, list[tuple[str, End]]] = {}
    operands: dict[str, list[tuple]] = {}
    for wire_ in network.wires:
        for target in wire_.targets:
            if target.part and wire_.source.operand is not None:
                operands.setdefault(target.part, []).append(
                    ("in", target.pin, _operand(wire_.source.operand)))
            elif target.part:
                feeds.setdefault(target.part, []).append((target.pin, wire_.source))
            elif target.operand is not None and wire_.source.part:
                operands.setdefault(wire_.source.part, []).append(
                    ("out", wire_.source.pin, _operand(target.operand)))
    memo: dict[str, tuple] = {}

    def signature(uid: str, depth: int = 0) -> tuple:
        if uid in memo:
            return memo[uid]
        part = parts[uid]
        inputs = []
        for pin, source in feeds.get(uid, []):
            origin: tuple = ("rail",) if source.powerrail else (
                source.pin, signature(source.part, depth + 1)) if depth < 50 else ("deep",)
            inputs.append((pin, origin))
        found = (part.name, tuple(sorted(part.negated)),
                 _operand(part.instance) if part.instance else None, _template(part),
                 part.call, part.label, part.dests,  # call_kind: SD does not know it
                 tuple(sorted(operands.get(uid, []))), tuple(sorted(inputs, key=repr)))
        memo[uid] = found
        return found

    return sorted((signature(uid) for uid in parts), key=repr)


def same_block(first: Block, second: Block) -> list[str]:
    """The differences between two blocks' graphs ([] when the same)."""
    problems = []
    for field in ("kind", "name", "language", "return_type", "instance_of"):
        if field == "return_type" and first.kind not in ("FC", "FB", "OB"):
            continue  # the SD reader keeps an instance DB's FB there too
        if getattr(first, field) != getattr(second, field):
            problems.append(field)
    if first.sections != second.sections:
        problems.append("sections")
    if len(first.networks) != len(second.networks):
        return [*problems, "network count"]
    for n, (a, b) in enumerate(zip(first.networks, second.networks, strict=True), start=1):
        if (a.language, a.source) != (b.language, b.source):
            problems.append(f"network {n} language/source")
        if canonical(a) != canonical(b):
            problems.append(f"network {n} graph")
    return problems
