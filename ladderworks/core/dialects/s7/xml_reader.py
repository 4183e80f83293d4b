"""Read SimaticML (TIA Openness block exports, XML) into the S7 graph (graph.py).

`SW.Blocks.OB|FB|FC|GlobalDB|InstanceDB` with their interface, each `SW.Blocks.CompileUnit` a
network: a `FlgNet` (LAD/FBD: `Parts` of `Access`/`Part`/`Call`, `Wires` of `Powerrail`,
`NameCon`, `IdentCon`, `OpenCon`) or SCL/STL text kept as text. `SW.Tags.PlcTagTable` gives
tags. The SD reader builds the same graph for the same program (tests/core/test_s7_xml.py).
docs/dialects.md, "SimaticML XML".
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7.graph import (
    PART_NAMES,
    SECTIONS,
    Block,
    End,
    Member,
    Operand,
    OperandKind,
    Part,
    S7Network,
    Tag,
    Wire,
)
from ladderworks.core.dialects.s7.texts import pick
from ladderworks.core.dialects.s7.xml_fbd import to_lad
from ladderworks.core.dialects.s7.xml_forms import (
    KNOWN_VERSIONS,
    address_text,
    namespace,
    part_in,
    pin_in,
)
from ladderworks.core.dialects.s7.xml_safe import Element, XmlRefused, parse
from ladderworks.core.dialects.s7.xml_text import component, graph_text, source_text

BLOCK_KINDS = {"SW.Blocks.OB": "OB", "SW.Blocks.FB": "FB", "SW.Blocks.FC": "FC",
               "SW.Blocks.GlobalDB": "GlobalDB", "SW.Blocks.InstanceDB": "InstanceDB"}
MAX_PARTS = 400  # parts per network; TIA's own networks stay far below
_CONSTANT_SCOPES = ("LiteralConstant", "TypedConstant")
_SWITCH_PIN = re.compile(r"^(eq|ne|lt|gt|le|ge)(\d+)$")


@dataclass(slots=True)
class XmlRead:
    """What one SimaticML document holds: blocks, tags, every culture of every text, the
    engineering version, and the diagnostics of reading it."""

    blocks: list[Block] = field(default_factory=list)
    tags: list[Tag] = field(default_factory=list)
    texts: dict[tuple[str, int, str], dict[str, str]] = field(default_factory=dict)
    version: str = ""
    diagnostics: list[Diagnostic] = field(default_factory=list)
    instances: dict[str, str] = field(default_factory=dict)  # instance DB → its FB (calls)


def _subelements(node: Element) -> str:
    """An array member's `<Subelement Path="i"><StartValue>` as an initializer `[a, , b]`
    (from the array's low bound; "" when it has none, or a path of several dimensions)."""
    found: dict[int, str] = {}
    for sub in node.all("Subelement"):
        value = sub.find("StartValue")
        path = sub.attrs.get("Path", "")
        if value is not None and re.fullmatch(r"-?\d{1,6}", path):
            found[int(path)] = value.text.strip()
    bounds = re.match(r"(?i)^array\s*\[\s*(-?\d+)", node.attrs.get("Datatype", "").strip())
    if not found or bounds is None:
        return ""
    low = int(bounds.group(1))
    if min(found) < low or max(found) - low > 100_000:
        return ""
    return "[" + ", ".join(found.get(i, "") for i in range(low, max(found) + 1)) + "]"


EXPORT_KINDS = ("SW.Blocks.", "SW.Types.PlcStruct", "SW.Tags.PlcTagTable")


def is_simaticml(text: str) -> bool:
    """True for a SimaticML document of blocks, a PLC data type or a tag table (the last two
    open with their folder's blocks)."""
    head, body = text[:4000], text[:200000]
    return "<Document" in head and any(kind in body for kind in EXPORT_KINDS)


def _multilingual(node: Element | None) -> dict[str, str]:
    """{culture: text} of a `MultilingualText` element."""
    found: dict[str, str] = {}
    if node is None:
        return found
    for item in node.walk():
        if item.name == "MultilingualTextItem":
            attributes = item.child("AttributeList") or item
            culture = attributes.text_of("Culture")
            if culture:
                found[culture] = attributes.text_of("Text")
    return found


def _texts(owner: Element) -> dict[str, dict[str, str]]:
    """The `MultilingualText`s an element's ObjectList holds, by CompositionName."""
    found: dict[str, dict[str, str]] = {}
    objects = owner.child("ObjectList")
    for node in objects.all("MultilingualText") if objects is not None else []:
        found[node.attrs.get("CompositionName", "")] = _multilingual(node)
    return found


def _chosen(cultures: dict[str, str]) -> str:
    return pick({"x": cultures}, "x")


class _Reader:
    """One document's blocks."""

    def __init__(self, root: Element) -> None:
        self.root = root
        self.out = XmlRead()
        self.dests: dict[str, dict[int, str]] = {}  # a network's JumpList/Switch DEST n

    def warn(self, code: str, line: int, **args: object) -> None:
        self.out.diagnostics.append(Diagnostic(code, dict(args), line, 1, Severity.WARNING))

    def error(self, code: str, line: int, **args: object) -> None:
        self.out.diagnostics.append(Diagnostic(code, dict(args), line, 1))

    def run(self) -> XmlRead:
        engineering = self.root.child("Engineering")
        self.out.version = engineering.attrs.get("version", "") if engineering else ""
        tables = 0  # an empty tag table (TIA's "Default tag table" often is) is no error
        for node in self.root.children:  # blocks and tag tables are the Document's children
            kind = BLOCK_KINDS.get(node.name)
            if kind is not None:
                self.out.blocks.append(self.block(node, kind))
            elif node.name == "SW.Tags.PlcTagTable":
                self.tag_table(node)
                tables += 1
            elif node.name == "SW.Types.PlcStruct":  # a PLC data type (UDT): its members
                self.out.blocks.append(self.plc_type(node))
        if not self.out.blocks and not self.out.tags and not tables:
            self.error("s7xml-empty", self.root.line)
        return self.out

    # -- tags -----------------------------------------------------------------------------
    def tag_table(self, node: Element) -> None:
        table = node.find("AttributeList", "Name")
        name = table.text.strip() if table is not None else ""
        for tag in node.walk():
            if tag.name in ("SW.Tags.PlcTag", "SW.Tags.PlcUserConstant"):
                attributes = tag.child("AttributeList") or tag
                comment = _chosen(_texts(tag).get("Comment", {}))
                self.out.tags.append(Tag(attributes.text_of("Name"),
                                         attributes.text_of("DataTypeName"),
                                         attributes.text_of("LogicalAddress"), comment, name,
                                         attributes.text_of("Value")))

    # -- blocks ---------------------------------------------------------------------------
    def block(self, node: Element, kind: str) -> Block:
        attributes = node.child("AttributeList") or node
        name = attributes.text_of("Name")
        number = attributes.text_of("Number")
        block = Block(kind, name, int(number) if number.isdigit() else 0)
        block.language = attributes.text_of("ProgrammingLanguage") or "LAD"
        block.instance_of = attributes.text_of("InstanceOfName")
        sections = attributes.find("Interface", "Sections")
        if sections is not None:
            self.check_ns(sections, "Interface", 0, name)
            for section in sections.all("Section"):
                section_name = section.attrs.get("Name", "")
                if section_name in SECTIONS:
                    block.sections[section_name] = [self.member(m) for m in section.all("Member")]
        returns = block.sections.pop("Return", None)
        if returns:
            block.return_type = returns[0].type_name
        texts = _texts(node)
        block.title = _chosen(texts.get("Title", {}))
        block.comment = _chosen(texts.get("Comment", {}))
        for culture_kind in ("Title", "Comment"):
            if texts.get(culture_kind):
                self.out.texts[(name, 0, culture_kind.lower())] = texts[culture_kind]
        objects = node.child("ObjectList")
        units = [u for u in objects.all("SW.Blocks.CompileUnit")] if objects is not None else []
        for index, unit in enumerate(units, start=1):
            block.networks.append(self.network(block, index, unit))
        return block

    def plc_type(self, node: Element) -> Block:
        """A `SW.Types.PlcStruct` as a `Type` block, its members under Static (as the SD
        reader has a `.udt` source's)."""
        attributes = node.child("AttributeList") or node
        block = Block("Type", attributes.text_of("Name"))
        sections = attributes.find("Interface", "Sections")
        if sections is not None:
            self.check_ns(sections, "Interface", 0, block.name)
            block.sections["Static"] = [self.member(m) for s in sections.all("Section")
                                        for m in s.all("Member")]
        return block

    def member(self, node: Element) -> Member:
        start = node.find("StartValue")
        comment = node.child("Comment")
        text = ""
        if comment is not None:
            cultures = {c.attrs.get("Lang", ""): c.text.strip() for c in comment.walk()
                        if c.name == "MultiLanguageText"}
            text = _chosen(cultures)
        inner = tuple(self.member(m) for m in node.all("Member"))
        sections = node.child("Sections")  # an FB/UDT-typed member's expanded interface
        if sections is not None and not inner:
            inner = tuple(self.member(m) for s in sections.all("Section") for m in s.all("Member"))
        start_text = start.text.strip() if start is not None else ""
        elements = _subelements(node)
        return Member(node.attrs.get("Name", ""), node.attrs.get("Datatype", ""),
                      elements or start_text, text, inner)

    def check_ns(self, node: Element, kind: str, network: int, block: str) -> bool:
        """False (with an error) for a foreign namespace; a newer version: a warning."""
        if not node.ns:
            return True
        found = namespace(node.ns)
        if found is None or not found[0].endswith(kind):
            self.error("s7xml-namespace", node.line, block=block, network=network, uri=node.ns)
            return False
        if found[1] not in KNOWN_VERSIONS:
            self.warn("s7xml-version", node.line, block=block, network=network, kind=kind,
                      version=found[1])
        return True

    # -- networks -------------------------------------------------------------------------
    def network(self, block: Block, index: int, unit: Element) -> S7Network:
        attributes = unit.child("AttributeList") or unit
        language = attributes.text_of("ProgrammingLanguage") or block.language or "LAD"
        language = language.removeprefix("F_")
        network = S7Network(language=language, line=unit.line)
        texts = _texts(unit)
        network.title = _chosen(texts.get("Title", {}))
        network.comment = _chosen(texts.get("Comment", {}))
        for culture_kind in ("Title", "Comment"):
            if texts.get(culture_kind):
                self.out.texts[(block.name, index, culture_kind.lower())] = texts[culture_kind]
        source = attributes.child("NetworkSource")
        body = source.children[0] if source is not None and source.children else None
        if body is None:
            return network
        if body.name == "FlgNet":
            if self.check_ns(body, "FlgNet", index, block.name):
                self.flgnet(block, index, network, body)
                if network.language == "FBD" and network.parts:
                    to_lad(network)
            if network.language not in ("LAD", "FBD"):
                network.language = "LAD"
        else:
            network.source = graph_text(body) if body.name == "Graph" else source_text(body)
            if network.language in ("LAD", "FBD"):
                network.language = {"StructuredText": "SCL", "Graph": "GRAPH"}.get(body.name, "STL")
        return network

    def flgnet(self, block: Block, index: int, network: S7Network, net: Element) -> None:
        where = {"block": block.name, "network": index}
        self.dests = {}
        accesses: dict[str, tuple[Operand | None, str, int]] = {}  # uid → (operand, label, line)
        labels = net.child("Labels")
        for declaration in labels.all("LabelDeclaration") if labels is not None else []:
            label = declaration.find("Label")
            if label is not None:
                network.parts.append(Part(declaration.attrs.get("UId", f"L{len(network.parts)}"),
                                          "Label", label=label.attrs.get("Name", "")))
        parts = net.child("Parts")
        for node in parts.children if parts is not None else []:
            uid = node.attrs.get("UId", "")
            if node.name == "Access":
                scope = node.attrs.get("Scope", "")
                if scope == "Label":
                    label = node.find("Label")
                    accesses[uid] = (None, label.attrs.get("Name", "") if label else "",
                                     node.line)
                else:
                    operand = self.operand(node)
                    if operand.kind is not OperandKind.CONSTANT and not operand.path:
                        operand = Operand(operand.kind, (), f"<{scope}>")  # named in the lowering
                        self.warn("s7xml-access", node.line, uid=uid, scope=scope, **where)
                    accesses[uid] = (operand, "", node.line)
            elif node.name in ("Part", "Call"):
                if len(network.parts) >= MAX_PARTS:
                    self.error("s7xml-too-many", node.line, limit=MAX_PARTS, **where)
                    network.parts.clear()
                    return
                part = self.part(node, where)
                network.parts.append(part)
        uids = {p.uid: p for p in network.parts}
        wires = net.child("Wires")
        for node in wires.all("Wire") if wires is not None else []:
            self.wire(node, network, uids, accesses, where)
        for wire in network.wires:  # SWITCH: the comparison of each case is in its pin's name
            for target in wire.targets:
                switch = uids.get(target.part)
                found = _SWITCH_PIN.match(target.pin) if switch and switch.name == "Switch" \
                    else None
                if switch is not None and found is not None:
                    switch.template[f"op{found.group(2)}"] = found.group(1).upper()
        self.find_loop(network, where)

    def part(self, node: Element, where: dict[str, object]) -> Part:
        uid = node.attrs.get("UId", "")
        if node.name == "Call":
            return self.call(node, uid)
        name = part_in(node.attrs.get("Name", ""))
        part = Part(uid, name, line=node.line,
                    disabled_eno=node.attrs.get("DisabledENO", "").lower() == "true")
        if name not in PART_NAMES:
            self.warn("s7xml-part", node.line, uid=uid, part=name, **where)
        part.negated = frozenset(pin_in(name, n.attrs.get("Name", ""))
                                 for n in node.all("Negated"))
        instance = node.child("Instance")
        if instance is not None:
            part.instance = self.operand(instance)
        for value in node.all("TemplateValue"):
            part.template[value.attrs.get("Name", "")] = value.text.strip()
        return part

    def call(self, node: Element, uid: str) -> Part:
        """A Call as the SD reader has it: an FC by its name; an FB by its instance — a global
        instance DB by the DB's name (its FB remembered in `instances`), a multi-instance by
        the local member."""
        info = node.child("CallInfo") or node
        name = info.attrs.get("Name", "")
        kind = "FB" if info.attrs.get("BlockType", "") in ("FB", "SFB") else \
            info.attrs.get("BlockType", "") or "FC"
        instance = info.child("Instance") or node.child("Instance")
        if kind != "FB" or instance is None:
            return Part(uid, "Call", call=name, call_kind=kind, line=node.line)
        operand = self.operand(instance)
        path = ".".join(operand.path)
        if operand.kind is OperandKind.LOCAL:
            return Part(uid, "Call", call=path, call_kind="FB", instance=operand, line=node.line)
        self.out.instances.setdefault(path, name)
        return Part(uid, "Call", call=path, call_kind="FB", line=node.line)

    def operand(self, node: Element) -> Operand:
        """An `Access` (or `Instance`) as an Operand."""
        scope = node.attrs.get("Scope", "")
        if scope in _CONSTANT_SCOPES:
            constant = node.child("Constant")
            value = constant.text_of("ConstantValue") if constant is not None else ""
            if value.upper() in ("TRUE", "FALSE"):
                return Operand(OperandKind.CONSTANT, (), value.upper(), "Bool")
            head, sep, _rest = value.partition("#")
            typed = head if scope == "TypedConstant" and sep and not head.isdigit() else ""
            return Operand(OperandKind.CONSTANT, (), value, typed)
        if scope in ("GlobalConstant", "LocalConstant"):
            constant = node.child("Constant")
            name = constant.attrs.get("Name", "") if constant is not None else ""
            kind = OperandKind.LOCAL if scope == "LocalConstant" else OperandKind.GLOBAL
            return Operand(kind, (name,), ("#" if kind is OperandKind.LOCAL else "") + name)
        symbol = node.child("Symbol")
        address = node.child("Address")
        if symbol is None and address is not None:  # an absolute access: %I0.0, %MW2
            text = address_text(address.attrs)
            return Operand(OperandKind.ABSOLUTE, (text,), text)
        components = symbol.all("Component") if symbol is not None else node.all("Component")
        path = tuple(component(c) for c in components)
        where = symbol.child("Address") if symbol is not None else None
        kind = OperandKind.LOCAL if scope in ("LocalVariable", "LocalConstant") \
            else OperandKind.GLOBAL
        found = Operand(kind, path, "", "", address_text(where.attrs) if where else "")
        # the text as written (`#x` is strictly a member of the block, as in SD)
        return Operand(kind, path, found.display(), "", found.address)

    def wire(self, node: Element, network: S7Network, uids: dict[str, Part],
             accesses: dict[str, tuple[Operand | None, str, int]],
             where: dict[str, object]) -> None:
        ends: list[End | str] = []  # an End, or a label name (str)
        for con in node.children:
            uid = con.attrs.get("UId", "")
            if con.name == "Powerrail":
                ends.append(End(powerrail=True))
            elif con.name == "NameCon":
                part = uids.get(uid)
                if part is None:
                    self.error("s7xml-wire", con.line, wire=node.attrs.get("UId", ""), uid=uid,
                               **where)
                    return
                ends.append(End(part=uid, pin=pin_in(part.name, con.attrs.get("Name", ""))))
            elif con.name == "IdentCon":
                found = accesses.get(uid)
                if found is None:
                    self.error("s7xml-wire", con.line, wire=node.attrs.get("UId", ""), uid=uid,
                               **where)
                    return
                operand, label, _line = found
                ends.append(End(operand=operand) if operand is not None else label)
            # OpenCon: an open pin, nothing to draw
        if len(ends) < 2 or isinstance(ends[0], str):
            if len(ends) == 2 and isinstance(ends[0], str) and isinstance(ends[1], End):
                self.label_pin(uids.get(ends[1].part), ends[1].pin, ends[0])
            return
        source = ends[0]
        targets: list[End] = []
        for end in ends[1:]:
            if isinstance(end, str):  # a pin naming a label: Jump's, a JumpList's DEST
                self.label_pin(uids.get(source.part), source.pin, end)
            else:
                targets.append(end)
        if targets:
            network.wires.append(Wire(source, targets, node.line))

    def label_pin(self, part: Part | None, pin: str, label: str) -> None:
        """A label wired to a pin: a Jump's target, a JumpList/Switch destination or ELSE."""
        if part is None:
            return
        if part.name in ("JumpList", "Switch") and pin.startswith("dest"):
            number = pin[4:]
            dests = self.dests.setdefault(part.uid, {})
            dests[int(number) if number.isdigit() else len(dests)] = label
            part.dests = tuple(dests[k] for k in sorted(dests))
        elif part.name == "Switch" and pin == "else":
            part.template["else"] = label
        else:
            part.label = label

    def find_loop(self, network: S7Network, where: dict[str, object]) -> None:
        """An error at the first part whose power wires lead back to it (iteratively)."""
        follows: dict[str, list[str]] = {}
        for wire in network.wires:
            if wire.source.part:
                follows.setdefault(wire.source.part, []).extend(
                    t.part for t in wire.targets if t.part)
        state: dict[str, int] = {}
        for first in follows:
            if state.get(first):
                continue
            stack = [(first, iter(follows.get(first, ())))]
            state[first] = 1
            while stack:
                uid, rest = stack[-1]
                step = next(rest, None)
                if step is None:
                    state[uid] = 2
                    stack.pop()
                elif state.get(step) == 1:
                    part = network.part(step)
                    self.error("s7xml-loop", part.line if part else 0, uid=step, **where)
                    return
                elif not state.get(step):
                    state[step] = 1
                    stack.append((step, iter(follows.get(step, ()))))


def read_document(data: bytes | str) -> XmlRead:
    """A SimaticML document's blocks and tags; a refused or malformed text gives no blocks and
    its diagnostic."""
    try:
        root = parse(data)
    except XmlRefused as refused:
        return XmlRead(diagnostics=[refused.diagnostic])
    if root.name != "Document":
        return XmlRead(diagnostics=[Diagnostic("s7xml-empty", {}, root.line, 1)])
    return _Reader(root).run()


def check_calls(blocks: list[Block], diagnostics: list[Diagnostic]) -> None:
    """A warning at each call of a block that is not among `blocks` (network and part UId):
    an FC or FB by its name, an FB called on an instance DB by the DB's FB."""
    by_name = {b.name.lower(): b for b in blocks}
    for block in blocks:
        for index, network in enumerate(block.networks, start=1):
            for part in network.parts:
                if part.name != "Call" or (part.instance is not None and
                                           part.instance.kind is OperandKind.LOCAL):
                    continue
                found = by_name.get(part.call.lower())
                callee = part.call
                if found is not None and found.kind == "InstanceDB":
                    callee = found.instance_of
                    found = by_name.get(found.instance_of.lower())
                if found is None:
                    diagnostics.append(Diagnostic("s7xml-call-missing", {
                        "block": block.name, "network": index, "uid": part.uid,
                        "callee": callee}, part.line, 1, Severity.WARNING))
