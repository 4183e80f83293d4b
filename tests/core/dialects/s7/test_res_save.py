"""A changed SD network title or comment is written into its `.s7res` (only that entry's line;
every other byte kept), beside the `.s7dcl` Save writes."""

from __future__ import annotations

import shutil
from pathlib import Path

from ladderworks.core.dialects.s7.res_save import res_files, update_res
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.dialects.s7.texts import read_texts
from ladderworks.core.il.reading import parse_file
from ladderworks.paths import EXAMPLES


def _opened(tmp_path: Path) -> tuple[Path, S7Model]:
    folder = tmp_path / "calls"
    shutil.copytree(EXAMPLES / "s7" / "calls", folder)
    program = parse_file(folder / "Main.s7dcl").program
    assert isinstance(program.model, S7Model)
    return folder, program.model


def _retitled(model: S7Model, index: int, lines: list[str]) -> S7Model:
    nets = model.draw()
    changed = [net.copy() for net in nets]
    changed[index].comments = lines
    program, found = model.rebuild(changed)
    assert not found
    assert isinstance(program.model, S7Model)
    return program.model


def test_a_changed_title_rewrites_only_its_line(tmp_path: Path) -> None:
    folder, model = _opened(tmp_path)
    assert res_files(model) == {}  # nothing changed: nothing written
    before = (folder / "Main.s7res").read_bytes()
    written = res_files(_retitled(model, 1, ["Fan: 3 s after the motor"]))
    assert list(written) == [folder / "Main.s7res"]
    after = written[folder / "Main.s7res"]
    assert after.startswith(b"\xef\xbb\xbf")  # its BOM kept
    old, new = before.splitlines(keepends=True), after.splitlines(keepends=True)
    assert len(old) == len(new)
    assert [(a, b) for a, b in zip(old, new, strict=True) if a != b] == [
        (b"    en-US: The fan 3 s after the motor, by the FB\n",
         b"    en-US: 'Fan: 3 s after the motor'\n")]
    texts = read_texts(after.decode("utf-8-sig"))
    assert texts["MLC_m2"] == {"en-US": "Fan: 3 s after the motor",
                               "tr-TR": "Fan motordan 3 s sonra, FB ile"}


def test_a_comment_without_an_id_place_and_a_new_id(tmp_path: Path) -> None:
    """A comment typed under a title: the network's pragma has no comment id, so it has no
    place in the `.s7res` (not written); `update_res` adds an id it does not hold at the
    end and writes a text of several lines as a block."""
    _folder, model = _opened(tmp_path)
    assert res_files(_retitled(model, 0, ["The motor held by the FC", "a comment"])) == {}
    data = b"MultiLingualTexts:\r\n  - id: A\r\n    de-DE: x\r\n"
    out = update_res(data, {"A": "neu", "B": "two\nlines"})
    assert out.decode().split("\r\n") == [
        "MultiLingualTexts:", "  - id: A", "    de-DE: neu", "  - id: B",
        "    en-US: |", "      two", "      lines", ""]
    assert read_texts(out.decode()) == {"A": {"de-DE": "neu"}, "B": {"en-US": "two\nlines"}}
