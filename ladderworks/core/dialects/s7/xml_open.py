"""Open SimaticML exports: one block document with its folder's companions, or a folder of
XML (and SD) exports — blocks, global and instance DBs, tag tables — as one program.

The entry is the document opened (its first OB/FC/FB), or a folder's first OB, else its first
code block. An unchanged entry file saves byte for byte (the S7 reader's FileSource).
"""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.dialects.s7 import reader, vci
from ladderworks.core.dialects.s7.graph import Block, S7Program, Tag
from ladderworks.core.dialects.s7.sd_parser import Parsed
from ladderworks.core.dialects.s7.texts import read_texts
from ladderworks.core.dialects.s7.xml_reader import (
    EXPORT_KINDS,
    XmlRead,
    check_calls,
    is_simaticml,
    read_document,
)
from ladderworks.core.dialects.s7.xml_safe import MAX_BYTES
from ladderworks.core.il.program import Program
from ladderworks.core.il.textform import TextForm, decode_lines, encode_text

CODE = ("OB", "FC", "FB")


def _head(path: Path) -> str:
    try:
        with open(path, "rb") as file:
            return file.read(4000).decode("utf-8", "replace")
    except OSError:
        return ""


def _is_block_file(path: Path, kinds: tuple[str, ...] = ("SW.Blocks.",)) -> bool:
    if path.suffix.lower() != ".xml":
        return False
    head = _head(path)
    return "<Document" in head and any(kind in head for kind in kinds)


def wants(path: Path, data: bytes | None) -> bool:
    """True when `path` is a SimaticML block document, or a folder whose blocks are XML only."""
    if path.is_dir():  # a folder of exports, or a folder of a TIA VCI workspace (vci.py)
        files = vci.files(path)
        return not any(p.suffix.lower() in reader.SD_SUFFIXES for p in files) and \
            any(_is_block_file(p) for p in files)
    head = data[:200000].decode("utf-8", "replace") if data is not None else _head(path)
    if is_simaticml(head) or head.lstrip().startswith("<SW."):  # a piece of an export (no
        return True  # Document): the XML reader names what it lacks (s7xml-empty)
    return data is None and _is_block_file(path, EXPORT_KINDS)


