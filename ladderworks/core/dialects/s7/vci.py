"""TIA Portal's Version Control Interface workspaces: a PLC's exports kept in folders named as
TIA's project tree names them (`Program blocks/…`, `PLC tags/`, `PLC data types/`). A block
opened from such a tree is read with the tag tables, types and other blocks of its whole PLC
folder, not only its own folder (docs/dialects.md, "Real exports tried").
"""

from __future__ import annotations

import os
from pathlib import Path

TREE = frozenset({"program blocks", "plc tags", "plc data types"})
MAX_FILES = 5000  # a PLC's exports; a tree larger than this is read no further
_UP = 4  # how far up from the folder opened the PLC folder is looked for


def root(folder: Path) -> Path | None:
    """The PLC folder of the workspace `folder` is in (the one holding `Program blocks` or
    `PLC tags`), None when it is in none."""
    for place in (folder, *list(folder.parents)[:_UP]):
        try:
            names = {child.name.lower() for child in place.iterdir() if child.is_dir()}
        except OSError:
            continue
        if names & TREE:
            return place
    return None


def files(folder: Path) -> list[Path]:
    """The files to read beside a block of `folder`: the folder's own, or every file of its
    PLC folder's tree (sorted, at most MAX_FILES)."""
    top = root(folder)
    if top is None:
        return sorted(p for p in folder.iterdir() if p.is_file())
    found: list[Path] = []
    visited = 0
    for place, dirs, names in os.walk(top):
        dirs.sort()
        visited += 1 + len(dirs)
        found += [Path(place) / name for name in sorted(names)]
        if len(found) >= MAX_FILES or visited >= MAX_FILES:  # folders count too: no long walk
            break
    return found[:MAX_FILES]
