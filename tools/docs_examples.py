"""The command examples of README.md and docs/*.md: find them, run them, compare what they print.

Shared by the docs test (tests/test_docs_examples.py) and the tool that rewrites the examples
from real runs (tools/regen_docs.py). The convention, also described in docs/README.md:

* A command example is a fenced block whose first line starts with ``$ ``. Every ``$ `` line
  in it is run; the lines after it, up to the next ``$ `` line or the end of the block, are
  what it prints: standard output and standard error interleaved, as a terminal shows them,
  with ``COLUMNS=80`` and ``NO_COLOR=1``. Trailing spaces and trailing empty lines are ignored.
* Commands that can be run: ``rbi ARGS`` (shell quoting and ``*`` globs as in bash), ``echo $?``
  (the exit status of the command before), ``mkdir DIR``, ``cat FILE | rbi ARGS`` (FILE on
  standard input), and ``python SCRIPT ARGS`` or ``.venv/bin/python SCRIPT ARGS``. Anything else
  (other pipes, redirections) fails the test: show such commands in a block without ``$ ``.
* Only the README's first command's install set can be imported while they run
  (:func:`only_the_readme_install`); a ``python SCRIPT`` may import what its ``# needs: MODULE``
  lines name (its page says so).
* The commands of one page run in order, in one fresh temporary folder holding ``bodies/``,
  ``docs/`` and ``tools/`` of the repository, so paths read as from the repository's root and
  files a command writes land in the temporary folder.
* A fenced block whose first line is ``# file: NAME`` (YAML, CSV, Python) or
  ``<!-- file: NAME -->`` (XML) is written to NAME in that folder, whole, before the commands
  after it on the page run: a page can show the file a command reads.
* Output that changes from run to run (wall times, step counts that depend on the machine) is
  written ``...``: a line that is just ``...`` stands for any number of lines (none included);
  ``...`` inside a line for any text on that line, the spaces around it included (so a
  right-aligned column may change width).
"""

from __future__ import annotations

import contextlib
import difflib
import functools
import glob
import io
import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
LINKED = ("bodies", "docs", "tools")
ENVIRONMENT = {"COLUMNS": "80", "NO_COLOR": "1", "LINES": "200"}
WILDCARD = "..."

_FENCE = re.compile(r"^(```+)([^\n]*)\n(.*?)^\1[ \t]*$", re.S | re.M)
_FILE_MARK = re.compile(r"^(?:#|<!--)\s*file:\s*(\S+?)\s*(?:-->)?\s*$")


@dataclass
class Command:
    """One ``$ `` line and the lines shown after it (``shown``: without trailing spaces)."""

    line: str
    shown: list[str]


@dataclass
class Block:
    """A fenced block of a page: a command example, or a file to write (``file_name``)."""

    start: int  # offset in the page's text of the block's body
    end: int  # offset just past its body
    commands: list[Command] = field(default_factory=list)
    file_name: str | None = None
    body: str = ""


def blocks(text: str) -> list[Block]:
    """The command examples and the files of a page's text, in order."""
    found = []
    for match in _FENCE.finditer(text):
        body = match.group(3)
        lines = body.split("\n")[:-1] if body.endswith("\n") else body.split("\n")
        block = Block(start=match.start(3), end=match.end(3), body=body)
        first = lines[0] if lines else ""
        file_mark = _FILE_MARK.match(first)
        if file_mark:
            block.file_name = file_mark.group(1)
        elif first.startswith("$ "):
            for line in lines:
                if line.startswith("$ "):
                    block.commands.append(Command(line[2:], []))
                else:
                    block.commands[-1].shown.append(line.rstrip())
        else:
            continue
        found.append(block)
    return found


# --- comparing ----------------------------------------------------------------------------


