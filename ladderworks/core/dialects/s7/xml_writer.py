"""Write a block of the S7 graph as a SimaticML document (TIA Openness import form).

Used to write the project's XML examples from its own graphs and to test that the reader
reads back what was written; `version` picks the FlgNet/Interface namespace (0 = unversioned,
1 … 5). docs/dialects.md, "SimaticML XML".
"""

from __future__ import annotations

from xml.sax.saxutils import escape, quoteattr

from ladderworks.core.dialects.s7.graph import (
    Block,
    End,
    Member,
    Operand,
    OperandKind,
    Part,
    S7Network,
)
from ladderworks.core.dialects.s7.xml_forms import OPENNESS, address_attrs, part_out, pin_out

ENGINEERING = {0: "V14", 1: "V15", 2: "V15.1", 3: "V16", 4: "V17", 5: "V19"}
_TAGS = {"OB": "SW.Blocks.OB", "FB": "SW.Blocks.FB", "FC": "SW.Blocks.FC",
         "GlobalDB": "SW.Blocks.GlobalDB", "InstanceDB": "SW.Blocks.InstanceDB"}
Texts = dict[tuple[int, str], dict[str, str]]  # (network index or 0, "title"/"comment") → cultures


def _ns(kind: str, version: int) -> str:
    return OPENNESS + kind + (f"/v{version}" if version else "")


class _Ids:
    def __init__(self) -> None:
        self.next = 0

    def take(self) -> str:
        value = f"{self.next:X}"
        self.next += 1
        return value


def _text_xml(ids: _Ids, kind: str, cultures: dict[str, str], pad: str) -> list[str]:
    lines = [f'{pad}<MultilingualText ID="{ids.take()}" CompositionName="{kind}">',
             f"{pad}  <ObjectList>"]
    for culture, text in cultures.items():
        lines += [f'{pad}    <MultilingualTextItem ID="{ids.take()}" CompositionName="Items">',
                  f"{pad}      <AttributeList>",
                  f"{pad}        <Culture>{escape(culture)}</Culture>",
                  f"{pad}        <Text>{escape(text)}</Text>",
                  f"{pad}      </AttributeList>",
                  f"{pad}    </MultilingualTextItem>"]
    return [*lines, f"{pad}  </ObjectList>", f"{pad}</MultilingualText>"]


def _member(member: Member, pad: str) -> list[str]:
    head = f"{pad}<Member Name={quoteattr(member.name)} Datatype={quoteattr(member.type_name)}"
    if not member.members and not member.start:
        return [head + " />"]
    lines = [head + ">"]
    for inner in member.members:
        lines += _member(inner, pad + "  ")
    if member.start:
        lines.append(f"{pad}  <StartValue>{escape(member.start)}</StartValue>")
    return [*lines, f"{pad}</Member>"]


def _components(path: tuple[str, ...], pad: str) -> list[str]:
    lines = []
    for name in path:
        base, _sep, index = name.partition("[")
        if not index:
            lines.append(f"{pad}<Component Name={quoteattr(name)} />")
            continue
        lines += [f'{pad}<Component Name={quoteattr(base)} AccessModifier="Array">',
                  f'{pad}  <Access Scope="LiteralConstant"><Constant><ConstantType>DInt'
                  f"</ConstantType><ConstantValue>{escape(index.rstrip(']'))}</ConstantValue>"
                  "</Constant></Access>",
                  f"{pad}</Component>"]
    return lines


def _access(uid: str, operand: Operand, pad: str) -> list[str]:
    if operand.kind is OperandKind.CONSTANT:
        value = escape(operand.text)
        if operand.type_name and operand.type_name != "Bool":
            return [f'{pad}<Access Scope="TypedConstant" UId="{uid}"><Constant><ConstantValue>'
                    f"{value}</ConstantValue></Constant></Access>"]
        kind = "Bool" if operand.type_name == "Bool" else "Real" if "." in operand.text \
            else "Int"
        return [f'{pad}<Access Scope="LiteralConstant" UId="{uid}"><Constant><ConstantType>'
                f"{kind}</ConstantType><ConstantValue>{value}</ConstantValue></Constant></Access>"]
    if operand.kind is OperandKind.ABSOLUTE:
        attrs = address_attrs(operand.path[0] if operand.path else operand.text) or {}
        text = " ".join(f"{k}={quoteattr(v)}" for k, v in attrs.items())
        return [f'{pad}<Access Scope="GlobalVariable" UId="{uid}"><Address {text} /></Access>']
    scope = "LocalVariable" if operand.kind is OperandKind.LOCAL else "GlobalVariable"
    return [f'{pad}<Access Scope="{scope}" UId="{uid}">', f"{pad}  <Symbol>",
            *_components(operand.path, pad + "    "), f"{pad}  </Symbol>", f"{pad}</Access>"]


