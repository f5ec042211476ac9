"""A ``.xacro`` file expanded in a sandbox: a child Python process with no environment
variables, no file outside the robot file's folder (unless ``--allow-outside-paths``), no
subprocess or network, at most :data:`TIME_LIMIT_S` seconds and :data:`MEMORY_LIMIT_BYTES` of
memory; past any of them, :class:`InputError` (exit 2).

xacro evaluates Python expressions (``${...}``), reads environment variables (``$(env X)``) and
files (``<xacro:include>``, ``xacro.load_yaml``): a robot file from somebody else must not make
rbi print ``/etc/shadow`` or ``$AWS_SECRET_ACCESS_KEY``, hang on ``${10**10**8}`` or a FIFO,
nor grow to gigabytes. The child is ``python -I`` (no user site, no ``PYTHON*`` variables) with
an empty environment; resource limits (address space, CPU time, open files, file size 0) are
set before xacro is imported, and an audit hook refuses every ``open`` outside the folder
(Python's own modules excepted), every non-regular file (a FIFO, a device), and every process
or socket. The parent waits at most :data:`TIME_LIMIT_S` seconds of wall time, then kills it.

An audit hook in the same interpreter is not a sandbox by itself (a list comprehension got past
xacro's ``__`` check to ``os``; issue 38), so two more walls stand in the child:

- **Expressions that cannot reach Python objects.** Every text xacro compiles (``${...}``,
  property values, ``xacro:if``/``unless``, macro defaults: all go through ``compile``) is parsed
  with :mod:`ast` first, in the audit hook's ``compile`` event, and refused unless it is made of
  constants, names, arithmetic, comparisons, boolean and conditional expressions, calls,
  subscripts, containers and f-strings, with no name or attribute starting with ``_``, no text
  holding ``__``, no ``format``/``format_map``/``mro``/``vars``/``type`` attribute and no
  comprehension, lambda or ``:=``. ``vars`` itself is taken away before xacro is imported.
- **Landlock** (Linux 5.13 and later): before xacro reads the robot file the child gives up, for good,
  writing, truncating, removing or creating any file, reading any file outside the robot's
  folder and Python's own (everything is readable with ``--allow-outside-paths``), other
  processes' ``/proc`` entries, TCP and (Linux 6.12 and later) signals to processes outside it.
  On a kernel without Landlock the first wall stands alone.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

from rbi.errors import InputError

TIME_LIMIT_S = 10.0
"""Wall-clock (and CPU) seconds a xacro expansion may take."""

MEMORY_LIMIT_BYTES = 1 << 30
"""Address space the expanding process may use (1 GiB)."""

MAX_OUTPUT_BYTES = 64 * 1024 * 1024
"""Largest expanded document accepted (the limit rbi reads any robot file at)."""

_CHILD = r"""
import json, os, re, resource, stat, sys
folder, path, allow, memory, seconds, largest = sys.argv[1], sys.argv[2], sys.argv[3] == "1", *map(int, sys.argv[4:7])
def out(**answer):
    sys.stdout.write(json.dumps(answer)); sys.stdout.flush(); os._exit(0)
resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
resource.setrlimit(resource.RLIMIT_CPU, (seconds, seconds + 1))
resource.setrlimit(resource.RLIMIT_FSIZE, (0, 0))
resource.setrlimit(resource.RLIMIT_NPROC, (0, 0)) if hasattr(resource, "RLIMIT_NPROC") and os.getuid() != 0 else None
code = tuple(os.path.realpath(p) + os.sep for p in {sys.prefix, sys.base_prefix, sys.exec_prefix} | {p for p in sys.path if p and os.path.isdir(p) and os.path.realpath(p) != os.path.realpath(folder)})
inside = os.path.realpath(folder) + os.sep
def landlock(readable):
    import ctypes
    libc = ctypes.CDLL(None, use_errno=True)
    abi = libc.syscall(444, None, 0, 1)  # landlock_create_ruleset(NULL, 0, LANDLOCK_CREATE_RULESET_VERSION)
    if abi < 1:
        return
    fs = (1 << (13 + (abi >= 2) + (abi >= 3) + (abi >= 5))) - 1  # every file-system right this ABI knows
    attr = (ctypes.c_uint64 * 3)(fs, 3 if abi >= 4 else 0, 3 if abi >= 6 else 0)  # + TCP bind/connect, signals
    ruleset = libc.syscall(444, ctypes.byref(attr), ctypes.sizeof(ctypes.c_uint64) * (3 if abi >= 6 else 2 if abi >= 4 else 1), 0)
    if ruleset < 0:
        return
    for place in readable:
        try:
            fd = os.open(place, os.O_PATH | os.O_CLOEXEC)
        except OSError:
            continue
        rule = (ctypes.c_char * 12).from_buffer_copy((1 | 4 | 8).to_bytes(8, "little") + fd.to_bytes(4, "little", signed=True))
        libc.syscall(445, ruleset, 1, ctypes.byref(rule), 0)  # LANDLOCK_RULE_PATH_BENEATH: execute, read file, read dir
        os.close(fd)
    libc.prctl(38, 1, 0, 0, 0)  # PR_SET_NO_NEW_PRIVS
    if libc.syscall(446, ruleset, 0) != 0:
        out(error="could not confine the expanding process (landlock_restrict_self failed)")
    os.close(ruleset)
