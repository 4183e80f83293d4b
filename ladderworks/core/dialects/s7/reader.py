"""Open S7-1200 exports as one Program: an SD block (`.s7dcl` with its `.s7res`), or a folder of
blocks and PLC tag tables; the entry block (the OB, else the first block) is lowered.

An unchanged program saves byte for byte (FileSource: the entry block's file, one span); a
changed one is written by saving.py when its change is known as a change of its graph (the S7
model on `Program.model` keeps the entry file as read), else refused (`Dialect.refuse_changes`).
`.db`/`.udt` sources beside the blocks are read with them.
"""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7 import scl_source, system_tags
from ladderworks.core.dialects.s7.as_read import AsRead
from ladderworks.core.dialects.s7.graph import Block, S7Program
from ladderworks.core.dialects.s7.layout import (
    COUNTER_MEMBERS,
    COUNTER_TYPES,
    TIMER_MEMBERS,
    TIMER_TYPES,
    Layout,
    size_of,
)
from ladderworks.core.dialects.s7.sd_parser import Parsed, ParseError, parse_sd
from ladderworks.core.dialects.s7.source import S7Model, program_of
from ladderworks.core.dialects.s7.tags import is_tag_table, read_tag_table
from ladderworks.core.dialects.s7.texts import pick, read_texts
from ladderworks.core.il.program import FileSource, Program
from ladderworks.core.il.textform import TextForm, decode_lines, encode_text
from ladderworks.core.symbols import Symbol, SymbolTable

NAME = "s7"
SD_SUFFIXES = (".s7dcl",)
SOURCE_SUFFIXES = (".db", ".udt", ".scl")  # TIA's "Generate source from blocks"
MAX_BYTES = 64 * 1024 * 1024  # a file larger than this is refused, not read


def _titles(parsed: Parsed, texts: dict[str, dict[str, str]]) -> None:
    block = parsed.block
    for network, (title_id, comment_id) in zip(block.networks, parsed.title_ids, strict=False):
        network.title = pick(texts, title_id) if title_id else ""
        network.comment = pick(texts, comment_id) if comment_id else ""
    if parsed.block_ids[0]:
        block.title = pick(texts, parsed.block_ids[0])


def _symbols(program: S7Program, layout: Layout, entry: Block) -> SymbolTable:
    """Every name the program knows, quoted as TIA writes it and bare: tags, DB members, the
    entry block's interface (`#Name`)."""
    table = SymbolTable()

    def add(name: str, address: Address, comment: str = "") -> None:
        table.add(address, Symbol(name, (comment,) if comment else ()))

    def typed(name: str, type_name: str) -> None:
        table.types.setdefault(name, (type_name, size_of(type_name)))

    for block in program.blocks:  # every global DB laid out, used or not (a Modbus map's)
        if block.kind == "GlobalDB":
            layout.global_name((block.name,))
    for tag in program.tags:
        if tag.value:  # a user constant: no place, its value is used where it is named
            continue
        place = layout.global_name((tag.name,))
        if place is not None:
            head, dot, rest = tag.name.partition(".")  # a member of a DB not read: "DB".a
            quoted = f'"{head}".{rest}' if dot and tag.table == system_tags.UNDECLARED \
                else f'"{tag.name}"'
            add(quoted, place.address, tag.comment)
            table.by_symbol.setdefault(tag.name, place.address)
            typed(f'"{tag.name}"', tag.type_name)
    for section in ("Input", "Output", "InOut", "Static", "Temp"):
        for member in entry.members(section):
            place = layout.local(entry, (member.name,))
            if place is not None:
                add(f"#{member.name}", place.address, member.comment)
                table.by_symbol.setdefault(member.name, place.address)
                typed(f"#{member.name}", member.type_name)
    own = (f"#{entry.name.lower()}",)
    for key, place in list(layout.places.items()):
        if len(key) == 1 and key in layout.members and place.type_name == "Struct" \
                and not key[0].startswith("#"):
            member = layout.members[key]  # a DB itself: its name and whole size
            table.types.setdefault(f'"{member.name}"', (
                place.type_name, size_of(member.type_name, member.members)))
            table.by_symbol.setdefault(f'"{member.name}"', place.address)
        if place.type_name == "Struct" or (len(key) < 2 and key[0].startswith("#")):
            continue
        names = [(layout.members[key[:n]].name if key[:n] in layout.members else key[n - 1])
                 for n in range(1, len(key) + 1)]
        db = program.block(key[0]) if key[:1] not in layout.members else None
        if db is not None:  # an instance DB named by its scope: as TIA spells it
            names[0] = db.name
        if key[:1] == own:  # the entry block's own members: #Data.Count
            name = "#" + ".".join(names[1:])
        elif key[0].startswith("#"):  # another block's (an FC's): its members by block
            continue
        else:
            name = ".".join([f'"{names[0]}"', *names[1:]])
        if name not in table.by_symbol:
            table.by_symbol[name] = place.address
        typed(name, place.type_name)
        kind = place.type_name.lower()
        members = TIMER_MEMBERS if kind in TIMER_TYPES else COUNTER_MEMBERS \
            if kind in COUNTER_TYPES else {}
        for pin in members:  # an instance's members: "IEC_Timer_0_DB".Q, #Zaman.ET
            inner = layout.sub(key, (pin,))
            if inner is not None:
                table.by_symbol.setdefault(f"{name}.{pin.upper()}", inner.address)
                typed(f"{name}.{pin.upper()}", inner.type_name)
    # the instances' members (`"T1".Q`, `#Timer.ET`) resolve on demand in scenarios
    return table


