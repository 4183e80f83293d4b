"""Write the S7 graph as SIMATIC SD text (`.s7dcl`, TIA V20+): a network, or a whole block with
its `.s7res` texts, in TIA's layout (four-space steps, `RUNG wire#powerrail`, named wires,
`{ S7_Templates := … }`, `"DB".TON( pt := T#10s, et => "x" )`).

Rungs: each chain of parts (one part's power out feeding the next part's power in alone) is one
rung; a point feeding several parts, an `O` part's output or a box's second Bool input gets a
name (`wire#wN`), an `O`'s inputs end their rungs `END_RUNG wire#wN` (sd_parser reads the same
back). docs/dialects.md, "SIMATIC SD: writing".
"""

from __future__ import annotations

import re
import textwrap

from ladderworks.core.dialects.s7.graph import (
    Block,
    End,
    Member,
    Operand,
    OperandKind,
    Part,
    S7Network,
)
from ladderworks.core.dialects.s7.sd_rungs import INSTANCE, SINGLE, pins

STEP = "    "
# graph part name → the SD spelling TIA writes (negated Contact/Coil: I_Contact/I_Coil)
SPELLING = {
    "Contact": "Contact", "Coil": "Coil", "SCoil": "S_Coil", "RCoil": "R_Coil",
    "PContact": "P_Contact", "NContact": "N_Contact", "PCoil": "P_Coil", "NCoil": "N_Coil",
    "PTCoil": "PT_Coil", "RTCoil": "RT_Coil", "Jump": "JumpCoil", "JumpN": "I_JumpCoil",
    "Return": "Return", "Ok": "IsValidContact", "NotOk": "IsNotValidContact",
    "Eq": "EQ_Contact", "Ne": "NE_Contact", "Gt": "GT_Contact", "Lt": "LT_Contact",
    "Ge": "GE_Contact", "Le": "LE_Contact", "InRange": "IN_RANGE", "OutRange": "OUT_RANGE",
    "Not": "Not", "PTrig": "P_Trig", "NTrig": "N_Trig", "Move": "Move", "Add": "Add",
    "Sub": "Sub", "Mul": "Mul", "Div": "Div", "Inc": "Inc", "Dec": "Dec", "Convert": "Convert",
    "JumpList": "JumpList", "Switch": "Switch", "Label": "Label",
}
_INSTANCE_SPELLING = {name: key.upper() for key, (name, _i, _o) in INSTANCE.items()}
_KEYWORDS = {"OB": "ORGANIZATION_BLOCK", "FC": "FUNCTION", "FB": "FUNCTION_BLOCK",
             "GlobalDB": "DATA_BLOCK", "InstanceDB": "DATA_BLOCK"}
_SECTIONS = {"Input": "VAR_INPUT", "Output": "VAR_OUTPUT", "InOut": "VAR_IN_OUT",
             "Static": "VAR", "Temp": "VAR_TEMP", "Constant": "VAR CONSTANT"}
# parts whose one argument is written bare (`Contact( "x" )`, `c.S_RS( wire#w1 )`)
_POSITIONAL = frozenset({"Sr", "Rs", "PTrig", "NTrig", "Return"})
# boxes whose operands are always written `pin := value`
_NAMED = frozenset({"Eq", "Ne", "Gt", "Lt", "Ge", "Le", "InRange", "OutRange", "Move", "Add",
                    "Sub", "Mul", "Div", "Inc", "Dec", "Convert", "JumpList", "Switch"})
_PLAIN = re.compile(r"^[A-Za-z_][A-Za-z_0-9]*$")


class Unwritable(ValueError):
    """A network the SD form cannot say (a part with no power in, an unknown part)."""


def name_text(name: str) -> str:
    """A name as SD writes it: bare when it is a plain identifier, else in double quotes."""
    return name if _PLAIN.match(name) else '"' + name.replace('"', '""') + '"'


def _component(name: str) -> str:
    base, sep, index = name.partition("[")
    return name_text(base) + sep + index