import ast, builtins
def no_vars(*args):
    raise PermissionError("rbi does not let a xacro expression call vars()")
builtins.vars = no_vars  # before xacro is imported: it builds its symbols (python.vars) from builtins then
try:
    import xacro, xml.dom.minidom, yaml, encodings.idna, encodings.utf_8, encodings.latin_1
except ImportError as exc:
    out(error="missing", detail=str(exc))
landlock(["/"] if allow else [folder, *(p.rstrip(os.sep) for p in code)])
REFUSED_NODES = {ast.Lambda: "a lambda", ast.ListComp: "a comprehension", ast.SetComp: "a comprehension", ast.DictComp: "a comprehension", ast.GeneratorExp: "a comprehension", ast.NamedExpr: "':='", ast.Await: "await", ast.Yield: "yield", ast.YieldFrom: "yield"}
REFUSED_ATTRIBUTES = {"format", "format_map", "mro", "vars", "type", "gi_frame", "gi_code", "cr_frame", "ag_frame", "tb_frame", "f_globals", "f_locals", "f_back", "f_builtins", "f_code"}
ALLOWED = (ast.Expression, ast.Constant, ast.Name, ast.expr_context, ast.BinOp, ast.operator, ast.UnaryOp, ast.unaryop, ast.BoolOp, ast.boolop, ast.Compare, ast.cmpop, ast.IfExp, ast.Call, ast.keyword, ast.Attribute, ast.Subscript, ast.Slice, ast.Tuple, ast.List, ast.Dict, ast.Set, ast.Starred, ast.JoinedStr, ast.FormattedValue)
def refusal(source):
    # why rbi does not evaluate this expression, or None: it cannot reach a Python object
    if not isinstance(source, (str, bytes)):
        return "not text"
    try:
        tree = ast.parse(source.strip(), "<rbi-check>", mode="eval")
    except (SyntaxError, ValueError):
        return None  # compile() itself reports it
    for node in ast.walk(tree):
        if type(node) in REFUSED_NODES:
            return REFUSED_NODES[type(node)]
        if not isinstance(node, ALLOWED):
            return type(node).__name__
        if isinstance(node, ast.Name) and node.id.startswith("_"):
            return f"the name {node.id[:40]}"
        if isinstance(node, ast.Attribute) and (node.attr.startswith("_") or node.attr in REFUSED_ATTRIBUTES):
            return f"the attribute .{node.attr[:40]}"
        if isinstance(node, ast.Constant) and isinstance(node.value, (str, bytes)) and ("__" in node.value if isinstance(node.value, str) else b"__" in node.value):
            return "text holding '__'"
    return None
def hook(event, args, inside=inside, code=code, allow=allow, refusal=refusal):
    if event == "compile" and not str(args[1]).endswith(".py") and args[1] != "<rbi-check>":
        why = refusal(args[0])
        if why:
            raise PermissionError(f"rbi does not evaluate an expression using {why}")
    elif event == "open":
        name, mode = args[0], args[1]
        if isinstance(name, int):
            return
        real = os.path.realpath(os.fsdecode(name))
        if mode is not None and any(c in str(mode) for c in "wax+"):
            raise PermissionError(13, "xacro may not write files", os.fsdecode(name))
        if real.endswith((".py", ".pyc", ".so")) and real.startswith(code):
            return
        if not allow and not real.startswith(inside):
            raise PermissionError(13, "outside the robot file's folder (give --allow-outside-paths to read it)", os.fsdecode(name))
        try:
            regular = stat.S_ISREG(os.stat(real).st_mode)
        except OSError:
            return
        if not regular:
            raise PermissionError(13, "not a regular file", os.fsdecode(name))
    elif event.split(".")[0] in ("subprocess", "socket", "ctypes") or event in ("os.system", "os.exec", "os.spawn", "os.posix_spawn", "os.fork", "os.forkpty", "pty.spawn", "webbrowser.open", "urllib.Request", "os.remove", "os.rmdir", "os.rename", "os.truncate", "os.kill", "os.killpg", "os.chmod", "os.chown", "os.link", "os.symlink", "os.mkdir", "os.utime", "os.putenv", "sys.setprofile", "sys.settrace"):
        raise PermissionError(f"xacro may not {event}")
