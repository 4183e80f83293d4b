"""Compiled native scans kept on disk: the object code and the program's facts by key, so a new
process (a `-j` worker, the IDE started again) loads a program without LLVM compiling it.

The key is the program's hash with the host's target triple, llvmlite's version and a hash of
this package's and the functional instructions' sources (a changed generator never loads an
old object). A file that cannot be read or written is ignored: the program is compiled.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import sys
from functools import lru_cache
from pathlib import Path

from ladderworks.core.plc.native.generator import NativeProgram

FORMAT = 2  # 2: the object code is several object files (jit.pack)
ENV = "LADDERWORKS_NATIVE_CACHE"  # a directory, or "off"


def directory() -> Path | None:
    """Where the files are ($LADDERWORKS_NATIVE_CACHE, else the user's cache directory)."""
    chosen = os.environ.get(ENV, "")
    if chosen.lower() == "off":
        return None
    if chosen:
        return Path(chosen)
    if sys.platform == "win32":
        base = Path(os.environ.get("LOCALAPPDATA") or Path.home() / "AppData" / "Local")
    elif sys.platform == "darwin":
        base = Path.home() / "Library" / "Caches"
    else:
        base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return base / "ladderworks" / "native"


@lru_cache(maxsize=1)
def _code_hash() -> str:
    """A hash of the sources the native code follows (this package, the functions)."""
    from ladderworks.core.plc import functions

    digest = hashlib.sha256()
    for folder in (Path(__file__).parent, Path(functions.__file__).parent):
        for path in sorted(folder.glob("*.py")):
            digest.update(path.read_bytes())
    return digest.hexdigest()


def file_key(key: tuple[str, bool, frozenset[int]], triple: str, version: str) -> str:
    """The files' name for a compiled variant."""
    program, monitored, disabled = key
    text = f"{FORMAT}|{triple}|{version}|{_code_hash()}|{program}|{monitored}|" \
           f"{sorted(disabled)}"
    return hashlib.sha256(text.encode()).hexdigest()[:40]


def load(name: str) -> tuple[bytes, NativeProgram] | None:
    """The object code and program facts stored under `name`, or None."""
    folder = directory()
    if folder is None:
        return None
    try:
        code = (folder / f"{name}.o").read_bytes()
        digest, program = pickle.loads((folder / f"{name}.facts").read_bytes())
    except (OSError, pickle.PickleError, EOFError, AttributeError, ValueError, TypeError):
        return None
    if not isinstance(program, NativeProgram) or digest != hashlib.sha256(code).hexdigest():
        return None  # a damaged or partly written object never reaches LLVM
    return code, program


def store(name: str, code: bytes, program: NativeProgram) -> None:
    """Keep a compiled variant (its IR text left out: it is large and not needed to run)."""
    folder = directory()
    if folder is None or not code:
        return
    facts = NativeProgram("", program.layout, program.calls, program.callbacks, program.edges,
                          program.blocks, program.units, program.labels)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        stored = pickle.dumps((hashlib.sha256(code).hexdigest(), facts))
        for suffix, data in ((".o", code), (".facts", stored)):
            part = folder / f"{name}{suffix}.{os.getpid()}.part"
            part.write_bytes(data)
            os.replace(part, folder / f"{name}{suffix}")
    except OSError:
        return
