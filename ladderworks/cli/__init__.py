"""ladderworks-cli: the headless commands; each module of this package adds its subcommands."""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Sequence
from typing import NoReturn

from ladderworks import version

# The module that adds each subcommand: a run imports only its command's module (`check` does
# not load the PLC engine); tests/core/test_cli_commands.py keeps this true to the modules.
COMMANDS: dict[str, str] = {
    "alarms": "alarms", "check": "text", "compile": "plc", "disasm": "plc", "format": "text",
    "ladder": "ladder", "mnemonic": "ladder", "pdw": "pdw", "run": "plc", "serve": "serve",
    "signals": "signals", "test": "scenario", "xref": "xref",
}


class _Version(argparse.Action):
    """`--version`: prints `ladderworks-cli VERSION` (the version is read only when asked)."""

    def __call__(self, parser: argparse.ArgumentParser, namespace: argparse.Namespace,
                 values: object, option_string: str | None = None) -> None:
        print(f"{parser.prog} {version()}")
        parser.exit()


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The argument parser with every subcommand of every module in this package, or only
    the subcommands of the module that adds `command`."""
    parser = argparse.ArgumentParser(
        prog="ladderworks-cli", description="LadderWorks command-line tools")
    parser.add_argument("--version", action=_Version, nargs=0,
                        help="show program's version number and exit")
    subparsers = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    if command in COMMANDS:
        names = [COMMANDS[command]]
    else:
        import pkgutil  # only to list every command module

        names = sorted(info.name for info in pkgutil.iter_modules(__path__))
    for name in names:
        if name.startswith("_"):  # __main__ runs the CLI when imported
            continue
        module = importlib.import_module(f"{__name__}.{name}")
        register = getattr(module, "register", None)
        if register is not None:
            register(subparsers)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run one subcommand; returns the process exit code."""
    words = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(words[0] if words else None)
    args = parser.parse_args(words)
    from ladderworks.cli._programs import use_dialect

    use_dialect(args)
    try:
        return int(args.handler(args) or 0)
    except BrokenPipeError:
        return 0
    except OSError as exc:
        print(f"ladderworks-cli: {exc}", file=sys.stderr)
        return 2


def run() -> NoReturn:
    """The `ladderworks-cli` program: `main()`, then exit once the output is flushed, without
    tearing the interpreter down (freeing the ~400,000 objects of a real FANUC program takes
    ~10 ms and changes nothing: the commands hold no other open file; mypy exits so too)."""
    code = main()
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except BrokenPipeError:  # `ladderworks-cli check FILE | head`: the reader has gone
        pass
    os._exit(code)


if __name__ == "__main__":
    run()
