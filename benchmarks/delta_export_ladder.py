"""A real WPLSoft export (../shared/real-programs/delta, a lathe): the share of its networks drawn
as ladder (the rest kept as instruction lists), and ms to read and lay it out; run from the
repository root."""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import median_ms, real_folder  # noqa: E402

from ladderworks.core.il.reading import parse_file  # noqa: E402
from ladderworks.core.ladder.convert import program_to_ladder  # noqa: E402

NAME = "METALURGICA_c91257f_proejto_clp.csv"


def main() -> int:
    """Print the figures."""
    folder = real_folder()
    path = folder / "delta" / NAME if folder is not None else None
    if path is None or not path.exists():
        print(f"{NAME}: not found beside the repository (../shared/real-programs/delta)")
        return 1
    result = parse_file(path)
    doc = program_to_ladder(result.program)
    listed = sum(net.listing is not None for net in doc.networks)
    total = len(doc.networks)
    errors = sum(d.is_error for d in result.diagnostics)
    print(f"{NAME}: {total} networks, {total - listed} drawn as ladder, {listed} as "
          f"instruction lists: {100 * (total - listed) / total:.1f} % ladder "
          f"({errors} reader errors)")
    print(f"read {median_ms(lambda: parse_file(path), 20):.2f} ms, lay out "
          f"{median_ms(lambda: program_to_ladder(result.program), 20):.2f} ms (median of 20)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
