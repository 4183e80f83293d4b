"""plc/families.py (the table's `family` fields), the names the checks read, agrees with the
implementations registered."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.families import FAMILIES, IMPLEMENTED
from ladderworks.core.plc.functions import REGISTRY, function, load_all


def test_the_declared_names_are_the_registry() -> None:
    registry = load_all()
    assert set(registry) == IMPLEMENTED
    for family, names in FAMILIES.items():
        for name in names:
            assert registry[name].__module__ == f"ladderworks.core.plc.functions.{family}"


def test_a_name_its_module_does_not_declare_is_refused() -> None:
    load_all()
    before = dict(REGISTRY)

    def tmr(ctx: object, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
        return False

    with pytest.raises(LookupError, match="must say family='test_families'"):
        function("TMR")(tmr)  # type: ignore[arg-type]
    assert before == REGISTRY


def test_a_declared_name_nothing_registers_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    load_all()
    monkeypatch.delitem(REGISTRY, "TMR")
    with pytest.raises(LookupError, match="not implemented: \\['TMR'\\]"):
        load_all()
