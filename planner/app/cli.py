"""The ``planner`` command line: :func:`main` parses (:mod:`planner.app.arguments`), runs
the command (:mod:`planner.app.commands`) and turns what goes wrong into an exit code and a
message. No science here.

Exit codes (one meaning each, :mod:`planner.app.commands`' ``EXIT_*``): 0 success; 1 plan
written, some samples unmet (``plan`` only); 2 bad input or an unusable output place (a
message on stderr, nothing written); 3 an internal error (a bug: a one-line message and the
log file with the details); 130 stopped by Ctrl+C.
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import sys
import tempfile
import time
import traceback
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

from planner.app.arguments import build_parser
from planner.app.commands import (
    EXIT_BAD_INPUT,
    EXIT_INTERNAL,
    EXIT_INTERRUPTED,
    EXIT_OK,
    command_started,
)
from planner.errors import PlannerError
from planner.text import printable


def _log_internal_error(exc: BaseException) -> Path | None:
    """Write the traceback of an unexpected error to a log file; its path, or None."""
    try:
        fd, name = tempfile.mkstemp(
            prefix=f"tls-planner-error-{time.strftime('%Y%m%d-%H%M%S')}-", suffix=".log"
        )
        with open(fd, "w", encoding="utf-8") as fh:
            fh.write(f"planner {' '.join(sys.argv[1:])}\n\n")
            fh.write("".join(traceback.format_exception(exc)))
        return Path(name)
    except OSError:
        return None


@contextlib.contextmanager
def _stop_on_signals():
    """SIGTERM and SIGHUP end the command like Ctrl+C does: as an exception, so that every
    temporary file is removed on the way out (exit code 128 + the signal's number)."""

    def stop(signum: int, _frame: object) -> None:
        raise SystemExit(128 + signum)

    previous = {}
    for sig in (signal.SIGTERM, signal.SIGHUP):
        with contextlib.suppress(ValueError, OSError):  # not the main thread: leave it be
            previous[sig] = signal.signal(sig, stop)
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


class _PrintableStream:
    """A text stream that writes user text as :func:`planner.text.printable` shows it: an
    id's ESC never reaches the terminal, a file name that is not UTF-8 prints as its bytes."""

    def __init__(self, stream: Any) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        # a line's leading carriage return is the progress bar's own (it redraws its line)
        lead = "\r" if text.startswith("\r") else ""
        return self._stream.write(lead + printable(text[len(lead) :], keep="\n\t"))

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


@contextlib.contextmanager
def _printable_output() -> Iterator[None]:
    """stdout and stderr as :class:`_PrintableStream` for the command's run."""
    out, err = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = _PrintableStream(out), _PrintableStream(err)
    try:
        yield
    finally:
        sys.stdout, sys.stderr = out, err


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command; the one boundary that turns every error into a message and an exit
    code (never a traceback): bad input 2, an unusable output place 2, a bug 3."""
    with _printable_output():
        return _main(argv)


def _main(argv: Sequence[str] | None) -> int:
    # the command's start: the process's when this process is the command (argv from its
    # command line), else now (called in a running program)
    started = command_started() if argv is None else time.monotonic()
    args = build_parser().parse_args(argv)
    args.started = started
    func: Callable[[argparse.Namespace], int] = args.func
    try:
        with _stop_on_signals():
            return func(args)
    except PlannerError as exc:
        print(f"planner: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except OSError as exc:
        if isinstance(exc, BrokenPipeError):
            return EXIT_OK
        where = f" {exc.filename!r}" if exc.filename else ""
        print(
            f"planner: error: cannot use{where}: {exc.strerror or exc}; check the path, the "
            "permissions and the free disk space",
            file=sys.stderr,
        )
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("planner: stopped", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Exception as exc:  # a bug: one line, and the details in a log file
        log = _log_internal_error(exc)
        print(
            f"planner: internal error ({type(exc).__name__}: {str(exc)[:200]}); this is a bug"
            + (f" — details in {log}" if log else ""),
            file=sys.stderr,
        )
        return EXIT_INTERNAL