# Numbers are compared as numbers, not as text: rounding noise differs between numpy/BLAS
# builds. A number the page shows matches a printed one when
# * both are below ``ZERO`` times the scale of the vector they sit in (a 0 on the page is
#   matched by noise, and noise on the page by a 0): the scale is the largest shown entry of
#   its vector (numbers on the line with only spaces, commas and brackets between them), else
#   of its line, else of the whole output shown for the command (an all-zero vector takes its
#   scale from the table it is in);
# * either is written at full precision (``FULL`` or more significant digits: repr output,
#   whose last digits are the build's rounding noise) and they agree to a relative ``FULL_REL``;
# * otherwise they are equal: a number rounded for a table must show the same digits.
ZERO = 1e-12
FULL = 15
FULL_REL = 1e-12
NUMBER = r"[-+\u2212]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?"
_NUMBER = re.compile(rf"(?<![\w.]){NUMBER}(?!\.?\w)")
_VECTOR_GAP = re.compile(r"[\s,;\[\]()]*\Z")


def _value(text: str) -> float:
    return float(text.replace("\u2212", "-"))


def _digits(text: str) -> int:
    """Significant digits written in a number's text."""
    mantissa = re.split("[eE]", text)[0].lstrip("+-\u2212").replace(".", "").lstrip("0")
    return len(mantissa)


def _vector_scales(line: str, numbers: list[re.Match]) -> list[float]:
    """The scale of each number of ``line``: the largest magnitude in its vector, else in its
    line (0 when the line holds only zeros)."""
    scales, group = [0.0] * len(numbers), []
    for i, number in enumerate(numbers):
        if group and not _VECTOR_GAP.match(line[numbers[group[-1]].end() : number.start()]):
            group = []
        group.append(i)
        largest = max(abs(_value(numbers[j].group())) for j in group)
        for j in group:
            scales[j] = largest
    whole = max((abs(_value(n.group())) for n in numbers), default=0.0)
    return [s or whole for s in scales]


def numbers_match(shown: str, printed: str, scale: float) -> bool:
    """Whether the printed number ``printed`` is the number the page shows as ``shown``, in a
    vector whose largest shown entry is ``scale`` (the rule above this function)."""
    if shown == printed:
        return True
    s, p = _value(shown), _value(printed)
    if abs(s) <= ZERO * scale and abs(p) <= ZERO * scale:
        return True
    if max(_digits(shown), _digits(printed)) >= FULL:
        return abs(p - s) <= FULL_REL * max(abs(s), abs(p))
    return s == p


def _line_pattern(line: str) -> tuple[re.Pattern, list[str]]:
    """A pattern for printed lines like ``line``: its text as written (spaces next to a number
    may change width, a right-aligned column), any number where it shows one (captured), and
    any text where it shows ``...``; with the numbers it shows, in order."""
    pattern, shown = [], []
    pieces = line.split(WILDCARD)
    for index, piece in enumerate(pieces):
        if index:
            pattern.append(r"\s*.*?\s*")
            piece = piece.lstrip(" ")
        if index < len(pieces) - 1:
            piece = piece.rstrip(" ")
        cursor = 0
        for number in _NUMBER.finditer(piece):
            pattern.append(re.escape(piece[cursor : number.start()].rstrip(" ")) + r"\s*")
            pattern.append(rf"(?<![\w.])({NUMBER})(?!\.?\w)")
            shown.append(number.group())
            cursor = number.end()
            rest = piece[cursor:]
            if rest[:1] == " ":
                pattern.append(r"\s+" if rest.strip() else r"\s*")
                cursor += len(rest) - len(rest.lstrip(" "))
        pattern.append(re.escape(piece[cursor:]))
    return re.compile("".join(pattern) + r"\Z", re.S), shown


def line_matches(shown: str, printed: str, scale: float = 0.0) -> bool:
    """Whether the printed line is the shown one: the same text, ``...`` standing for any text,
    and numbers compared by :func:`numbers_match` (``scale``: the scale of an all-zero line)."""
    if shown == printed:
        return True
    if WILDCARD not in shown and not _NUMBER.search(shown):
        return False
    pattern, numbers = _line_pattern(shown)
    found = pattern.match(printed)
    if found is None:
        return False
    scales = [s or scale for s in _vector_scales(shown, list(_NUMBER.finditer(shown.replace(WILDCARD, " "))))]
    if len(scales) != len(numbers):  # a number glued to a wildcard: only exact text
        scales = [scale] * len(numbers)
    return all(numbers_match(s, p, k) for s, p, k in zip(numbers, found.groups(), scales, strict=True))