def operand_text(operand: Operand) -> str:
    """An operand as SD writes it: "Start", "DB".Member, #Local.Q, %I0.0, T#10s."""
    if operand.kind is OperandKind.CONSTANT:
        return operand.text
    if operand.kind is OperandKind.ABSOLUTE:
        return operand.path[0] if operand.path else operand.text
    if not operand.path:
        return operand.text
    head, *rest = operand.path
    base, sep, index = head.partition("[")
    if operand.kind is OperandKind.LOCAL:
        first = "#" + name_text(base) + sep + index
    else:
        first = '"' + base.replace('"', '""') + '"' + sep + index
    return ".".join([first, *(_component(c) for c in rest)])


def _templates(template: dict[str, str]) -> str:
    items = [f"{k} := {v}" for k, v in template.items()
             if k != "else" and not re.fullmatch(r"op\d+", k)]
    if not items:
        return ""
    body = items[0] if len(items) == 1 else "[ " + ", ".join(items) + " ]"
    return f'{{ S7_Templates := "{body}" }}'


class _Rungs:
    """The rungs of one LAD network: chains of parts, named points, `O` parts as names."""

    def __init__(self, network: S7Network, blocks: list[Block] | None = None) -> None:
        self.network = network
        self.spelling = _parameter_names(blocks or [])
        self.parts = {p.uid: p for p in network.parts}
        self.feeds: dict[tuple[str, str, bool], list[End]] = {}  # source key → targets
        self.source_of: dict[tuple[str, str], End] = {}  # (part, pin) → its source
        self.operands: dict[str, list[tuple[str, Operand, str]]] = {}  # uid → (pin, op, dir)
        for wire in network.wires:
            source = wire.source
            for target in wire.targets:
                if target.operand is not None:  # an output pin written to an operand
                    self.operands.setdefault(source.part, []).append(
                        (source.pin, target.operand, "=>"))
                elif source.operand is not None:
                    self.operands.setdefault(target.part, []).append(
                        (target.pin, source.operand, ":="))
                else:
                    self.source_of[(target.part, target.pin)] = source
                    self.feeds.setdefault(self._key(source), []).append(target)
        self.names: dict[tuple[str, str, bool], str] = {}
        used = {p.uid[2:] for p in network.parts if p.name == "O" and p.uid.startswith("O_")}
        self.counter = 0
        self.used = used
        self.inline: dict[str, tuple[Part, Part]] = {}

    @staticmethod
    def _key(end: End) -> tuple[str, str, bool]:
        return (end.part, end.pin, end.powerrail)

    def _fresh(self) -> str:
        while True:
            self.counter += 1
            name = f"w{self.counter}"
            if name not in self.used:
                self.used.add(name)
                return name

    def name_of(self, end: End) -> str:
        """The wire name of a point (rail → powerrail, an O's output → its own name)."""
        if end.powerrail:
            return "powerrail"
        key = self._key(end)
        if key not in self.names:
            part = self.parts.get(end.part)
            if part is not None and part.name == "O" and part.uid.startswith("O_") \
                    and part.uid[2:] not in self.names.values():
                self.names[key] = part.uid[2:]
            else:
                self.names[key] = self._fresh()
        return self.names[key]

    def main_in(self, part: Part) -> str:
        return "" if part.name in ("Label", "O") else pins(part)[0]

    def next_in_chain(self, part: Part) -> Part | None:
        """The part this part's power out feeds alone, on its main input."""
        out = pins(part)[1] if part.name != "O" else ""
        if not out:
            return None
        targets = self.feeds.get((part.uid, out, False), [])
        if len(targets) != 1:
            return None
        target = self.parts.get(targets[0].part)
        if target is None or target.name == "O" or self.main_in(target) != targets[0].pin:
            return None
        return target

    def _inline(self) -> dict[str, tuple[Part, Part]]:
        """The `O` parts written mid-rung (`Contact( a ) wire#w1 Coil( b )`): by the uid of the
        part whose power out is their first input, (the O, the part their output feeds alone)."""
        found: dict[str, tuple[Part, Part]] = {}
        for o_part in (p for p in self.network.parts if p.name == "O"):
            targets = self.feeds.get((o_part.uid, "out", False), [])
            follower = self.parts.get(targets[0].part) if len(targets) == 1 else None
            if follower is None or follower.name == "O" or \
                    self.main_in(follower) != targets[0].pin:
                continue
            inputs = sorted(((pin, end) for (uid, pin), end in self.source_of.items()
                             if uid == o_part.uid), key=lambda item: _pin_order(item[0]))
            if inputs and self._ends_a_chain(inputs[0][1]):
                found[inputs[0][1].part] = (o_part, follower)
        return found

    def rungs(self) -> list[list[str]]:
        """Each rung as lines (without the network's indentation)."""
        self.inline = self._inline()
        chained: set[str] = {follower.uid for _o, follower in self.inline.values()}
        for part in self.network.parts:
            follower = self.next_in_chain(part)
            if follower is not None:
                chained.add(follower.uid)
        out: list[list[str]] = []
        for part in self.network.parts:
            if part.name in ("O", "Label") or part.uid in chained:
                continue
            pin = self.main_in(part)
            source = self.source_of.get((part.uid, pin))
            if source is None:
                raise Unwritable(part.name)
            out.append(self.chain(part, source))
        for o_part in (p for p in self.network.parts if p.name == "O"):
            name = self.name_of(End(part=o_part.uid, pin="out"))
            inputs = sorted((pin, end) for (uid, pin), end in self.source_of.items()
                            if uid == o_part.uid)
            for _pin, source in sorted(inputs, key=lambda item: _pin_order(item[0])):
                if not self._ends_a_chain(source):
                    out.append([f"RUNG wire#{self.name_of(source)}", f"END_RUNG wire#{name}"])
        return out

    def _ends_a_chain(self, source: End) -> bool:
        """Whether the O input's source is a chain's last part's power out (written as its
        rung's `END_RUNG wire#o`)."""
        part = self.parts.get(source.part)
        return part is not None and part.name != "O" and not source.powerrail \
            and source.pin == pins(part)[1] and self.next_in_chain(part) is None \
            and len(self.feeds.get(self._key(source), [])) == 1

    def chain(self, first: Part, source: End) -> list[str]:
        lines = [f"RUNG wire#{self.name_of(source)}"]
        part: Part | None = first
        last: Part = first
        while part is not None:
            template = _templates(part.template)
            if template:
                lines.append(STEP + template)
            lines += [STEP + line for line in self.element(part)]
            last = part
            follower = self.next_in_chain(part)
            out = pins(part)[1]
            if follower is not None:
                if self._needs_name(End(part=part.uid, pin=out)):
                    lines.append(STEP + "wire#" + self.name_of(End(part=part.uid, pin=out)))
            elif part.uid in self.inline:
                o_part, follower = self.inline[part.uid]
                lines.append(STEP + "wire#" + self.name_of(End(part=o_part.uid, pin="out")))
            part = follower
        out_pin = pins(last)[1]
        targets = self.feeds.get((last.uid, out_pin, False), []) if out_pin else []
        ending = "END_RUNG"
        if len(targets) == 1 and self.parts.get(targets[0].part, last).name == "O":
            ending += " wire#" + self.name_of(End(part=targets[0].part, pin="out"))
        elif targets:
            ending += " wire#" + self.name_of(End(part=last.uid, pin=out_pin))
        return [*lines, ending]

    def _needs_name(self, end: End) -> bool:
        return len(self.feeds.get(self._key(end), [])) > 1

    def element(self, part: Part) -> list[str]:
        """One element: `Contact( "x" )`, `"DB".TON( … )`, `"FC"( … )`, `Switch( … )`."""
        head = self._head(part)
        args = self._arguments(part)
        if len(args) <= 1 and not (part.instance is not None or part.name == "Call"):
            return [f"{head}( {args[0]} )" if args else f"{head}()"]
        if len(args) <= 3 and all(len(a) < 30 for a in args) and part.instance is None \
                and part.name not in ("Call", "Switch", "JumpList"):
            return [f"{head}( {', '.join(args)} )"]
        if not args:
            return [f"{head}()"]
        return [f"{head}(", *[STEP + a + ("," if n < len(args) - 1 else "")
                              for n, a in enumerate(args)], ")"]

    def _head(self, part: Part) -> str:
        if part.name in _INSTANCE_SPELLING and part.instance is not None:
            return operand_text(part.instance) + "." + _INSTANCE_SPELLING[part.name]
        if part.name == "Call":
            if part.instance is not None:
                return operand_text(part.instance)
            return '"' + part.call.replace('"', '""') + '"'
        if part.name in ("Contact", "Coil") and "operand" in part.negated:
            return "I_" + part.name
        if part.name in SPELLING:
            return SPELLING[part.name]
        raise Unwritable(part.name)

    def _arguments(self, part: Part) -> list[str]:
        if part.name in ("Jump", "JumpN", "Label"):
            return [name_text(part.label)] if part.label else []
        single = SINGLE.get(part.name, "operand")
        positional = part.name in _POSITIONAL or (single == "operand" and part.name in SPELLING
                                                  and part.name not in _NAMED)
        main_in = pins(part)[0]
        args: list[str] = []
        switch: dict[str, str] = {}
        names = self.spelling.get(part.call.lower(), {}) if part.name == "Call" else {}
        for pin, operand, direction in self.operands.get(part.uid, []):
            text = operand_text(operand)
            pin = names.get(pin, pin)  # a call's parameter as its block spells it
            if part.name == "Switch" and re.fullmatch(r"(eq|ne|lt|gt|le|ge)\d+", pin):
                switch[pin] = text
            elif positional and pin == single and direction == ":=":
                args.append(text)
            else:
                args.append(f"{pin} {direction} {text}")
        for (uid, pin), source in self.source_of.items():
            if uid == part.uid and pin != main_in:
                value = "wire#" + self.name_of(source)
                pin = names.get(pin, pin)
                args.append(value if positional and pin == single else f"{pin} := {value}")
        if part.name == "Switch":
            for n, dest in enumerate(part.dests, start=1):
                relation = part.template.get(f"op{n}", "EQ")
                value = switch.get(f"{relation.lower()}{n}", "")
                args.append(f"{relation} {value} => {name_text(dest)}")
            if part.template.get("else"):
                args.append(f"else => {name_text(part.template['else'])}")
        elif part.name == "JumpList":
            args += [f"dest{n} => {name_text(d)}" for n, d in enumerate(part.dests)]
        return args


