"""Parse a SIMATIC SD block (`.s7dcl`, TIA V20+) into the S7 graph (graph.py).

The form, learned from public exports and Siemens' "SIMATIC Source Documents LADDER Format
Description" (entry 109994073) as quoted in them: a block pragma, `ORGANIZATION_BLOCK` /
`FUNCTION … : Void` / `FUNCTION_BLOCK` / `DATA_BLOCK` "Name", `VAR_*` sections, then networks:
a pragma `{ S7_Language := "LAD"; S7_NetworkTitle := "MLC_x" }`, `NETWORK`, `RUNG wire#powerrail
… END_RUNG [wire#w1]`, `END_NETWORK`. Elements of a rung are in series; `wire#wN` names the
point where it stands; a rung ending `END_RUNG wire#wN` joins its power there (an OR), a rung
starting `RUNG wire#wN` branches from it. A global DB's or a type's generated source (`.db`,
`.udt`: `STRUCT … END_STRUCT;`, `BEGIN` start values, several blocks a file) is read by
`parse_sources` (db_source.py). docs/dialects.md, "SIMATIC SD", "S7-1200: global DB sources".
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.s7.db_source import begin_values
from ladderworks.core.dialects.s7.graph import (
    Block,
    End,
    Member,
    Operand,
    OperandKind,
    Part,
    S7Network,
    Wire,
)
from ladderworks.core.dialects.s7.sd_lexer import LexError, Token, pragma_items, templates, tokens
from ladderworks.core.dialects.s7.sd_rungs import (
    CMP,
    INSTANCE,
    SIMPLE,
    SINGLE,
    Link,
    pins,
    resolve_links,
    wire_ref,
)

_BLOCKS = {"ORGANIZATION_BLOCK": "OB", "FUNCTION": "FC", "FUNCTION_BLOCK": "FB",
           "DATA_BLOCK": "GlobalDB", "TYPE": "Type"}
_SECTIONS = {"VAR_INPUT": "Input", "VAR_OUTPUT": "Output", "VAR_IN_OUT": "InOut",
             "VAR": "Static", "VAR_STAT": "Static", "VAR_TEMP": "Temp"}
class ParseError(Exception):
    """The SD text cannot be read on; `diagnostic` says where."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message())
        self.diagnostic = diagnostic


@dataclass(slots=True)
class Parsed:
    """A parsed SD block: the graph, the texts' ids its pragmas name, the networks' lines."""

    block: Block
    title_ids: list[tuple[str, str]] = field(default_factory=list)  # per network (title, comment)
    block_ids: tuple[str, str] = ("", "")


