"""What reaches the terminal: control characters from a spec shown escaped, an ASCII fallback
for terminals that cannot encode rbi's symbols, and the signals that end a run.

Imported by :func:`rbi.cli.app.main` before any command runs, so it uses the standard library
only (``rbi --help`` stays fast).
"""

from __future__ import annotations

import codecs
import contextlib
import errno
import io
import os
import signal
import sys
import unicodedata

from rbi import visible

terminal_safe = visible
"""What reaches the terminal: :func:`rbi.visible`, the one escaper of text from outside."""


def say(message: str) -> None:
    """One line on stderr, ``rbi: message``, with control characters escaped (see
    :func:`terminal_safe`): how every error, warning and note reaches the user."""
    print(f"rbi: {terminal_safe(message)}", file=sys.stderr)


# --- terminals that cannot encode every character ------------------------------------------

SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁻ᵀ", "0123456789-T"))
"""Superscripts, spelled ``^`` and the plain characters (``m²`` → ``m^2``, ``10⁻⁴`` → ``10^-4``)."""

ASCII_SPELLINGS = {
    "·": "*",
    "×": "x",
    "÷": "/",
    "−": "-",
    "–": "-",
    "—": "-",
    "°": "deg",
    "±": "+/-",
    "µ": "u",
    "½": "1/2",
    "≈": "~",
    "≤": "<=",
    "≥": ">=",
    "→": "->",
    "√": "sqrt",
    "∝": "~",
    "∫": "int",
    "⟂": "_|_",
    "⊗": "(x)",
    "•": "*",
    "★": "*",
    "‖": "||",
    "ω": "omega",
    "θ": "theta",
    "φ": "phi",
    "ψ": "psi",
    "α": "alpha",
    "β": "beta",
    "ε": "eps",
    "λ": "lambda",
    "ν": "nu",
    "π": "pi",
    "σ": "sigma",
    "τ": "tau",
    "Ω": "Omega",
    "Σ": "Sigma",
    "Π": "Pi",
    "ᵢ": "_i",
    # rich's table rules, should an ASCII box not be chosen
    "─": "-",
    "━": "-",
    "│": "|",
    "┃": "|",
    "┼": "+",
    "╇": "+",
    "╸": "-",
    "╺": "-",
}
"""Readable ASCII for the symbols rbi prints (units such as ``kg·m²``, Greek letters), used
only when the terminal's encoding cannot show the symbol itself."""

ERROR_HANDLER = "rbi-ascii"


def _ascii_fallback(error: UnicodeError):
    """A codec error handler: each unencodable character as its ASCII spelling, else its
    decomposition's ASCII letters (``é`` → ``e``), else a ``\\uXXXX`` escape."""
    if not isinstance(error, UnicodeEncodeError):
        raise error
    pieces = []
    text = error.object
    for index in range(error.start, error.end):
        char = text[index]
        spelling = ASCII_SPELLINGS.get(char)
        if char in SUPERSCRIPTS:
            after_superscript = index > 0 and text[index - 1] in SUPERSCRIPTS
            spelling = ("" if after_superscript else "^") + SUPERSCRIPTS[char]
        elif spelling is None:
            base = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode("ascii")
            spelling = base if base.isprintable() and base else char.encode("unicode_escape").decode()
        pieces.append(spelling)
    return "".join(pieces), error.end


codecs.register_error(ERROR_HANDLER, _ascii_fallback)


def encodes_unicode(stream) -> bool:
    """Whether ``stream`` writes an encoding that can hold every character (UTF-8/16/32); a
    text buffer without an encoding (``io.StringIO``) holds any text."""
    encoding = getattr(stream, "encoding", None)
    return encoding is None or encoding.lower().replace("_", "-").startswith("utf")


def prepare_streams() -> None:
    """Let stdout and stderr fall back to ASCII spellings (:data:`ASCII_SPELLINGS`) instead of
    raising UnicodeEncodeError on a terminal whose encoding (``PYTHONIOENCODING=cp1252``,
    ``latin-1``, ``ascii``) cannot show a character. UTF-8 streams are left alone; JSON is
    always ASCII and unaffected."""
    for stream in (sys.stdout, sys.stderr):
        if stream is not None and hasattr(stream, "reconfigure") and not encodes_unicode(stream):
            try:
                stream.reconfigure(errors=ERROR_HANDLER)
            except (ValueError, OSError):  # a closed or detached stream: nothing to print to
                pass