def build(blocks: list[Parsed], tags: list, texts: dict[str, dict[str, str]],
          diagnostics: list[Diagnostic]) -> tuple[Program, S7Program, Layout]:
    """The Program of the entry block among `blocks`, with the tags' symbols."""
    for parsed in blocks:
        _titles(parsed, texts)
    every = [p.block for p in blocks]
    program = S7Program(every, list(tags) + system_tags.implied(every, list(tags)))
    layout = Layout(program)
    code = [b for b in program.blocks if b.kind in ("OB", "FC", "FB")]
    entry = code[0] if code else None  # the file opened, or a folder's OB (put first)
    result, found = program_of(program, layout, entry, _finish)
    result.dialect = NAME
    diagnostics += found
    return result, program, layout


def _finish(result: Program, program: S7Program, layout: Layout, entry: Block) -> None:
    """The symbols of a (re)built program."""
    result.symbols = _symbols(program, layout, entry)


def _source(program: Program, form: TextForm, lines: list[str], ends: list[str]) -> None:
    keys = [network.key() for network in program.networks]
    spans = [(0, len(lines))] + [(len(lines), len(lines))] * (len(keys) - 1)
    program.source = FileSource(form, lines, ends, 0, len(lines), keys, spans[:len(keys)],
                                [0] * len(keys), (), (len(lines), len(lines)))
    if not keys:  # nothing lowered: the whole text is the trailer, kept as read
        program.source.trailer_span = (0, len(lines))


def attach(program: Program, blocks: list[Block], data: bytes, form: str,
           path: Path | None = None) -> None:
    """Keep the entry block's file as read in the program's model (as_read.py) when the entry
    block is one of that file's `blocks`: what Save needs to write a changed entry block in
    its own form (saving.py)."""
    model = program.model
    if isinstance(model, S7Model) and any(b is model.entry for b in blocks):
        model.read = AsRead.of(data, form, model.entry, path)


def _parse(text: str, diagnostics: list[Diagnostic]) -> Parsed | None:
    if len(text) > MAX_BYTES:
        diagnostics.append(Diagnostic("s7-too-large", {"size": len(text) >> 20,
                                                       "limit": MAX_BYTES >> 20}, 1, 1))
        return None
    try:
        return parse_sd(text)
    except ParseError as error:
        diagnostics.append(error.diagnostic)
        return None


def _source_entry(text: str, diagnostics: list[Diagnostic]) -> tuple[Parsed | None,
                                                                     list[Parsed]]:
    """A source opened as the program: its first code block (else its first block) and the
    others."""
    try:
        found = scl_source.parse_scl(text)
    except ParseError as error:
        diagnostics.append(error.diagnostic)
        return None, []
    first = next((p for p in found if p.block.kind in scl_source.CODE), found[0])
    return first, [p for p in found if p is not first]


def read(text: str, form: TextForm, lines: list[str],
         ends: list[str]) -> tuple[Program, list[Diagnostic]]:
    """One SD block's text (no companion files) as a Program and its diagnostics."""
    diagnostics: list[Diagnostic] = []
    parsed = _parse(text, diagnostics)
    program, _graph, _layout = build([parsed] if parsed else [], [], {}, diagnostics)
    _source(program, form, lines, ends)
    if parsed is not None:
        attach(program, [parsed.block], encode_text(text, form), "sd")
    return program, diagnostics