class _Parser:
    """Recursive descent over the tokens."""

    def __init__(self, toks: list[Token], lines: list[str]) -> None:
        self.toks = toks
        self.lines = lines  # the text's lines (an SCL network keeps its own)
        self.pos = 0

    # -- tokens ---------------------------------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.toks[self.pos]

    def next(self) -> Token:
        tok = self.toks[self.pos]
        if tok.kind != "end":
            self.pos += 1
        return tok

    def word(self, *words: str) -> bool:
        return self.tok.kind == "word" and self.tok.text.upper() in words

    def op(self, *ops: str) -> bool:
        return self.tok.kind == "op" and self.tok.text in ops

    def fail(self, expected: str, inside: str = "") -> ParseError:
        tok = self.tok
        if tok.kind == "end" and inside:
            return ParseError(Diagnostic("s7-cut", {"what": inside}, tok.line, tok.column))
        return ParseError(Diagnostic("s7-syntax", {"expected": expected, "found": tok.text or
                                                   "the end of the text"}, tok.line, tok.column))

    def expect_op(self, text: str, inside: str) -> Token:
        if not self.op(text):
            raise self.fail(f"'{text}'", inside)
        return self.next()

    # -- the block ------------------------------------------------------------------------
    def block(self) -> Parsed:
        attributes: dict[str, str] = {}
        while self.tok.kind == "pragma":
            attributes.update(pragma_items(self.next().text))
        if not (self.tok.kind == "word" and self.tok.text.upper() in _BLOCKS):
            raise self.fail("ORGANIZATION_BLOCK, FUNCTION, FUNCTION_BLOCK, DATA_BLOCK or TYPE")
        keyword = self.next().text.upper()
        name_tok = self.next()
        if name_tok.kind not in ("name", "word"):
            raise self.fail("the block's name", "the block's head")
        block = Block(_BLOCKS[keyword], _unquote(name_tok.text))
        number = attributes.get("S7_BlockNumber", "")
        block.number = int(number) if number.isdigit() else 0
        block.language = attributes.get("S7_PreferredLanguage", "LAD")
        if self.op(":"):
            self.next()
            type_tok = self.next()
            if type_tok.kind not in ("name", "word"):
                raise self.fail("the block's type", "the block's head")
            block.return_type = _unquote(type_tok.text)
            if block.kind == "GlobalDB":  # DATA_BLOCK "X" : "FB": an instance DB
                block.kind, block.instance_of = "InstanceDB", block.return_type
        if block.kind == "GlobalDB" and self.tok.kind == "name":  # DATA_BLOCK "X" "FB"
            block.kind, block.instance_of = "InstanceDB", _unquote(self.next().text)
        parsed = Parsed(block, block_ids=(attributes.get("S7_BlockTitle", ""),
                                          attributes.get("S7_BlockComment", "")))
        end = "END_" + keyword
        pending: dict[str, str] = {}
        while True:
            tok = self.tok
            if tok.kind == "end":
                raise self.fail(end, f"the block {block.name}")
            if tok.kind == "pragma":
                pending = pragma_items(self.next().text)
            elif self.word(end):
                self.next()
                break
            elif tok.kind == "word" and tok.text.upper() in _SECTIONS:
                self.section(block)
            elif self.word("NETWORK"):
                self.network(block, parsed, pending)
                pending = {}
            elif self.word("VERSION", "TITLE", "AUTHOR", "FAMILY", "NAME"):  # SCL-source heads
                self.next()
                if self.op(":", "="):
                    self.next()
                    self.next()
            elif self.word("NON_RETAIN", "RETAIN"):
                self.next()
            elif self.word("STRUCT") and block.kind in ("GlobalDB", "Type"):  # a `.db` source
                self.next()
                members = self.members("STRUCT", "END_STRUCT")
                self.next()
                if self.op(";"):
                    self.next()
                block.sections.setdefault("Static", []).extend(members)
            elif block.kind == "GlobalDB" and tok.kind == "name":  # `"FB"` on its own line
                block.kind, block.instance_of = "InstanceDB", _unquote(self.next().text)
            elif self.word("BEGIN"):  # a DB's start values (`Count := 3;`)
                self.next()
                begin_values(self, block, end)
            else:
                raise self.fail(f"VAR_…, NETWORK or {end}")
        return parsed

    def type_text(self, inside: str) -> str:
        """A member's type as written up to `;` or `:=` (Struct handled by the caller)."""
        parts: list[str] = []
        depth = 0
        while not (depth == 0 and self.op(";", ":=")) and self.tok.kind != "end":
            tok = self.next()
            depth += {"[": 1, "]": -1}.get(tok.text, 0)
            parts.append(tok.text)
            if self.word("END_VAR") or self.tok.kind == "pragma" or (
                    tok.text.upper() == "OF" and self.word("STRUCT")):  # Array[…] of Struct
                break
        if self.tok.kind == "end":
            raise self.fail("';'", inside)
        return " ".join(parts).replace(" [ ", "[").replace(" ]", "]").replace(" . . ", "..")

    def members(self, inside: str, closing: str) -> list[Member]:
        found: list[Member] = []
        while not self.word(closing):
            if self.tok.kind == "end":
                raise self.fail(closing, inside)
            if self.tok.kind == "pragma":
                self.next()
                continue
            if self.word("CONSTANT", "RETAIN", "NON_RETAIN"):
                self.next()
                continue
            name_tok = self.next()
            if name_tok.kind not in ("word", "name"):
                raise ParseError(Diagnostic("s7-syntax", {"expected": "a member's name",
                                                          "found": name_tok.text},
                                            name_tok.line, name_tok.column))
            while self.tok.kind == "pragma":  # `Timer {InstructionName := 'TON_TIME'} : …`
                self.next()
            self.expect_op(":", inside)
            if self.word("STRUCT"):
                self.next()
                inner = self.members(inside, "END_STRUCT")
                self.next()
                member = Member(_unquote(name_tok.text), "Struct", members=tuple(inner))
            else:
                member = Member(_unquote(name_tok.text), self.type_text(inside))
                if self.word("STRUCT"):  # Array[…] of Struct … END_STRUCT
                    self.next()
                    inner = self.members(inside, "END_STRUCT")
                    self.next()
                    member = Member(member.name, member.type_name + " Struct",
                                    members=tuple(inner))
            if self.op(":="):
                self.next()
                start = self.type_text(inside)
                member = Member(member.name, member.type_name, start, members=member.members)
            if self.op(";"):
                self.next()
            found.append(member)
        return found

    def section(self, block: Block) -> None:
        keyword = self.next().text.upper()
        section = _SECTIONS[keyword]
        if self.word("CONSTANT"):
            self.next()
            section = "Constant"
        members = self.members(f"the section {keyword}", "END_VAR")
        self.next()
        block.sections.setdefault(section, []).extend(members)

    # -- networks -------------------------------------------------------------------------
    def network(self, block: Block, parsed: Parsed, pragma: dict[str, str]) -> None:
        start = self.next()
        network = S7Network(language=pragma.get("S7_Language", block.language or "LAD"),
                            line=start.line)
        parsed.title_ids.append((pragma.get("S7_NetworkTitle", ""),
                                 pragma.get("S7_NetworkComment", "")))
        block.networks.append(network)
        inside = f"network {len(block.networks)}"
        if network.language.upper() not in ("LAD", "FBD"):
            while not self.word("END_NETWORK"):
                if self.tok.kind == "end":
                    raise self.fail("END_NETWORK", inside)
                self.next()
            network.end_line = self.next().line
            body = self.lines[start.line:network.end_line - 1]
            network.source = "\n".join(line.rstrip() for line in body).strip("\n")
            return
        links: list[Link] = []
        named: set[str] = set()
        while not self.word("END_NETWORK"):
            if self.tok.kind == "end":
                raise self.fail("END_NETWORK", inside)
            if self.word("LABEL"):
                part = self.element(network, inside, {})
                if part is None or part.name != "Label":
                    raise self.fail("RUNG", inside)
                continue
            if not self.word("RUNG"):
                raise self.fail("RUNG or END_NETWORK", inside)
            self.rung(network, links, named, f"a rung of {inside}")
        network.end_line = self.next().line
        resolve_links(network, links)

    def rung(self, network: S7Network, links: list[Link], named: set[str], inside: str) -> None:
        self.next()
        if self.tok.kind != "wire":
            raise self.fail("wire#powerrail or wire#name", inside)
        first = self.next()
        current: tuple[str, object] = wire_ref(first.text)
        pending: dict[str, str] = {}
        while not self.word("END_RUNG"):
            tok = self.tok
            if tok.kind == "end":
                raise self.fail("END_RUNG", inside)
            if tok.kind == "pragma":
                items = pragma_items(self.next().text)
                if "S7_Templates" in items:
                    pending = templates(items["S7_Templates"])
                continue
            if tok.kind == "wire":
                self.next()
                ref = wire_ref(tok.text)
                links.append(Link(current, End(part="@" + str(ref[1])), tok.line))
                named.add(str(ref[1]))
                current = ref
                continue
            part = self.element(network, inside, pending)
            pending = {}
            if part is None:
                continue
            main_in, main_out = pins(part)
            if main_in:
                links.append(Link(current, End(part=part.uid, pin=main_in), tok.line))
            current = ("end", End(part=part.uid, pin=main_out)) if main_out else ("none", None)
        self.next()
        if self.tok.kind == "wire":
            tok = self.next()
            ref = wire_ref(tok.text)
            links.append(Link(current, End(part="@" + str(ref[1])), tok.line))

    def element(self, network: S7Network, inside: str,
                pending: dict[str, str]) -> Part | None:
        """One element `Name( args )`, `#inst.TON( … )`, `CMP >=( … )`, `"FC"( … )`."""
        start = self.tok
        path: list[Token] = [self.next()]
        if start.kind == "word" and start.text.upper() == "CMP" and self.tok.kind == "op":
            symbol = self.next().text
            part = Part(str(len(network.parts) + 1), CMP.get(symbol, "CMP " + symbol),
                        line=start.line)
        else:
            while self.op("."):
                self.next()
                path.append(self.next())
            part = self.make_part(network, path, start)
            spelled = path[0].text.upper() if len(path) == 1 else ""
            if spelled in ("RETURNTRUE", "RETURNFALSE"):  # RET's value in its name
                value = Operand(OperandKind.CONSTANT, (), spelled[6:], "Bool")
                network.wires.append(Wire(End(operand=value), [End(part=part.uid,
                                                                   pin="operand")], start.line))
        part.template.update(pending)
        network.parts.append(part)
        self.expect_op("(", inside)
        self.arguments(network, part, inside)
        return part

    def make_part(self, network: S7Network, path: list[Token], start: Token) -> Part:
        uid = str(len(network.parts) + 1)
        last = path[-1].text.lower()
        if len(path) == 1 and path[0].kind == "word" and last in SIMPLE:
            name, negated, _in, _out = SIMPLE[last]
            return Part(uid, name, negated=negated, line=start.line)
        if len(path) == 1 and last == "label":
            return Part(uid, "Label", line=start.line)
        if len(path) > 1 and last in INSTANCE and path[-1].kind == "word":
            instance = _operand_of(path[:-1])
            return Part(uid, INSTANCE[last][0], instance=instance, line=start.line)
        if path[0].kind in ("name", "local"):  # a call: "FC"( … ) or an FB instance #inst( … )
            callee = _operand_of(path)
            kind = "FB" if path[0].kind == "local" or len(path) > 1 else ""
            return Part(uid, "Call", call=".".join(callee.path), call_kind=kind,
                        instance=callee if kind == "FB" else None, line=start.line)
        return Part(uid, ".".join(t.text for t in path), line=start.line)

    def arguments(self, network: S7Network, part: Part, inside: str) -> None:
        wires = network.wires
        position = 0
        while not self.op(")"):
            if self.tok.kind == "end":
                raise self.fail("')'", inside)
            tok = self.tok
            if self.op(","):
                self.next()
                continue
            relation = ""
            if part.name == "Switch" and tok.kind == "word" and tok.text.upper() in (
                    "EQ", "NE", "LT", "GT", "LE", "GE") and self.toks[self.pos + 1].kind != "op":
                relation = self.next().text.upper()
            pin = ""
            after = self.toks[self.pos + 1]
            if not relation and tok.kind == "word" and after.kind == "op" \
                    and after.text in (":=", "=>"):
                pin = self.next().text.lower()
            direction = self.next().text if pin and self.op(":=", "=>") else ":="
            if relation:
                value = self.value(inside)
                position += 1
                pin = f"{relation.lower()}{position}"
                part.template[f"op{position}"] = relation
                self.expect_op("=>", inside)
                label = self.next()
                part.dests = (*part.dests, _unquote(label.text))
                direction = ":="
            elif part.name in ("JumpList", "Switch") and pin.startswith(("dest", "else")):
                label = self.next()
                if pin == "else":
                    part.template["else"] = _unquote(label.text)
                else:
                    part.dests = (*part.dests, _unquote(label.text))
                continue
            else:
                value = self.value(inside) if not self.op(",", ")") else None
            if value is None:
                continue
            if not pin:
                pin = SINGLE.get(part.name, "operand")
            if pin == "label" or (part.name == "Label"):
                name = value if isinstance(value, str) else value.path[0] if value.path \
                    else value.text
                part.label = _unquote(name)
                continue
            if isinstance(value, str):  # a wire as a pin's power
                wires.append(Wire(End(part="@" + value), [End(part=part.uid, pin=pin)],
                                  tok.line))
            elif direction == "=>":
                wires.append(Wire(End(part=part.uid, pin=pin), [End(operand=value)], tok.line))
            else:
                wires.append(Wire(End(operand=value), [End(part=part.uid, pin=pin)], tok.line))
        self.next()

    def value(self, inside: str) -> Operand | str | None:
        """An actual parameter: an operand, a constant, or a wire's name (str)."""
        tok = self.tok
        if tok.kind == "wire":
            self.next()
            return tok.text.split("#", 1)[1]
        if tok.kind == "absolute":
            self.next()
            return Operand(OperandKind.ABSOLUTE, (tok.text,), tok.text)
        if tok.kind in ("number", "string") or (tok.kind == "op" and tok.text == "-"):
            text = self.next().text
            if text == "-" and self.tok.kind == "number":
                text += self.next().text
            head, sep, _rest = text.partition("#")
            type_name = head if sep and not head.isdigit() else ""
            return Operand(OperandKind.CONSTANT, (), text, type_name)
        if tok.kind == "word" and tok.text.upper() in ("TRUE", "FALSE"):
            self.next()
            return Operand(OperandKind.CONSTANT, (), tok.text.upper(), "Bool")
        if tok.kind in ("local", "name", "word"):
            path = [self.next()]
            while self.op(".") or self.op("["):
                if self.op("["):
                    self.next()
                    depth_text = ""
                    while not self.op("]"):
                        if self.tok.kind == "end":
                            raise self.fail("']'", inside)
                        depth_text += self.next().text
                    self.next()
                    path[-1] = Token(path[-1].kind, f"{path[-1].text}[{depth_text}]",
                                     path[-1].line, path[-1].column)
                    continue
                self.next()
                path.append(self.next())
            return _operand_of(path)
        raise self.fail("an operand", inside)


