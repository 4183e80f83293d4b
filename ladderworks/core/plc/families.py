"""The functional instructions each module of `plc/functions` implements, by name, read from the
instruction table's `family` field: the checks read them here to know an instruction has an
implementation without loading one (`check` loads no engine). `plc/functions` keeps them true:
its `function` decorator refuses a name whose row does not name its module, and `load_all`
refuses a row's name that nothing registered."""

from __future__ import annotations

from ladderworks.core.dialects.delta.instructions import FAMILIES as DELTA_FAMILIES
from ladderworks.core.instructions import FUNCTIONS, implemented

FAMILIES: dict[str, tuple[str, ...]] = {}
for _spec in FUNCTIONS:
    if _spec.family:
        FAMILIES.setdefault(_spec.family, ())
        FAMILIES[_spec.family] += (_spec.name,)

# A dialect's families (core/dialects/<name>/instructions.py says which module runs which row).
FAMILIES.update(DELTA_FAMILIES)

# Every functional instruction that has an implementation.
IMPLEMENTED: frozenset[str] = implemented() | {name for names in DELTA_FAMILIES.values()
                                               for name in names}