def _output_scale(lines: list[str]) -> float:
    """The largest magnitude of any number shown: the scale of an all-zero table."""
    return max((abs(_value(n.group())) for line in lines for n in _NUMBER.finditer(line)), default=0.0)


def _trimmed(lines: list[str]) -> list[str]:
    lines = [line.rstrip() for line in lines]
    while lines and not lines[-1]:
        lines.pop()
    return lines


def output_matches(shown: list[str], printed: list[str]) -> bool:
    """Whether ``printed`` is what ``shown`` describes (wildcards as in the module's docstring)."""
    shown, printed = _trimmed(shown), _trimmed(printed)
    scale = _output_scale(shown)

    def match(i: int, j: int) -> bool:
        if i == len(shown):
            return j == len(printed)
        if shown[i].strip() == WILDCARD:
            return any(match(i + 1, k) for k in range(j, len(printed) + 1))
        return j < len(printed) and line_matches(shown[i], printed[j], scale) and match(i + 1, j + 1)

    return match(0, 0)


def difference(shown: list[str], printed: list[str]) -> str:
    return "\n".join(
        difflib.unified_diff(_trimmed(shown), _trimmed(printed), "shown", "printed", lineterm="")
    )


# --- running ------------------------------------------------------------------------------


def readme_install_set() -> set[str]:
    """The distributions the README's first command installs (``pip install '.[plot,cad]'``):
    rbi's dependencies, those of the extras it names, and theirs, as this environment's
    metadata gives them (names normalized)."""
    from importlib import metadata

    from packaging.requirements import Requirement
    from packaging.utils import canonicalize_name

    command = re.search(r"pip install '?\.(?:\[([\w,]+)\])?", (ROOT / "README.md").read_text())
    assert command is not None, "README.md: no `pip install .` command"
    wanted, found = [("rbi", set((command[1] or "").split(",")) - {""})], set()
    while wanted:
        name, extras = wanted.pop()
        found.add(canonicalize_name(name))
        try:
            requires = metadata.requires(name) or []
        except metadata.PackageNotFoundError:
            requires = [line for line in _pyproject_requires(extras)] if name == "rbi" else []
        for text in requires:
            requirement = Requirement(text)
            marker = requirement.marker
            if marker is None or any(marker.evaluate({"extra": e}) for e in extras or {""}):
                if canonicalize_name(requirement.name) not in found:
                    wanted.append((requirement.name, set(requirement.extras)))
    return found


def _pyproject_requires(extras: set[str]) -> list[str]:
    import tomllib

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    return project["dependencies"] + [r for e in extras for r in project["optional-dependencies"][e]]


@functools.cache
def _not_installed_by_the_readme() -> frozenset[str]:
    """Top-level modules of the installed distributions :func:`readme_install_set` leaves out."""
    from importlib import metadata

    from packaging.utils import canonicalize_name

    allowed = readme_install_set()
    return frozenset(
        module
        for module, dists in metadata.packages_distributions().items()
        if module != "rbi" and not any(canonicalize_name(d) in allowed for d in dists)
    )


@contextlib.contextmanager
def only_the_readme_install():
    """While inside: the modules of every installed distribution the README's first command
    does not install (the test extras: dask, pyarrow, xacro, pytest, ...) cannot be imported,
    so an example that needs more says so or fails."""
    hidden = _not_installed_by_the_readme()
    loaded = {k: m for k, m in sys.modules.items() if k.partition(".")[0] in hidden}
    for key in loaded:
        del sys.modules[key]
    sys.modules.update(dict.fromkeys(hidden))  # None: 'import X' fails, importlib's find_spec says None
    try:
        yield hidden
    finally:
        for key in hidden:
            sys.modules.pop(key, None)
        sys.modules.update(loaded)