sys.addaudithook(hook)
def without_data(words, path, included):
    # text a data file (load_yaml) holds is not printed, unless the robot's own text has it too
    # (float(y['key']) fails with the value in its message)
    def text(name):
        try:
            with open(name, encoding="utf-8", errors="replace") as handle:
                return handle.read()
        except OSError:
            return ""
    robot = (".xacro", ".urdf", ".xml", ".sdf")
    own = text(path) + "".join(text(name) for name in included if str(name).endswith(robot))
    values = set()
    for name in included:
        if str(name).endswith(robot):
            continue
        try:
            stack = [yaml.safe_load(text(name))]
        except Exception:
            continue
        while stack:
            item = stack.pop()
            if isinstance(item, dict):
                stack.extend(item.keys()); stack.extend(item.values())
            elif isinstance(item, list):
                stack.extend(item)
            elif isinstance(item, str) and len(item) > 1 and item not in own:
                values.add(item)
    for value in sorted(values, key=len, reverse=True):
        words = words.replace(value, "...")
    return words
import io, contextlib
try:
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        document = xacro.process_file(path)
        text = document.toxml()
except MemoryError:
    out(error="memory")
except RecursionError:
    out(error="xacro could not expand it: macros or properties nested too deeply")
except BaseException as exc:
    cause, seen = exc, set()
    while cause is not None and id(cause) not in seen:  # xacro wraps errors in XacroException(exc=...)
        seen.add(id(cause))
        if isinstance(cause, MemoryError):
            out(error="memory")
        cause = getattr(cause, "exc", None) or cause.__cause__ or cause.__context__
    words = " ".join(str(exc).split())
    words = re.sub(r"^<class '[^']*'>:\s*", "", words)
    words = without_data(words, path, getattr(xacro, "all_includes", []))
    out(error="xacro could not expand it: " + (words[:300] or type(exc).__name__))
if len(text) > largest:
    out(error=f"the expanded document is larger than the {largest // 2**20} MiB rbi reads from a robot file")
out(xml=text, includes=sorted({os.path.realpath(p) for p in xacro.all_includes}))
"""


def expand_xacro(path: str, allow_outside: bool = False) -> tuple[bytes, list[str]]:
    """(the URDF ``path`` expands to as UTF-8 bytes, the files it included), expanded in the
    sandbox described above; InputError naming the file for anything refused or past a limit."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: " + ("not a regular file" if os.path.exists(path) else "no such file"))
    folder = os.path.dirname(os.path.abspath(path))
    command = [
        sys.executable,
        "-I",
        "-c",
        _CHILD,
        folder,
        os.path.abspath(path),
        "1" if allow_outside else "0",
        str(MEMORY_LIMIT_BYTES),
        str(int(TIME_LIMIT_S)),
        str(MAX_OUTPUT_BYTES),
    ]
    try:
        done = subprocess.run(
            command, env={}, cwd=folder, capture_output=True, timeout=TIME_LIMIT_S, stdin=subprocess.DEVNULL
        )
    except subprocess.TimeoutExpired:
        raise InputError(
            f"{path}: xacro took longer than {TIME_LIMIT_S:g} s to expand it; refused (a file that "
            "loops, computes a huge number or includes a FIFO)"
        ) from None
    return _answer(path, done)


def _answer(path: str, done: subprocess.CompletedProcess) -> tuple[bytes, list[str]]:
    try:
        answer = json.loads(done.stdout.decode("utf-8"))
    except (UnicodeDecodeError, ValueError):
        answer = {"error": "memory" if b"MemoryError" in done.stderr else "crash"}
    meanings = {  # the child's error codes; any other error is its own message
        "missing": "a .xacro file needs the xacro package: pip install '.[xacro]' in rbi's source folder (or "
        "run `xacro FILE > FILE.urdf` and read that)",
        "memory": f"xacro ran out of its {MEMORY_LIMIT_BYTES // 2**30} GiB memory limit expanding it; refused "
        "(a property or expression that builds a huge string or list)",
        "crash": f"xacro needed more than {MEMORY_LIMIT_BYTES // 2**30} GiB of memory or {TIME_LIMIT_S:g} s "
        "to expand it; refused",
    }
    error = answer.get("error")
    if error:
        raise InputError(f"{path}: {meanings.get(error, error)}")
    return answer["xml"].encode("utf-8"), list(answer["includes"])