def _unquote(text: str) -> str:
    if len(text) >= 2 and text[0] == text[-1] == '"':
        return text[1:-1].replace('""', '"')
    return text


def _operand_of(path: list[Token]) -> Operand:
    head = path[0]
    if head.kind == "absolute":
        return Operand(OperandKind.ABSOLUTE, (head.text,), head.text)
    names = tuple(_unquote(t.text.lstrip("#")) for t in path)
    kind = OperandKind.LOCAL if head.kind == "local" else OperandKind.GLOBAL
    if head.kind == "word":  # a bare name: the lowering looks it up as a local first
        kind = OperandKind.LOCAL
    return Operand(kind, names, "".join(t.text for t in path))


def parse_sd(text: str) -> Parsed:
    """An SD block's text as its graph; ParseError (with its diagnostic) when it cannot be read."""
    try:
        toks = tokens(text)
    except LexError as error:
        raise ParseError(error.diagnostic) from None
    parser = _Parser(toks, text.split("\n"))
    parsed = parser.block()
    return parsed


def parse_sources(text: str) -> list[Parsed]:
    """Every block of a source text (a `.db` file may hold several, and TYPE blocks before
    them); ParseError at the first that cannot be read."""
    try:
        toks = tokens(text)
    except LexError as error:
        raise ParseError(error.diagnostic) from None
    parser = _Parser(toks, text.split("\n"))
    found = [parser.block()]
    while parser.tok.kind != "end":
        found.append(parser.block())
    return found