class Folder:
    """The temporary folder a page's commands run in, with the state ``echo $?`` needs."""

    def __init__(self, path: Path):
        self.path = path
        self.status = 0
        for name in LINKED:
            (path / name).symlink_to(ROOT / name)

    def write(self, block: Block) -> None:
        target = self.path / block.file_name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(block.body)

    def run(self, line: str) -> list[str]:
        """What ``line`` prints, as lines; sets the status ``echo $?`` shows next."""
        words = shlex.split(line)
        stdin = ""
        if len(words) > 3 and words[0] == "cat" and words[2] == "|":  # cat FILE | rbi ...: FILE on stdin
            stdin, words = (self.path / words[1]).read_text(), words[3:]
        if any(w in ("|", ">", ">>", "<", "2>", "&&", ";") for w in words):
            raise ValueError(f"cannot run `{line}` (pipes and redirections): show it in a block without `$ `")
        if words == ["echo", "$?"]:
            return [str(self.status)]
        if words and words[0] == "mkdir":
            for name in words[1:]:
                (self.path / name).mkdir(parents=True)
            self.status = 0
            return []
        if words and words[0] == "rbi":
            text, self.status = self._rbi(self._globbed(words[1:]), stdin)
        elif words and Path(words[0]).name in ("python", "python3"):
            text, self.status = self._python(words[1:])
        else:
            raise ValueError(f"cannot run `{line}`: only rbi, python, mkdir and `echo $?` are run")
        return text.split("\n")

    def _globbed(self, words: list[str]) -> list[str]:
        out = []
        for word in words:
            matches = sorted(glob.glob(word, root_dir=self.path)) if any(c in word for c in "*?[") else []
            out.extend(matches or [word])
        return out

    def _rbi(self, args: list[str], stdin: str = "") -> tuple[str, int]:
        """Run ``rbi.cli.app.main`` in this process (a fraction of a subprocess's start-up),
        stdout and stderr into one buffer, in the folder, with :data:`ENVIRONMENT`."""
        from rbi.cli.app import main

        printed = io.StringIO()
        saved = sys.argv, sys.stdin, os.getcwd(), {k: os.environ.get(k) for k in ENVIRONMENT}
        sys.argv, sys.stdin = ["rbi", *args], io.StringIO(stdin)
        os.environ.update(ENVIRONMENT)
        os.chdir(self.path)
        status = 0
        try:
            with (
                contextlib.redirect_stdout(printed),
                contextlib.redirect_stderr(printed),
                only_the_readme_install(),
            ):
                main()
        except SystemExit as exc:
            status = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
        finally:
            sys.argv, sys.stdin, cwd, env = saved
            os.chdir(cwd)
            for key, value in env.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
        return printed.getvalue(), status

    def _python(self, args: list[str]) -> tuple[str, int]:
        """Run a script with the README's install set only (a ``sitecustomize`` hides the rest
        as :func:`only_the_readme_install` does), and the modules it names in ``# needs: NAME``
        lines (its page must say so too)."""
        hide = self.path / ".readme_install"
        hide.mkdir(exist_ok=True)
        script = (self.path / args[0]).read_text() if args and (self.path / args[0]).is_file() else ""
        needs = set(re.findall(r"^# needs: (\w+)", script, re.M))  # what its page says it needs
        hidden = sorted(_not_installed_by_the_readme() - needs)
        (hide / "sitecustomize.py").write_text(f"import sys\nsys.modules.update(dict.fromkeys({hidden!r}))\n")
        path = os.pathsep.join(p for p in (str(hide), os.environ.get("PYTHONPATH")) if p)
        proc = subprocess.run(
            [sys.executable, *args],
            cwd=self.path,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            timeout=300,
            env={**os.environ, **ENVIRONMENT, "PYTHONPATH": path},
        )
        return proc.stdout, proc.returncode