def _part(part: Part, uid: str, ids: dict[str, str], pad: str,
          blocks: dict[str, Block]) -> list[str]:
    if part.name == "Call":
        called = blocks.get(part.call.lower())
        name, kind, instance = part.call, part.call_kind or "FC", part.instance
        if called is not None and called.kind == "InstanceDB":  # an FB on its instance DB
            name, kind = called.instance_of, "FB"
            instance = Operand(OperandKind.GLOBAL, (called.name,))
        elif called is not None:
            kind = called.kind
        lines = [f'{pad}<Call UId="{uid}">',
                 f'{pad}  <CallInfo Name={quoteattr(name)} BlockType="{kind}">']
        if instance is not None:
            lines += _instance(instance, ids, pad + "    ")
        return [*lines, f"{pad}  </CallInfo>", f"{pad}</Call>"]
    inner: list[str] = []
    for pin in sorted(part.negated):
        inner.append(f"{pad}  <Negated Name={quoteattr(pin_out(part.name, pin))} />")
    if part.instance is not None:
        inner += _instance(part.instance, ids, pad + "  ")
    for key, value in part.template.items():
        if key == "else" or (key.startswith("op") and part.name == "Switch"):
            continue
        kind = "Cardinality" if key == "Card" else "Type"
        inner.append(f"{pad}  <TemplateValue Name={quoteattr(key)} Type=\"{kind}\">"
                     f"{escape(value)}</TemplateValue>")
    head = f"{pad}<Part Name={quoteattr(part_out(part.name))} UId=\"{uid}\"" + (
        ' DisabledENO="true"' if part.disabled_eno else "")
    return [head + " />"] if not inner else [head + ">", *inner, f"{pad}</Part>"]


def _instance(operand: Operand, ids: dict[str, str], pad: str) -> list[str]:
    scope = "LocalVariable" if operand.kind is OperandKind.LOCAL else "GlobalVariable"
    uid = ids.setdefault(f"instance{len(ids)}", str(100 + len(ids)))
    return [f'{pad}<Instance Scope="{scope}" UId="{uid}">',
            *_components(operand.path, pad + "  "), f"{pad}</Instance>"]


def _flgnet(network_parts: list[Part], wires: list, version: int, pad: str,
            blocks: dict[str, Block]) -> list[str]:
    uids: dict[str, str] = {}
    counter = iter(range(21, 100000))
    accesses: list[str] = []
    wire_lines: list[str] = []
    labels = [p for p in network_parts if p.name == "Label"]
    for part in network_parts:
        uids[part.uid] = str(next(counter))

    def end(e: End) -> str:
        if e.powerrail:
            return "<Powerrail />"
        if e.operand is not None:
            uid = str(next(counter))
            accesses.extend(_access(uid, e.operand, pad + "    "))
            return f'<IdentCon UId="{uid}" />'
        part = next(p for p in network_parts if p.uid == e.part)
        return f'<NameCon UId="{uids[e.part]}" Name={quoteattr(pin_out(part.name, e.pin))} />'

    def label_wire(source: str, label: str) -> None:
        uid = str(next(counter))
        accesses.append(f'{pad}    <Access Scope="Label" UId="{uid}"><Label '
                        f"Name={quoteattr(label)} /></Access>")
        wire_lines.append(f'{pad}    <Wire UId="{next(counter)}">{source}'
                          f'<IdentCon UId="{uid}" /></Wire>')

    for wire in wires:
        text = "".join(end(e) for e in [wire.source, *wire.targets])
        wire_lines.append(f'{pad}    <Wire UId="{next(counter)}">{text}</Wire>')
    for part in network_parts:
        if part.name in ("Jump", "JumpN") and part.label:
            label_wire(f'<NameCon UId="{uids[part.uid]}" Name="label" />', part.label)
        for n, dest in enumerate(part.dests):
            if part.name == "Switch":
                label_wire(f'<NameCon UId="{uids[part.uid]}" Name="dest{n}" />', dest)
            else:
                label_wire(f'<NameCon UId="{uids[part.uid]}" Name="dest{n}" />', dest)
        if part.name == "Switch" and part.template.get("else"):
            label_wire(f'<NameCon UId="{uids[part.uid]}" Name="else" />', part.template["else"])
    ids: dict[str, str] = {}
    lines = [f'{pad}<FlgNet xmlns="{_ns("NetworkSource/FlgNet", version)}">']
    if labels:
        lines.append(f"{pad}  <Labels>")
        for part in labels:
            lines += [f'{pad}    <LabelDeclaration UId="{uids[part.uid]}">',
                      f"{pad}      <Label Name={quoteattr(part.label)} />",
                      f"{pad}    </LabelDeclaration>"]
        lines.append(f"{pad}  </Labels>")
    lines += [f"{pad}  <Parts>", *accesses]
    for part in network_parts:
        if part.name != "Label":
            lines += _part(part, uids[part.uid], ids, pad + "    ", blocks)
    return [*lines, f"{pad}  </Parts>", f"{pad}  <Wires>", *wire_lines, f"{pad}  </Wires>",
            f"{pad}</FlgNet>"]


