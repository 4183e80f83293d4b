"""The packages that import their names when first asked for (il, compiler) give the very
objects of the modules that define them, and nothing else."""

from __future__ import annotations

import importlib
import subprocess
import sys

import pytest

import ladderworks.core.compiler as compiler
import ladderworks.core.il as il
from ladderworks.core.compiler import binary
from ladderworks.paths import CHECKOUT


def test_il_gives_the_objects_of_its_modules() -> None:
    assert set(il._MODULE_OF) == set(il.__all__)
    for name, module in il._MODULE_OF.items():
        defining = importlib.import_module(f"ladderworks.core.il.{module}")
        assert getattr(il, name) is getattr(defining, name)


def test_compiler_gives_the_objects_of_the_binary_module() -> None:
    for name in compiler._BINARY_NAMES:
        assert getattr(compiler, name) is getattr(binary, name)
    assert all(hasattr(compiler, name) for name in compiler.__all__)


@pytest.mark.parametrize("package", [il, compiler])
def test_an_unknown_name_is_an_attribute_error(package: object) -> None:
    with pytest.raises(AttributeError, match="has no attribute 'nosuch'"):
        package.nosuch  # type: ignore[attr-defined]  # noqa: B018


SCRIPT = """
import sys
from ladderworks.core.compiler import check
from ladderworks.core.il import parse_file
lazy = ("ladderworks.core.compiler.binary", "ladderworks.core.il.printer")
print(*(m in sys.modules for m in lazy))
from ladderworks.core.il import *
print(*(m in sys.modules for m in lazy))
"""


def test_a_package_loads_a_module_only_for_a_name_asked_for() -> None:
    done = subprocess.run([sys.executable, "-c", SCRIPT], cwd=CHECKOUT, capture_output=True,
                          text=True, timeout=120, check=True)
    assert done.stdout.splitlines() == ["False False", "False True"]  # `*`: every name of il