def run_page(page: Path, folder: Path) -> list[tuple[Block, Command, list[str]]]:
    """Run every command example of ``page`` in ``folder``: (block, command, printed lines)."""
    place = Folder(folder)
    results = []
    for block in blocks(page.read_text()):
        if block.file_name:
            place.write(block)
            continue
        for command in block.commands:
            results.append((block, command, place.run(command.line)))
    return results


# --- rewriting ----------------------------------------------------------------------------


def _similarity(a: str, b: str) -> float:
    return difflib.SequenceMatcher(None, a, b).ratio()


def _likeness(shown: str, printed: str, tie_break: int) -> tuple:
    """How likely ``printed`` is the line ``shown`` became: same first word, then similar text."""
    same_start = shown.split()[:1] == printed.split()[:1]
    return same_start, _similarity(shown, printed), tie_break


def _with_inline_wildcards(line: str, shown: list[str]) -> str:
    """``line`` as printed, or the ``shown`` line with ``...`` inside that stands for it: one
    that matches it, else one that starts with the same words before its ``...`` (the value
    changed: its words that were ``...`` stay ``...`` when the word count is the same)."""
    wild = [w for w in shown if WILDCARD in w and w.strip() != WILDCARD]
    for candidate in wild:
        if line_matches(candidate, line):
            return candidate
    for candidate in wild:
        head = candidate.split(WILDCARD)[0].strip()
        if head and line.strip().startswith(head):
            shown_words, parts = candidate.split(), re.split(r"(\s+)", line)
            if len(shown_words) == len([p for p in parts if p and not p.isspace()]):
                words = iter(shown_words)
                return "".join(
                    p if not p or p.isspace() else (WILDCARD if WILDCARD in next(words) else p) for p in parts
                )
    return line


def rewritten_output(shown: list[str], printed: list[str]) -> list[str]:
    """The lines to show for a command that printed ``printed``: ``shown`` when it still
    matches, else ``printed``, keeping ``shown``'s wildcards. Each run of lines between two
    ``...`` lines is found again in ``printed`` (from the line most like its first to the line
    most like its last); a run at the start or end of the output stays anchored there."""
    shown, printed = _trimmed(shown), _trimmed(printed)
    if output_matches(shown, printed):
        return shown
    if not any(line.strip() == WILDCARD for line in shown):
        return [_with_inline_wildcards(line, shown) for line in printed]
    segments, current = [], []
    for line in shown:
        if line.strip() == WILDCARD:
            segments.append(current)
            segments.append(line)
            current = []
        else:
            current.append(line)
    segments.append(current)
    out, position = [], 0
    for index, segment in enumerate(segments):
        if isinstance(segment, str):  # a `...` line, kept as written
            out.append(segment)
            continue
        at_start, at_end = index == 0, index == len(segments) - 1
        if not segment or position > len(printed):
            continue
        rest = range(position, len(printed))
        if not rest:
            break
        first = position if at_start else max(rest, key=lambda j: _likeness(segment[0], printed[j], -j))
        if at_end:
            last = len(printed) - 1
        else:
            expected = first + len(segment) - 1
            last = max(
                range(first, len(printed)),
                key=lambda j: _likeness(segment[-1], printed[j], -abs(j - expected)),
            )
        out += [_with_inline_wildcards(line, segment) for line in printed[first : last + 1]]
        position = last + 1
    return out


def rewrite_page(page: Path, folder: Path) -> tuple[str, list[str]]:
    """The page's text with every command's output taken from a real run, and the commands
    whose shown output changed."""
    text = page.read_text()
    runs = run_page(page, folder)
    changed = []
    pieces, cursor = [], 0
    for block in blocks(text):
        if block.file_name:
            continue
        lines = []
        for _, command, printed in [r for r in runs if r[0].start == block.start]:
            new = rewritten_output(command.shown, printed)
            if new != _trimmed(command.shown):
                changed.append(command.line)
            lines += [f"$ {command.line}", *new]
        pieces += [text[cursor : block.start], "\n".join(lines) + "\n"]
        cursor = block.end
    pieces.append(text[cursor:])
    return "".join(pieces), changed
