"""The ``mechverify`` command: check designs, diff revisions for CI, browse data, explain checks.

Exit codes: 0 all checks pass, 1 a check fails (or a margin was lost, for ``diff``), 2 invalid input
(a usage error, an invalid design file, a refused output path), 3 an internal error (a bug).

Structure (standard-library ``argparse``; start-up imports nothing but the standard library, so
``mechverify --help`` needs neither numpy nor pint nor rich):

- every public module of this package (name not starting with ``_``) is a *command module*, found by
  listing the package; it provides ``add_parser(subparsers) -> None``, which adds one or more
  sub-commands, each ending with ``parser.set_defaults(run=run)`` where ``run(args) -> int`` returns
  the exit code; an optional module constant ``ORDER`` (int, default 100) sorts the commands in ``--help``;
- a command module imports only the standard library at module level; everything else (mechverify's
  models, rich, numpy) is imported inside ``run``;
- ``run`` raises :class:`Invalid` or any :class:`mechverify.errors.MechverifyError` for exit 2: the
  message is printed without a traceback;
- helpers: :mod:`mechverify.cli._console` (rich consoles and the results table, imported lazily),
  :mod:`mechverify.cli._common` (argument helpers, output-path validation before any check runs).
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import signal
import sys
import warnings
from types import ModuleType
from typing import NoReturn

EXIT_PASS, EXIT_FAIL, EXIT_INVALID, EXIT_BUG = 0, 1, 2, 3


class Invalid(Exception):
    """Raised inside commands for exit status 2 with a message."""


class _Parser(argparse.ArgumentParser):
    """argparse with usage errors as exit status 2 (argparse's own convention) and full option names."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", _Formatter)
        super().__init__(*args, **kwargs)


class _Formatter(argparse.HelpFormatter):
    """Help wrapped to the terminal's width (``COLUMNS`` or the terminal; argparse's default) with the
    column of option names wide enough for the longest name, so that no name is cut."""

    def __init__(self, prog: str, **kwargs):
        kwargs.setdefault("max_help_position", 32)
        super().__init__(prog, **kwargs)

    def add_argument(self, action: argparse.Action) -> None:
        super().add_argument(action)
        if isinstance(action, argparse._SubParsersAction):  # argparse forgets the commands' indentation
            for sub in action._get_subactions():
                n = len(self._format_action_invocation(sub)) + self._current_indent + 2 * self._indent_increment
                self._action_max_length = max(self._action_max_length, n)


def command_modules() -> list[ModuleType]:
    """The command modules of this package, in ``--help`` order."""
    mods = [importlib.import_module(f"{__name__}.{m.name}") for m in pkgutil.iter_modules(__path__)
            if not m.name.startswith("_")]
    return sorted(mods, key=lambda m: (getattr(m, "ORDER", 100), m.__name__))


#: Command -> the module of this package that defines it: a run of one command builds only that command's parser
#: and imports only its module (``tests/test_cli_main.py`` checks this table against the modules).
COMMANDS = {"check": "check", "study": "study", "select-motor": "select_motor", "size": "size", "diff": "diff",
            "explain": "explain", "init": "init", "schema": "schema", "materials": "catalogues",
            "threads": "catalogues", "bearings": "catalogues", "motors": "catalogues", "faces": "faces"}


class _Version(argparse.Action):
    """``--version``: the installed distribution's version, looked up only when asked for."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS, help=None):
        super().__init__(option_strings, dest=dest, default=default, nargs=0,
                         help=help or "show program's version number and exit")

    def __call__(self, parser, namespace, values, option_string=None):
        sys.stdout.write(f"mechverify {_version()}\n")  # on stdout, as argparse's own version action
        parser.exit()


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The command line's parser; with ``command`` (one of :data:`COMMANDS`) only that command's sub-parser."""
    parser = _Parser(prog="mechverify", description="Verify the mechanical design of small machines and robots.",
                     epilog="Exit status: 0 all checks pass, 1 a check fails, 2 invalid input. "
                            "'mechverify COMMAND --help' describes a command.")
    parser.add_argument("--version", action=_Version)
    sub = parser.add_subparsers(title="commands", metavar="COMMAND", parser_class=_Parser)
    mods = [importlib.import_module(f"{__name__}.{COMMANDS[command]}")] if command in COMMANDS else command_modules()
    for mod in mods:
        mod.add_parser(sub)
    return parser


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("mechverify")
    except PackageNotFoundError:
        return "0.0.0+source"


def _on_sigterm(signum, frame):
    # turn SIGTERM into an exception so that temporary files and folders are removed on the way out
    raise SystemExit(128 + signum)


def _show_warning(message, category, filename, lineno, file=None, line=None) -> None:
    """A warning as one line, ``warning: message``, without the source line of the code that raised it."""
    sys.stderr.write(f"warning: {message}\n")


def _own_warning_classes() -> type[Warning]:
    from mechverify.units import PlausibilityWarning

    return PlausibilityWarning


def error(message: str) -> None:
    """Print ``error: message`` on stderr (no rich: also used before anything heavy is imported)."""
    sys.stderr.write(f"error: {message}\n")
    sys.stderr.flush()


def entry() -> NoReturn:
    """The ``mechverify`` command (console script) and ``python -m mechverify.cli``: :func:`main`, then a fast exit.

    Once the command has returned and its output is flushed, the process ends with ``os._exit``, as mypy's
    ``--fast-exit`` does: the interpreter's teardown, which frees every module and object one by one, is skipped
    (~80 ms CPU after a check of the lead-screw lift, ~50 ms after ``import numpy, pint`` alone; issue 27,
    docs/performance.md). The atexit handlers still run (``weakref.finalize`` clean-ups such as temporary
    folders, logging). With another thread still running, or ``MECHVERIFY_SLOW_EXIT`` set, the exit is the
    normal one (which waits for non-daemon threads). Tests call :func:`main`, which returns the status.
    """
    import atexit
    import os
    import threading

    code = main()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe (`mechverify materials | head`) or a closed stream
            pass
    run_exit_handlers = getattr(atexit, "_run_exitfuncs", None)
    if threading.active_count() > 1 or os.environ.get("MECHVERIFY_SLOW_EXIT") or run_exit_handlers is None:
        sys.exit(code)
    run_exit_handlers()
    os._exit(code)


def main(argv: list[str] | None = None) -> int:
    """Entry point: parse, run the command, turn every error into a message and an exit status."""
    argv = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(argv[0] if argv else None)
    if not argv:
        parser.print_help(sys.stderr)
        return EXIT_INVALID
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version (0) and usage errors (2)
        return exc.code if isinstance(exc.code, int) else EXIT_INVALID
    if getattr(args, "run", None) is None:
        parser.print_help(sys.stderr)
        return EXIT_INVALID
    previous = None
    try:
        previous = signal.signal(signal.SIGTERM, _on_sigterm)
    except ValueError:  # not the main thread
        pass
    from mechverify.errors import MechverifyError

    try:
        with warnings.catch_warnings():
            warnings.showwarning = _show_warning
            if getattr(args, "quiet", False):  # -q: only mechverify's own warnings (a plausibility warning...)
                warnings.filterwarnings("ignore")
                warnings.filterwarnings("default", module=r"mechverify(\..*)?$")
                warnings.filterwarnings("default", category=_own_warning_classes())
            return int(args.run(args) or 0)
    except (Invalid, MechverifyError) as exc:
        error(str(exc))
        return EXIT_INVALID
    except KeyboardInterrupt:
        error("interrupted")
        return 130
    except BrokenPipeError:  # `mechverify materials | head`
        return EXIT_PASS
    except Exception as exc:  # anything unforeseen is a bug: say so, without a traceback
        error(f"internal error: {type(exc).__name__}: {exc}\n"
              "This is a bug in mechverify; please report it with the design file.")
        return EXIT_BUG
    finally:
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)
