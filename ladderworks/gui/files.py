"""Writing program files safely: atomic, through symlinks, keeping the mode, never read-only."""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from pathlib import Path


class ReadOnlyFile(PermissionError):
    """The file exists and may not be written: it is never replaced."""


def write_target(path: str | Path) -> Path:
    """The file a write to `path` changes: a symlink's target (the link itself stays)."""
    return Path(os.path.realpath(path))


def default_mode() -> int:
    """The mode of a new file: 0666 minus the process umask (as the shell creates files)."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def is_read_only(path: str | Path) -> bool:
    """True when `path` (through symlinks) exists and is not writable for the user, or has no
    write bit at all (root may write anything; a file marked read-only is still kept)."""
    target = write_target(path)
    try:
        mode = target.stat().st_mode
    except FileNotFoundError:
        return False
    return not os.access(target, os.W_OK) or not mode & (stat.S_IWUSR | stat.S_IWGRP
                                                         | stat.S_IWOTH)


def atomic_write_bytes(path: str | Path, data: bytes) -> None:
    """Write `data` to `path` via a temporary file and a rename: never a half-written file.

    A symlink is written through; an existing file keeps its mode, a new one gets the default
    mode. Raises ReadOnlyFile for a read-only file, OSError when writing fails."""
    target = write_target(path)
    if is_read_only(target):
        raise ReadOnlyFile(13, "the file is read-only", str(path))
    try:
        mode = stat.S_IMODE(target.stat().st_mode)
    except FileNotFoundError:
        mode = default_mode()
    handle, temp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp",
                                         dir=target.parent)
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.chmod(temp_name, mode)
        os.replace(temp_name, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp_name)
        raise


def atomic_write(path: str | Path, text: str, encoding: str = "utf-8") -> None:
    """Write `text` in `encoding` atomically (see atomic_write_bytes); a character the encoding
    cannot hold raises UnicodeEncodeError and nothing is written (never a `?`)."""
    atomic_write_bytes(path, text.encode(encoding, errors="surrogateescape"))