def _read_text(path: Path, diagnostics: list[Diagnostic]) -> str | None:
    try:
        if path.stat().st_size > MAX_BYTES:
            diagnostics.append(Diagnostic("s7-too-large", {
                "size": path.stat().st_size >> 20, "limit": MAX_BYTES >> 20}, 0, 0))
            return None
        return path.read_bytes().decode("utf-8-sig", "replace")
    except OSError:
        return None


def read_sources(path: Path, diagnostics: list[Diagnostic]) -> list[tuple[Path, Parsed]]:
    """The blocks of a `.db`/`.udt` source beside the program; a source that does not read is
    left out with a warning naming the file and its line."""
    text = _read_text(path, diagnostics)
    if text is None:
        return []
    try:
        return [(path, parsed) for parsed in scl_source.parse_scl(text)]
    except ParseError as error:
        inner = error.diagnostic
        args: dict[str, object] = {"file": path.name, "line": inner.line}
        code = "s7-db-cut" if inner.code == "s7-cut" else "s7-db-syntax"
        args.update(inner.args)
        diagnostics.append(Diagnostic(code, args, 0, 0, Severity.WARNING))
        return []


def companions(folder: Path, entry: Path | None, diagnostics: list[Diagnostic]
               ) -> tuple[list[tuple[Path, Parsed]], list, dict[str, dict[str, str]]]:
    """The SD blocks (but the entry's), tags and texts of a folder."""
    blocks: list[tuple[Path, Parsed]] = []
    tags: list = []
    texts: dict[str, dict[str, str]] = {}
    files = sorted(p for p in folder.iterdir() if p.is_file())
    for path in files:
        suffix = path.suffix.lower()
        if suffix == ".s7res":
            text = _read_text(path, diagnostics)
            if text is not None:
                texts.update(read_texts(text))
        elif suffix == ".xml":
            text = _read_text(path, diagnostics)
            if text is not None and is_tag_table(text):
                found, problems = read_tag_table(text)
                tags += found
                diagnostics += [Diagnostic(d.code, d.args, d.line, d.column, Severity.WARNING)
                                for d in problems]
        elif suffix in SOURCE_SUFFIXES:
            blocks += read_sources(path, diagnostics)
        elif suffix in SD_SUFFIXES and path != entry:
            text = _read_text(path, diagnostics)
            if text is not None:
                other: list[Diagnostic] = []
                parsed = _parse(text, other)
                if parsed is not None:
                    blocks.append((path, parsed))
    return blocks, tags, texts


def open_path(path: Path, data: bytes | None) -> tuple[Program, list[Diagnostic], str]:
    """An SD file with its folder's `.s7res` texts and tag tables, or a folder of exports
    (its OB first): the Program, its diagnostics, the entry file's encoding."""
    diagnostics: list[Diagnostic] = []
    entry: Path | None = path if path.is_file() else None
    folder = path.parent if entry is not None else path
    found, tags, texts = companions(folder, entry, diagnostics)
    if entry is None:  # a folder: its OB, else its first code block, else its first file
        code = [p for p, b in found if b.block.kind in ("OB", "FC", "FB")]
        ob = next((p for p, b in found if b.block.kind == "OB"), None)
        sd = sorted(p for p in folder.iterdir() if p.suffix.lower() in SD_SUFFIXES) or \
            sorted(p for p, _b in found)  # else a folder of sources: DBs and types alone
        entry = ob or (code[0] if code else sd[0] if sd else None)
    blocks = [b for p, b in found if p != entry]
    if entry is None:
        diagnostics.append(Diagnostic("s7-syntax", {"expected": "a .s7dcl block",
                                                    "found": str(path)}, 0, 0))
        program = Program(dialect=NAME)
        return program, diagnostics, "utf-8"
    raw = data if data is not None and path.is_file() else entry.read_bytes()
    text, form, problems, (lines, ends) = decode_lines(raw)
    diagnostics += problems
    if entry.suffix.lower() in SOURCE_SUFFIXES:  # a source: its first code block, the rest
        parsed, more = _source_entry(text, diagnostics)  # of its blocks beside it
        blocks += more
    else:
        parsed = _parse(text, diagnostics)
    program, _graph, _layout = build(([parsed] if parsed else []) + blocks, tags, texts,
                                     diagnostics)
    _source(program, form, lines, ends)
    if parsed is not None:  # a changed source is refused on Save (no writer for "scl")
        source = entry.suffix.lower() in SOURCE_SUFFIXES
        attach(program, [parsed.block], raw, "scl" if source else "sd", entry)
    return program, diagnostics, form.encoding
