"""Writing the user's outputs safely: paths checked before any work, atomic writes, no temp file left.

- :func:`check_output_paths` refuses, before a single check runs, an output that is one of the inputs
  (a design file or one of its includes), two outputs that are the same file, a folder that does not
  exist or cannot be written, and anything that exists but is not a regular file (a symbolic link, a
  FIFO, a device, a folder): each an :class:`OutputPathError` naming the option and the path.
- :func:`atomic_write` writes to a temporary file next to the target and renames it over the target
  when complete; on an error, Ctrl-C (SIGINT) or SIGTERM the temporary file is removed and the target
  is left as it was. Temporary files left by a process killed with SIGKILL (``.NAME.PID.xxxx.tmp``) are
  removed by the next write of the same target once their process is gone.
"""

from __future__ import annotations

import contextlib
import glob
import os
import signal
import stat
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path

from mechverify.errors import InputError


class OutputPathError(InputError):
    """An output path that mechverify refuses to write (it would replace an input, a link, a device...)."""


def _same(a: Path, b: Path) -> bool:
    try:
        if a.exists() and b.exists():
            return os.path.samefile(a, b)
    except OSError:
        pass
    return os.path.normcase(os.path.abspath(a)) == os.path.normcase(os.path.abspath(b)) or (
        a.resolve(strict=False) == b.resolve(strict=False))


def check_output_path(path: str | Path, option: str = "output") -> Path:
    """Refuse an output ``path`` that exists but is not a regular file, or whose folder is missing or
    not writable; return it as a :class:`~pathlib.Path`. ``option`` names the path in the message."""
    p = Path(path)
    if str(path) in ("", "."):
        raise OutputPathError(f"{option}: an empty path is not a file name")
    try:
        st = os.lstat(p)
    except FileNotFoundError:
        st = None
    except OSError as exc:  # e.g. a component of the path is a file: "Not a directory"
        raise OutputPathError(f"{option}: cannot write {p}: {exc.strerror}") from None
    if st is not None:
        mode = st.st_mode
        if stat.S_ISLNK(mode):
            raise OutputPathError(f"{option}: {p} is a symbolic link; mechverify does not write through links "
                                  f"(give the target's own path)")
        if stat.S_ISDIR(mode):
            raise OutputPathError(f"{option}: {p} is a folder; give a file name")
        if not stat.S_ISREG(mode):
            kind = ("a FIFO" if stat.S_ISFIFO(mode) else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                    else "a socket" if stat.S_ISSOCK(mode) else "not a regular file")
            raise OutputPathError(f"{option}: {p} is {kind}; mechverify writes regular files only")
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise OutputPathError(f"{option}: the folder {parent} does not exist (create it first)")
    try:  # the honest test of writability (os.access says yes to root on a read-only file system)
        fd, probe = tempfile.mkstemp(dir=parent, prefix=f".{p.name}.{os.getpid()}.", suffix=".tmp")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise OutputPathError(f"{option}: cannot write in the folder {parent}: {exc.strerror}") from None
    return p


def check_output_paths(outputs: Mapping[str, str | Path | None], inputs: Iterable[str | Path] = ()) -> None:
    """Validate every output (option name -> path; ``None`` entries are skipped) against each other and
    against the ``inputs``: raise :class:`OutputPathError` on the first problem, before anything is written."""
    ins = [Path(i) for i in inputs]
    seen: list[tuple[str, Path]] = []
    for option, path in outputs.items():
        if path is None:
            continue
        p = Path(path)
        for i in ins:
            if _same(p, i):
                raise OutputPathError(f"{option}: {p} is an input ({i}); mechverify never writes over its inputs")
        for other, q in seen:
            if _same(p, q):
                raise OutputPathError(f"{option} and {other} name the same file {p}; give each its own file")
        check_output_path(p, option)
        seen.append((option, p))


# --- atomic writes -----------------------------------------------------------------------------------

_pending: set[Path] = set()
_lock = threading.Lock()


def _remove_pending() -> None:
    with _lock:
        for t in list(_pending):
            with contextlib.suppress(OSError):
                t.unlink()
        _pending.clear()


def _sigterm(signum, frame):
    _remove_pending()
    raise SystemExit(128 + signum)


@contextlib.contextmanager
def _cleanup_on_sigterm() -> Iterator[None]:
    """While writing: SIGTERM removes the temporary file (SIGINT raises KeyboardInterrupt, handled by
    the caller's cleanup). Only where no handler of the application is installed, on the main thread."""
    installed = None
    if threading.current_thread() is threading.main_thread():
        with contextlib.suppress(ValueError, OSError):
            if signal.getsignal(signal.SIGTERM) in (signal.SIG_DFL, None):
                installed = signal.signal(signal.SIGTERM, _sigterm)
    try:
        yield
    finally:
        if installed is not None:
            signal.signal(signal.SIGTERM, installed)


def _remove_stale(path: Path) -> None:
    """Remove ``.NAME.PID.*.tmp`` of ``path`` left by a process that no longer runs (killed by SIGKILL)."""
    for t in path.parent.glob(f".{glob.escape(path.name)}.*.tmp"):
        pid = t.name[len(path.name) + 2:].split(".", 1)[0]
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        try:
            os.kill(int(pid), 0)
        except ProcessLookupError:
            with contextlib.suppress(OSError):
                t.unlink()
        except OSError:
            pass


def atomic_write(path: str | Path, content: str | bytes | Callable[[Path], None]) -> Path:
    """Write ``content`` (text, bytes, or a function that writes a given temporary path) to ``path``.

    The data go to a temporary file in the same folder, which replaces ``path`` only when complete;
    on any error (and on SIGINT/SIGTERM) the temporary file is removed and ``path`` is left as it was.
    The file gets the usual permissions (0666 less the umask). A symbolic link or a special file at
    ``path`` is refused (:class:`OutputPathError`), never replaced.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.is_symlink() or (path.exists() and not path.is_file()):
        check_output_path(path)  # raises with the reason
    _remove_stale(path)
    with _cleanup_on_sigterm():
        fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp")
        tmp = Path(name)
        with _lock:
            _pending.add(tmp)
        try:
            with os.fdopen(fd, "wb") as fh:
                if isinstance(content, str):
                    fh.write(content.encode("utf-8"))
                elif isinstance(content, bytes):
                    fh.write(content)
            if callable(content):
                content(tmp)
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)
            os.replace(tmp, path)
        except BaseException:
            tmp.unlink(missing_ok=True)
            raise
        finally:
            with _lock:
                _pending.discard(tmp)
    return path


def json_safe(obj: object) -> object:
    """``obj`` with every non-finite float (NaN, ±inf, also NumPy floats) replaced by ``None``, recursively
    through dicts, lists and tuples, so that it serialises as strict JSON (RFC 8259 has no NaN)."""
    import math

    if isinstance(obj, float):  # also numpy.float64, a float subclass
        return float(obj) if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: json_safe(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [json_safe(v) for v in obj]
    if type(obj).__module__ == "numpy" and hasattr(obj, "item"):  # other numpy scalars
        return json_safe(obj.item())
    return obj


def json_text(obj: object, **kw: object) -> str:
    """Strict JSON text of ``obj`` (:func:`json_safe` first, then ``allow_nan=False``): every JSON file
    mechverify writes goes through here, so a strict parser (jq, JavaScript) reads it."""
    import json

    return json.dumps(json_safe(obj), allow_nan=False, **kw)  # type: ignore[arg-type]
