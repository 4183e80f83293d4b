"""The functional instructions each module of `plc/functions` implements, by name, read from the
instruction table's `family` field: the checks read them here to know an instruction has an
implementation without loading one (`check` loads no engine). `plc/functions` keeps them true:
its `function` decorator refuses a name whose row does not name its module, and `load_all`
refuses a row's name that nothing registered."""

from __future__ import annotations

from ladderworks.core import dialects
from ladderworks.core.instructions import FUNCTIONS

FAMILIES: dict[str, tuple[str, ...]] = {}
for _spec in FUNCTIONS:
    if _spec.family:
        FAMILIES.setdefault(_spec.family, ())
        FAMILIES[_spec.family] += (_spec.name,)

# Each dialect's families (its `Dialect.families`: which module runs which of its rows).
for _dialect in dialects.every():
    FAMILIES.update(_dialect.families)

# Every functional instruction that has an implementation.
IMPLEMENTED: frozenset[str] = frozenset(name for names in FAMILIES.values() for name in names)
