"""The functional instructions each module of `plc/functions` implements, by name, read from the
instruction table's `family` field: the checks read them here to know an instruction has an
implementation without loading one (`check` loads no engine). `plc/functions` keeps them true:
its `function` decorator refuses a name whose row does not name its module, and `load_all`
refuses a row's name that nothing registered."""

from __future__ import annotations

from ladderworks.core.instructions import FUNCTIONS, implemented

FAMILIES: dict[str, tuple[str, ...]] = {}
for _spec in FUNCTIONS:
    if _spec.family:
        FAMILIES.setdefault(_spec.family, ())
        FAMILIES[_spec.family] += (_spec.name,)

# Every functional instruction that has an implementation.
IMPLEMENTED: frozenset[str] = implemented()