def _parameter_names(blocks: list[Block]) -> dict[str, dict[str, str]]:
    """Each callable name's parameters as its interface spells them (the graph's pins are
    lower case): FCs and FBs by name, instance DBs by their FB's."""
    by_name = {b.name.lower(): b for b in blocks}
    found: dict[str, dict[str, str]] = {}
    for block in blocks:
        callee = by_name.get(block.instance_of.lower()) if block.kind == "InstanceDB" else block
        if callee is not None and callee.kind in ("FC", "FB"):
            found[block.name.lower()] = {m.name.lower(): m.name for s in ("Input", "Output",
                                         "InOut") for m in callee.members(s)}
    return found


def _pin_order(pin: str) -> tuple[int, str]:
    digits = "".join(c for c in pin if c.isdigit())
    return (int(digits) if digits else 0, pin)


def network_lines(network: S7Network, network_id: str = "",
                  blocks: list[Block] | None = None) -> list[str]:
    """A network as SD lines without indentation: its pragma, NETWORK … END_NETWORK.
    `network_id` is its title's text id in the `.s7res` ("" for none); `blocks` (the
    program's) spell the calls' parameters. Unwritable when a part cannot be said in SD."""
    pragma = [f'S7_Language := "{network.language}"']
    if network_id:
        pragma.append(f'S7_NetworkTitle := "{network_id}"')
    lines = ["{", *[STEP + item + (";" if n < len(pragma) - 1 else "")
                    for n, item in enumerate(pragma)], "}", "NETWORK"]
    return [*lines, *[STEP + line for line in body_lines(network, blocks)], "END_NETWORK"]


