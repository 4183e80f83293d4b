"""The ladder is edited through one object: each undo step's name is written once, there."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import ladderworks
from ladderworks.gui.editor import ladder_edits

GUI = Path(ladderworks.__file__).parent / "gui"
STEP = re.compile(r'editor_step\(QT_TRANSLATE_NOOP\("LadderEditor", "([^"]+)"\)')


def test_each_undo_step_of_the_editor_is_named_once_in_ladder_edits() -> None:
    where: Counter[str] = Counter()
    files: dict[str, set[str]] = {}
    for path in GUI.rglob("*.py"):
        for name in STEP.findall(path.read_text(encoding="utf-8")):
            where[name] += 1
            files.setdefault(name, set()).add(path.name)
    assert where and all(count == 1 for count in where.values()), where
    assert set().union(*files.values()) == {Path(ladder_edits.__file__).name}


def test_ladder_edits_is_a_plain_class() -> None:
    assert ladder_edits.LadderEdits.__mro__ == (ladder_edits.LadderEdits, object)