def _read_file(path: Path, diagnostics: list[Diagnostic]) -> XmlRead | None:
    try:
        size = path.stat().st_size
        if size > MAX_BYTES:
            diagnostics.append(Diagnostic("s7xml-too-large", {
                "size": size // (1024 * 1024), "limit": MAX_BYTES // (1024 * 1024)}, 0, 0))
            return None
        return read_document(path.read_bytes())
    except OSError:
        return None


def _companions(folder: Path, entry: Path | None, diagnostics: list[Diagnostic],
                extra: dict[str, str]
                ) -> tuple[list[Block], list[Tag], dict[str, dict[str, str]], list[Parsed]]:
    """The XML blocks and tags, the SD blocks and texts of a folder, the entry file left out;
    the FBs of the instance DBs the XML calls name go into `extra`."""
    blocks: list[Block] = []
    tags: list[Tag] = []
    texts: dict[str, dict[str, str]] = {}
    sd: list[Parsed] = []
    for path in (p for p in vci.files(folder) if p != entry):
        suffix = path.suffix.lower()
        if suffix == ".xml":
            found = _read_file(path, diagnostics)
            if found is None:
                continue
            blocks += found.blocks
            tags += found.tags
            extra.update(found.instances)
            diagnostics += [Diagnostic(d.code, d.args, d.line, d.column, Severity.WARNING)
                            for d in found.diagnostics if d.code != "s7xml-empty"]
        elif suffix == ".s7res":
            text = path.read_bytes().decode("utf-8-sig", "replace")
            texts.update(read_texts(text))
        elif suffix in reader.SOURCE_SUFFIXES:
            sd += [parsed for _path, parsed in reader.read_sources(path, diagnostics)]
        elif suffix in reader.SD_SUFFIXES:
            parsed = reader._parse(path.read_bytes().decode("utf-8-sig", "replace"), [])
            if parsed is not None:
                sd.append(parsed)
    return blocks, tags, texts, sd


def read(text: str, form: TextForm, lines: list[str],
         ends: list[str]) -> tuple[Program, list[Diagnostic]]:
    """One SimaticML document's text (no companion files) as a Program."""
    found = read_document(text)
    diagnostics = list(found.diagnostics)
    program, _graph = _build(found.blocks, [], found.tags, {}, diagnostics, None,
                            found.instances)
    reader._source(program, form, lines, ends)
    _attach(program, found, encode_text(text, form))
    return program, diagnostics


def _build(entry_blocks: list[Block], others: list[Block], tags: list[Tag],
           texts: dict[str, dict[str, str]], diagnostics: list[Diagnostic],
           sd: list[Parsed] | None = None, instances: dict[str, str] | None = None
           ) -> tuple[Program, S7Program]:
    every = entry_blocks + others + [p.block for p in sd or []]
    names = {b.name.lower() for b in every}
    for db, fb in (instances or {}).items():  # an FB call's instance DB not exported with it
        if db.lower() not in names:
            others = [*others, Block("InstanceDB", db, instance_of=fb)]
            every.append(others[-1])
            names.add(db.lower())
    check_calls(every, diagnostics)
    code = [b for b in entry_blocks if b.kind in CODE]
    rest = [b for b in entry_blocks if b.kind not in CODE] + others
    parsed = [Parsed(b) for b in code + rest] + list(sd or [])
    program, graph, _layout = reader.build(parsed, tags, texts, diagnostics)
    return program, graph


def open_path(path: Path, data: bytes | None) -> tuple[Program, list[Diagnostic], str]:
    """A SimaticML document with its folder's blocks, DBs and tag tables, or a folder of
    exports (its first OB first): the Program, its diagnostics, the entry file's encoding."""
    diagnostics: list[Diagnostic] = []
    entry: Path | None = path if path.is_file() else None
    folder = path.parent if entry is not None else path
    extra: dict[str, str] = {}
    blocks, tags, texts, sd = _companions(folder, entry, diagnostics, extra)
    if entry is None:
        owners = [p for p in vci.files(folder) if _is_block_file(p)]
        obs = [p for p in owners if "SW.Blocks.OB" in _head(p)]  # OB1 first, else any OB
        entry = next((p for p in obs if _number(p) == 1), obs[0] if obs else None) or \
            next((p for p in owners if any(f"SW.Blocks.{k}" in _head(p) for k in CODE)), None)
        if entry is None:
            diagnostics.append(Diagnostic("s7xml-empty", {}, 0, 0))
            return Program(dialect=reader.NAME), diagnostics, "utf-8"
        blocks = [b for b in blocks if b.name not in _names(entry)]
    if data is not None and path.is_file():
        raw = data
    else:
        try:
            if entry.stat().st_size > MAX_BYTES:
                diagnostics.append(Diagnostic("s7xml-too-large", {
                    "size": entry.stat().st_size // (1024 * 1024),
                    "limit": MAX_BYTES // (1024 * 1024)}, 0, 0))
                return Program(dialect=reader.NAME), diagnostics, "utf-8"
            raw = entry.read_bytes()
        except OSError:
            return Program(dialect=reader.NAME), diagnostics, "utf-8"
    if len(raw) > MAX_BYTES:
        diagnostics.append(Diagnostic("s7xml-too-large", {
            "size": len(raw) // (1024 * 1024), "limit": MAX_BYTES // (1024 * 1024)}, 0, 0))
        return Program(dialect=reader.NAME), diagnostics, "utf-8"
    found = read_document(raw)
    diagnostics += found.diagnostics
    text, form, problems, (lines, ends) = decode_lines(raw)
    del text
    diagnostics += problems
    instances = {**extra, **found.instances}
    program, _graph = _build(found.blocks, blocks, found.tags + tags, texts, diagnostics, sd,
                            instances)
    reader._source(program, form, lines, ends)
    _attach(program, found, raw, entry)
    return program, diagnostics, form.encoding


def _attach(program: Program, found: XmlRead, data: bytes, path: Path | None = None) -> None:
    """Keep the document as read in the program's model for a Save of a changed entry block
    (saving.py), when the entry block is this document's."""
    reader.attach(program, found.blocks, data, "xml", path)


def _names(path: Path) -> set[str]:
    found = _read_file(path, [])
    return {b.name for b in found.blocks} if found is not None else set()


def _number(path: Path) -> int:
    """The number of a document's first block (0 when it has none)."""
    found = _read_file(path, [])
    return found.blocks[0].number if found is not None and found.blocks else 0
