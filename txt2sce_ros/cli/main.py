"""`txt2sce` entry point: finds the subcommand modules and runs the chosen one.

Each module `txt2sce_ros/cli/cmd_<name>.py` defines:

    HELP = "one line shown in `txt2sce --help`"
    def register(parser: argparse.ArgumentParser) -> None   # add the subcommand's arguments
    def run(args: argparse.Namespace) -> int                # do the work, return the exit code

so each stage owns its own command without touching a central file.

Exit status, the same for every command: 0 all good; 1 some items (rows, files, bags, runs) failed and were
recorded, the rest kept; 2 unusable input or arguments. Errors raised on purpose (`Txt2SceError`) print as one line
naming the file and element; a file that cannot be opened or written prints its path and the system's reason.
Anything else is a bug: it still prints one line (`internal error`), with the traceback only when
`TXT2SCE_DEBUG=1`.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from pathlib import Path
from types import ModuleType

from .. import __version__
from ..errors import Txt2SceError

PREFIX = "cmd_"


def _command_names() -> dict[str, str]:
    """Command name -> module name, from the file names alone (nothing imported)."""
    # A directory listing, not pkgutil.iter_modules: that imports `inspect` (~10 ms of every cold start).
    here = Path(__file__).parent
    return {f.stem[len(PREFIX):].replace("_", "-"): f"{__package__}.{f.stem}"
            for f in sorted(here.glob(f"{PREFIX}*.py"))}


def _chosen(argv: list[str], names: dict[str, str]) -> str | None:
    """The command named on the command line: the first argument that is not an option (the top-level parser has
    only flag options), if it names a command."""
    first = next((a for a in argv if not a.startswith("-")), None)
    return first if first in names else None


def build_parser(argv: list[str] | None = None) -> argparse.ArgumentParser:
    """The parser; with `argv`, only the command it names gets its arguments registered (its module, and what
    `register` imports, are all a cold start pays for); without one, every command is listed by its HELP line."""
    parser = argparse.ArgumentParser(
        prog="txt2sce",
        description=(
            "Turn AV collision reports into OpenSCENARIO scenarios and test a driving stack with them.\n"
            "Pipeline: extract (report -> sketch) -> seed (sketch -> .xosc) -> tree (mutations) -> run/campaign\n"
            "(closed loop: player + planner + oracle) -> judge/analysis. `txt2sce demo` runs it on bundled data."
        ),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"txt2sce {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    names = _command_names()
    chosen = _chosen(argv, names) if argv is not None else None
    for name, module_name in names.items():
        if chosen is not None and name != chosen:
            continue    # not run: neither imported nor registered (a stub parser alone costs ~2 ms)
        module = importlib.import_module(module_name)
        p = sub.add_parser(name, help=getattr(module, "HELP", ""), description=getattr(module, "HELP", ""),
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        module.register(p)
        p.set_defaults(_run=module.run)
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    # numpy works on small arrays here and the campaign parallelises with processes: OpenBLAS's thread pool,
    # started when numpy is imported, would cost each process ~50 ms of CPU and compete with the workers. Set
    # before any command imports numpy; inherited by the processes a command starts; a user's setting wins.
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    parser = build_parser(argv)
    args = parser.parse_args(argv)
    if not getattr(args, "_run", None):
        parser.print_help()
        return 1
    try:
        return int(args._run(args) or 0)
    except Txt2SceError as exc:
        print(f"txt2sce {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"txt2sce {args.command}: interrupted", file=sys.stderr)
        return 130
    except OSError as exc:
        # A path that cannot be opened or written (--out naming a directory, a full disk, no permission).
        where = exc.filename if exc.filename is not None else ""
        print(f"txt2sce {args.command}: error: {where}{': ' if where else ''}{exc.strerror or exc}", file=sys.stderr)
        return 2
    except MemoryError:
        print(f"txt2sce {args.command}: error: out of memory", file=sys.stderr)
        return 2
    except Exception as exc:  # noqa: BLE001 - the last guard: no traceback reaches a user
        if os.environ.get("TXT2SCE_DEBUG"):
            import traceback

            traceback.print_exc()
        text = " ".join(str(exc).split())[:300]
        print(f"txt2sce {args.command}: internal error: {type(exc).__name__}: {text} "
              f"(please report it; TXT2SCE_DEBUG=1 shows the traceback)", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
