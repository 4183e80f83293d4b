"""The PMC models a program can be written for: the one list the parser, the checks and the
Program properties dialog read (a dialect added later registers here and shows up there)."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.il.program import FANUC, SEED

FANUC_PMC = "fanuc-pmc"  # the family of the seed's and FANUC's PMC ladder (same file form)


@dataclass(frozen=True, slots=True)
class PmcModel:
    """A model: its key (`Program.dialect`), its English title, the family of file forms it
    belongs to (a program's model may change only within its family)."""

    key: str
    title: str
    family: str


MODELS: dict[str, PmcModel] = {}


def register(model: PmcModel) -> PmcModel:
    """Add a model to the list (its key must be new)."""
    if model.key in MODELS:
        raise ValueError(f"PMC model {model.key!r} is registered twice")
    MODELS[model.key] = model
    return model


def model_of(key: str) -> PmcModel:
    """The model of a key; an unknown key is a model of its own family (shown read-only)."""
    return MODELS.get(key) or PmcModel(key, key, key)


def same_family(key: str) -> list[PmcModel]:
    """The models a program of model `key` may be changed to (its own included)."""
    family = model_of(key).family
    return [model for model in MODELS.values() if model.family == family]


register(PmcModel(SEED, "LadderWorks (seed manual)", FANUC_PMC))
register(PmcModel(FANUC, "FANUC Series 30i-A PMC (memory-B)", FANUC_PMC))
