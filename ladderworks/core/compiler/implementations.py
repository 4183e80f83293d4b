"""Which implementation a functional instruction runs: the registry's, the functions
package's generic entry, or the CNC stub (the checks and the code generator ask here)."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ladderworks.core.instructions import Combine, InstructionSpec

if TYPE_CHECKING:
    from ladderworks.core.plc.functions import FunctionImpl


def cnc_stub(ctx: object, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """A CNC-side or unknown instruction with no CNC: W1 = ACT (docs/instructions.md)."""
    return bool(inputs[-1]) if inputs else False


def passes_input(ctx: object, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """A box shown but not simulated: nothing happens, its input is passed on."""
    return bool(inputs[-1]) if inputs else False


def never_conducts(ctx: object, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """A contact (LD or AND form) shown but not simulated: it never conducts."""
    return False


def not_simulated(spec: InstructionSpec) -> FunctionImpl:
    """What a shown-only row (`simulated` False) runs: an OR contact passes its input on (the
    contact adds nothing), an LD or AND contact never conducts; a box's W1 (Fatek's FO0) is
    off, a box without one (a Delta output) passes the rung's power on."""
    if spec.combine in (Combine.READ, Combine.AND) or (spec.combine is Combine.NONE and spec.w1):
        return never_conducts
    return passes_input


def implementation_of(spec: InstructionSpec,
                      registry: dict[str, FunctionImpl]) -> FunctionImpl | None:
    """The implementation of a functional instruction: the registry's, a shown-only row's no-op,
    else `impl_for`'s (the functions package's generic entry, when it has one), else the CNC
    stub for an unknown SUB."""
    impl = registry.get(spec.name)
    if impl is not None:
        return impl
    if not spec.simulated:
        return not_simulated(spec)
    from ladderworks.core.plc import functions  # loaded with the engine, never by `check`

    impl_for: Callable[[InstructionSpec], Any] | None = getattr(functions, "impl_for", None)
    if impl_for is not None and (spec.cnc or not spec.known):
        try:
            found = impl_for(spec)
        except (KeyError, LookupError):
            found = None
        if found is not None:
            return found
    return cnc_stub if not spec.known else None