def body_lines(network: S7Network, blocks: list[Block] | None = None) -> list[str]:
    """The lines between NETWORK and END_NETWORK, unindented."""
    if network.language.upper() not in ("LAD", "FBD"):
        return textwrap.dedent(network.source).splitlines()
    rungs = _Rungs(network, blocks)
    lines = [f"Label( {name_text(p.label)} )" for p in network.parts if p.name == "Label"]
    for rung in rungs.rungs():
        lines += rung
    return lines


def _member_lines(member: Member) -> list[str]:
    start = f" := {member.start}" if member.start else ""
    if member.members:
        inner = [STEP + line for m in member.members for line in _member_lines(m)]
        return [f"{name_text(member.name)} : Struct", *inner, "END_STRUCT;"]
    return [f"{name_text(member.name)} : {member.type_name}{start};"]


def _start_path(members: tuple[Member, ...], path: tuple[str, ...]) -> str:
    """A BEGIN line's member path with the members' own spelling (`Data.Counts[2]`)."""
    names = []
    for component in path:
        base, bracket, index = component.partition("[")
        found = next((m for m in members if m.name.lower() == base), None)
        names.append(_component((found.name if found else base) + bracket + index))
        members = found.members if found is not None else ()
    return ".".join(names)


def source_text(block: Block) -> str:
    """A global DB or a PLC data type as TIA's generated source (`.db`/`.udt`): STRUCT
    members, a DB's BEGIN start values (db_source.py reads it back)."""
    keyword = "TYPE" if block.kind == "Type" else "DATA_BLOCK"
    lines = [f'{keyword} "{block.name}"']
    if block.kind != "Type":
        lines.append("{ S7_Optimized_Access := 'TRUE' }")
    lines += ["VERSION : 0.1"]
    members = tuple(m for s in ("Static", "Input", "Output", "InOut") for m in block.members(s))
    if block.kind == "InstanceDB":
        lines += ["NON_RETAIN", f'"{block.instance_of}"']
    else:
        lines += [*(["NON_RETAIN"] if block.kind != "Type" else []), "   STRUCT"]
        lines += ["      " + line.replace(STEP, "   ") for m in members
                  for line in _member_lines(m)]
        lines.append("   END_STRUCT;")
    if block.kind == "Type":
        return "\n".join([*lines, "", "END_TYPE", ""])
    lines += ["", "", "BEGIN"]
    lines += [f"   {_start_path(members, path)} := {value};"
              for path, value in block.starts.items()]
    return "\n".join([*lines, "END_DATA_BLOCK", ""])


