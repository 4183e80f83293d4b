"""Every Fatek row native outside fatek.py, for stateful.py to add with one line each: the
rows without a state (`EMITTERS`, builtins' kind) and those with a state block (`STATEFUL`,
stateful.ROWS' kind) of fatek_contacts, fatek_timers, fatek_words, fatek_tables and
fatek_table_ops."""

from __future__ import annotations

from ladderworks.core.plc.native import (
    fatek_contacts,
    fatek_table_ops,
    fatek_tables,
    fatek_timers,
    fatek_words,
)

EMITTERS = {**fatek_contacts.EMITTERS, **fatek_timers.EMITTERS, **fatek_words.EMITTERS}
STATEFUL = {**fatek_contacts.STATEFUL, **fatek_timers.STATEFUL, **fatek_words.STATEFUL,
            **fatek_tables.STATEFUL, **fatek_table_ops.STATEFUL}