def ascii_only() -> bool:
    """Whether standard output cannot show rbi's symbols, so tables should spell them in ASCII."""
    return not encodes_unicode(sys.stdout)


# --- standard output that cannot take the results -------------------------------------------


class StdoutUnwritable(Exception):
    """Standard output refused the results (a full disk or ``/dev/full``, ``rbi ... >&-``, an I/O
    error): the answer cannot reach the user. A reader that left (``| head``) is not this: that
    is :class:`ReaderLeft`, which ends the run quietly."""


class ReaderLeft(Exception):
    """The reader of standard output left (``rbi check a.yaml b.yaml | head -1``): the run ends
    quietly with ``status``, the exit status already known then (0; 1 once a check failed, 2
    once a file was bad input: see :func:`status_kept`). Not an OSError, so that neither click
    nor rich takes the broken pipe for their own (each ends the run with a silent status 1)."""

    def __init__(self, status: int = 0) -> None:
        super().__init__(status)
        self.status = status


@contextlib.contextmanager
def status_kept(status: int):
    """Output written inside belongs to a run whose exit status is already ``status`` (a failed
    check, a bad file): if the reader leaves meanwhile, the run still ends with it, not 0."""
    try:
        yield
    except ReaderLeft as exc:
        exc.status = max(exc.status, status)
        raise


class _ClosedStdout(io.TextIOBase):
    """Standard output when file descriptor 1 is closed (``rbi ... >&-``): every write fails, as
    writing to a closed descriptor does, instead of vanishing (rich) or raising AttributeError."""

    encoding = "utf-8"

    @property
    def buffer(self) -> _ClosedStdout:
        return self

    def writable(self) -> bool:
        return True

    def write(self, data) -> int:
        raise OSError(errno.EBADF, "standard output is closed")


class _GuardedStdout:
    """Standard output (text, or its binary ``buffer``) whose write and flush errors are
    :class:`StdoutUnwritable`; every other attribute is the stream's own."""

    def __init__(self, stream) -> None:
        self._stream = stream

    def __getattr__(self, name: str):
        return getattr(self._stream, name)

    @property
    def buffer(self) -> _GuardedStdout:
        return _GuardedStdout(self._stream.buffer)

    def write(self, data) -> int:
        return self._guarded(self._stream.write, data)

    def flush(self) -> None:
        self._guarded(self._stream.flush)

    @staticmethod
    def _guarded(call, *args):
        try:
            return call(*args)
        except BrokenPipeError:
            raise ReaderLeft() from None
        except OSError as exc:
            raise StdoutUnwritable(exc.strerror or str(exc)) from None


def guard_stdout() -> None:
    """Route every write to standard output through :class:`_GuardedStdout` (a closed descriptor
    1 becomes :class:`_ClosedStdout`), so that results that cannot be written end the run with
    one line (:func:`rbi.cli.app.main`) rather than an internal error or a Python message at exit."""
    sys.stdout = _GuardedStdout(sys.stdout if sys.stdout is not None else _ClosedStdout())


def discard_stdout() -> None:
    """After :class:`StdoutUnwritable`: point descriptor 1 at /dev/null so that what is still
    buffered is dropped silently when Python exits, rather than failing a second time."""
    sys.stdout = None
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.close(devnull)
    except OSError:  # nothing more can be done for a descriptor that is gone
        pass


# --- signals --------------------------------------------------------------------------------


class Terminated(SystemExit):
    """Raised by the SIGTERM handler: unwinds like an exit (a half-written output's temporary
    file is removed on the way), then ends the process with status 143 (128 + SIGTERM)."""

    def __init__(self) -> None:
        super().__init__(128 + signal.SIGTERM)


def _on_sigterm(signum, frame) -> None:
    raise Terminated()


@contextlib.contextmanager
def sigterm_unwinds():
    """Inside, SIGTERM unwinds the run (see :class:`Terminated`) instead of killing the process
    where it stands, so no temporary output file is left behind; the default handling is back
    on leaving. Ctrl-C (SIGINT) already raises KeyboardInterrupt. Only the main thread may
    install handlers, and only a default one is replaced; elsewhere nothing changes."""
    installed = False
    with contextlib.suppress(ValueError):  # not the main thread (an embedding program): its handlers stay
        if signal.getsignal(signal.SIGTERM) in (signal.SIG_DFL, None):
            signal.signal(signal.SIGTERM, _on_sigterm)
            installed = True
    try:
        yield
    finally:
        if installed:
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