def flgnet_lines(network: S7Network, version: int = 5,
                 others: list[Block] | None = None) -> list[str]:
    """One LAD network's `FlgNet` element as lines (no indentation, as TIA writes it)."""
    blocks = {b.name.lower(): b for b in others or []}
    return _flgnet(network.parts, network.wires, version, "", blocks)


def unit_lines(network: S7Network, version: int, first_id: int,
               others: list[Block] | None = None) -> tuple[list[str], int]:
    """A whole `SW.Blocks.CompileUnit` of a new network (its texts in en-US), unindented, its
    document IDs from `first_id` on; and the next free ID."""
    ids = _Ids()
    ids.next = first_id
    lines = [f'<SW.Blocks.CompileUnit ID="{ids.take()}" CompositionName="CompileUnits">',
             "  <AttributeList>", "    <NetworkSource>"]
    lines += ["      " + line for line in flgnet_lines(network, version, others)]
    lines += ["    </NetworkSource>",
              f"    <ProgrammingLanguage>{escape(network.language)}</ProgrammingLanguage>",
              "  </AttributeList>", "  <ObjectList>"]
    for kind in ("comment", "title"):
        lines += _text_xml(ids, kind.capitalize(), {"en-US": getattr(network, kind)}, "    ")
    return [*lines, "  </ObjectList>", "</SW.Blocks.CompileUnit>"], ids.next


def write_block(block: Block, version: int = 5, texts: Texts | None = None,
                others: list[Block] | None = None) -> str:
    """The SimaticML document of one block (UTF-8 text with a declaration); `others`, the
    program's other blocks, tell an FB called on its instance DB from an FC."""
    texts = texts or {}
    blocks = {b.name.lower(): b for b in others or []}
    ids = _Ids()
    tag = _TAGS[block.kind]
    lines = ['<?xml version="1.0" encoding="utf-8"?>', "<Document>",
             f'  <Engineering version="{ENGINEERING.get(version, "V19")}" />',
             f'  <{tag} ID="{ids.take()}">', "    <AttributeList>", "      <Interface>",
             f'        <Sections xmlns="{_ns("Interface", version)}">']
    sections = dict(block.sections)
    if block.kind == "FC":
        sections["Return"] = [Member("Ret_Val", block.return_type or "Void")]
    for name, members in sections.items():
        if not members:
            lines.append(f'          <Section Name="{name}" />')
            continue
        lines.append(f'          <Section Name="{name}">')
        for member in members:
            lines += _member(member, "            ")
        lines.append("          </Section>")
    lines += ["        </Sections>", "      </Interface>",
              "      <MemoryLayout>Optimized</MemoryLayout>",
              f"      <Name>{escape(block.name)}</Name>"]
    if block.instance_of:
        lines.append(f"      <InstanceOfName>{escape(block.instance_of)}</InstanceOfName>")
    if block.number:
        lines.append(f"      <Number>{block.number}</Number>")
    lines += [f"      <ProgrammingLanguage>{escape(block.language)}</ProgrammingLanguage>",
              "    </AttributeList>", "    <ObjectList>"]
    if texts.get((0, "comment")):
        lines += _text_xml(ids, "Comment", texts[(0, "comment")], "      ")
    for index, network in enumerate(block.networks, start=1):
        lines += [f'      <SW.Blocks.CompileUnit ID="{ids.take()}" CompositionName="CompileUnits">',
                  "        <AttributeList>", "          <NetworkSource>"]
        lines += _flgnet(network.parts, network.wires, version, "            ", blocks)
        lines += ["          </NetworkSource>",
                  f"          <ProgrammingLanguage>{escape(network.language)}"
                  "</ProgrammingLanguage>", "        </AttributeList>", "        <ObjectList>"]
        for kind in ("comment", "title"):
            cultures = texts.get((index, kind)) or ({"en-US": getattr(network, kind)}
                                                    if getattr(network, kind) else {})
            lines += _text_xml(ids, kind.capitalize(), cultures, "          ")
        lines += ["        </ObjectList>", "      </SW.Blocks.CompileUnit>"]
    if texts.get((0, "title")):
        lines += _text_xml(ids, "Title", texts[(0, "title")], "      ")
    lines += ["    </ObjectList>", f"  </{tag}>", "</Document>", ""]
    return "\n".join(lines)