def block_text(block: Block, culture: str = "en-US",
               blocks: list[Block] | None = None) -> tuple[str, str]:
    """A whole block as SD text (BOM, LF line ends) and its `.s7res` texts ("" when none);
    `blocks`, the program's, spell the calls' parameters."""
    if block.kind == "Type":
        return source_text(block), ""
    head = ['S7_Optimized := "TRUE"']
    if block.number:
        head.append(f'S7_BlockNumber := "{block.number}"')
    if block.kind in ("OB", "FC", "FB"):
        head += [f'S7_PreferredLanguage := "{block.language}"', 'S7_Version := "0.1"']
    texts: list[tuple[str, str]] = []
    if block.title:
        head.append('S7_BlockTitle := "MLC_block"')
        texts.append(("MLC_block", block.title))
    lines = ["\ufeff{", *[STEP + item + (";" if n < len(head) - 1 else "")
                         for n, item in enumerate(head)], "}"]
    keyword = _KEYWORDS[block.kind]
    title = f'{keyword} "{block.name}"'
    if block.kind == "FC":
        title += f" : {name_text(block.return_type or 'Void')}"
    if block.kind == "InstanceDB":
        title += f' : "{block.instance_of}"'
    lines.append(title)
    for section, members in block.sections.items():
        if section not in _SECTIONS or not members:
            continue
        lines.append(STEP + _SECTIONS[section])
        lines += [STEP * 2 + line for m in members for line in _member_lines(m)]
        lines.append(STEP + "END_VAR")
    if block.kind in ("GlobalDB", "InstanceDB"):
        lines += ["BEGIN", f"END_{keyword}", ""]
        return "\n".join(lines), ""
    if block.sections:
        lines.append("")
    for n, network in enumerate(block.networks, start=1):
        network_id = ""
        if network.title:
            network_id = f"MLC_{n}"
            texts.append((network_id, network.title))
        lines += [STEP + line for line in network_lines(network, network_id, blocks)]
    lines += [f"END_{keyword}", ""]
    return "\n".join(lines), texts_text(texts, culture)


def texts_text(texts: list[tuple[str, str]], culture: str = "en-US") -> str:
    """An `.s7res` of (id, text) pairs in one culture ("" when there are none)."""
    if not texts:
        return ""
    lines = ["\ufeffMultiLingualTexts:"]
    for text_id, text in texts:
        value = "'" + text.replace("'", "''") + "'" if _needs_quotes(text) else text
        lines += [f"  - id: {text_id}", f"    {culture}: {value}"]
    return "\n".join(lines) + "\n"


def _needs_quotes(text: str) -> bool:
    return text != text.strip() or "\n" in text or text[:1] in "'\"|>-[{&*!%@`#" or \
        ": " in text or " #" in text or not text
