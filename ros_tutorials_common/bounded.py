"""Reading what users hand us with limits: files, pipes, YAML documents, parameter values.

Everything this project reads from a user (launch files, params files, ``<rosparam>`` text,
YAML typed on a command line, a type name piped into ``rosmsg show``) goes through here, so
``rosparam load /dev/zero`` or a 500-byte YAML "billion laughs" is refused with one line
instead of eating the machine's memory:

- a file or pipe: at most MAX_INPUT_BYTES (1 MiB), read in one bounded read; a pipe or device
  that gives nothing for MAX_INPUT_WAIT seconds is refused (a named pipe nobody writes to);
- a YAML document: at most MAX_YAML_ALIASES aliases (``*name``), at most MAX_YAML_NODES
  values once every alias is expanded, nesting at most MAX_YAML_DEPTH deep;
- a parameter value: what a ROS parameter can hold (bool, int64, float, string, a flat list
  of one of those), under string keys; a params file: node names mapping to
  ``ros__parameters`` (read_params_file).

Nothing here imports rclpy: the launcher uses it and stays light.
"""

from __future__ import annotations

import datetime
import os
import select
import stat
import threading
import time
from collections.abc import Callable
from functools import cache
from typing import IO, TYPE_CHECKING, Any

if TYPE_CHECKING:
    import yaml

MAX_INPUT_BYTES = 1024 * 1024  # a file or a pipe
MAX_YAML_ALIASES = 100  # *alias references in one document
MAX_YAML_NODES = 100_000  # values in a document once its aliases are expanded
MAX_YAML_DEPTH = 100  # nested mappings and lists
MAX_INPUT_WAIT = 10.0  # s without a byte from a pipe or device
INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1


class InputError(ValueError):
    """Input refused: the message is one line that says why."""


class StoppedWhileReading(KeyboardInterrupt):
    """The program was told to stop (SIGTERM) while it waited for input: it ends as on Ctrl-C."""


# Set by a program whose SIGTERM does not end it at once (the tools: rclpy's handler only shuts
# ROS down): whether it has been told to stop. The waits for input below look at it.
stop_requested: Callable[[], bool] = lambda: False  # noqa: E731
STOP_CHECK_PERIOD = 0.05  # s: how soon a wait notices a SIGTERM (20 wake-ups a second)


def _size(limit: int) -> str:
    return f"{limit // (1024 * 1024)} MiB" if limit % (1024 * 1024) == 0 else f"{limit} bytes"


def read_bytes(
    path: str | os.PathLike, limit: int = MAX_INPUT_BYTES, wait: float = MAX_INPUT_WAIT
) -> bytes:
    """The bytes of a file (or device, or named pipe), refusing more than ``limit``.

    What is not a plain file may have nothing to give and no end: a named pipe nobody writes
    to (open() waited for a writer for good), ``<(command)``, a terminal, /proc/kmsg (a
    "regular" file whose read blocks). Refused when it gives nothing for ``wait`` seconds.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as error:
        raise InputError(f"cannot read {path}: {error.strerror or error}") from None
    try:
        mode, size = os.fstat(fd)[stat.ST_MODE], os.fstat(fd).st_size
        if stat.S_ISFIFO(mode) or stat.S_ISSOCK(mode) or os.isatty(fd):
            data = _read_polling(fd, path, limit, wait)  # poll() tells when it has data
        else:
            os.set_blocking(fd, True)
            if stat.S_ISREG(mode) and size > 0:
                data = _read_file(fd, limit)
            else:  # a device, or a file of /proc or /sys: poll() may not tell
                data = _read_within(fd, path, limit, wait)
    except OSError as error:
        raise InputError(f"cannot read {path}: {error.strerror or error}") from None
    finally:
        os.close(fd)
    if len(data) > limit:
        raise InputError(f"{path} is larger than {_size(limit)}; refusing to read it")
    return data


def _read_file(fd: int, limit: int) -> bytes:
    with os.fdopen(fd, "rb", closefd=False) as file:
        return file.read(limit + 1)


def _nothing_for(path: str | os.PathLike, wait: float, got: int) -> InputError:
    what = "nothing came from it" if got == 0 else "it stopped giving data"
    return InputError(f"cannot read {path}: {what} in {wait:g} s (a pipe nobody writes to?)")


def _wait_until(ready: Callable[[], bool], wait: float) -> bool:
    """Ask ready() (each call waits up to STOP_CHECK_PERIOD) until it says yes or ``wait``
    seconds pass; StoppedWhileReading as soon as the program is told to stop."""
    deadline = time.monotonic() + wait
    while not ready():
        if stop_requested():
            raise StoppedWhileReading
        if time.monotonic() >= deadline:
            return False
    return True


def _read_polling(fd: int, path: str | os.PathLike, limit: int, wait: float) -> bytes:
    """Read a non-blocking descriptor to its end or past limit, waiting at most ``wait``
    seconds for each piece (for a named pipe, poll() waits for a writer too)."""
    chunks: list[bytes] = []
    size = 0
    poller = select.poll()
    poller.register(fd, select.POLLIN)
    while size <= limit:
        if not _wait_until(lambda: bool(poller.poll(STOP_CHECK_PERIOD * 1000)), wait):
            raise _nothing_for(path, wait, size)
        try:
            chunk = os.read(fd, min(65536, limit + 1 - size))
        except BlockingIOError:
            continue
        if not chunk:
            break
        chunks.append(chunk)
        size += len(chunk)
    return b"".join(chunks)


def _read_within(fd: int, path: str | os.PathLike, limit: int, wait: float) -> bytes:
    """A blocking read that may never return, done by a daemon thread: refused after
    ``wait`` seconds (the thread stays blocked until the process ends, which it soon does)."""
    reader = os.dup(fd)  # the thread's own descriptor: the caller closes fd
    result: list[bytes | OSError] = []

    def read() -> None:
        try:
            result.append(_read_file(reader, limit))
        except OSError as error:
            result.append(error)
        os.close(reader)

    thread = threading.Thread(target=read, name=f"read {path}", daemon=True)
    thread.start()
    if not _wait_until(lambda: thread.join(STOP_CHECK_PERIOD) or bool(result), wait):
        raise _nothing_for(path, wait, 0)
    if isinstance(result[0], OSError):
        raise result[0]
    return result[0]


def decode(data: bytes, source: str) -> str:
    """Bytes as UTF-8 text; anything else is refused, naming the first bad byte."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        raise InputError(
            f"{source} is not a text file (not UTF-8: byte 0x{data[error.start]:02x} "
            f"at offset {error.start})"
        ) from None


def read_text(path: str | os.PathLike, limit: int = MAX_INPUT_BYTES) -> str:
    """A UTF-8 text file, refusing more than ``limit`` bytes."""
    return decode(read_bytes(path, limit), str(path))


def read_line(stream: IO[str], source: str, limit: int = 4096) -> str:
    """One line from a text stream (a pipe), refusing a line longer than ``limit``."""
    try:
        line = stream.readline(limit + 1)
    except UnicodeDecodeError:
        raise InputError(f"{source} is not a text file (not UTF-8)") from None
    if len(line) > limit and not line.endswith("\n"):
        raise InputError(f"{source}: a line longer than {limit} characters; refusing it")
    return line


@cache
def _loader_class() -> type:
    """PyYAML's safe loader, counting aliases and depth while it composes the document. Made
    at first use, as yaml is imported then: most programs that read files read no YAML, and
    the import was a tenth of the launcher's start before its first process."""
    import yaml

    class BoundedLoader(yaml.SafeLoader):
        def __init__(self, stream: str) -> None:
            super().__init__(stream)
            self.aliases = 0
            self.depth = 0

        def compose_node(self, parent: Any, index: Any) -> Any:
            if self.check_event(yaml.AliasEvent):
                self.aliases += 1
                if self.aliases > MAX_YAML_ALIASES:
                    raise InputError(f"more than {MAX_YAML_ALIASES} YAML aliases")
            self.depth += 1
            try:
                if self.depth > MAX_YAML_DEPTH:
                    raise InputError(f"YAML nested more than {MAX_YAML_DEPTH} deep")
                return super().compose_node(parent, index)
            finally:
                self.depth -= 1

    return BoundedLoader


def bounded_loader(stream: str) -> Any:
    """A YAML loader for ``stream`` that refuses too many aliases and too deep nesting
    (InputError); the caller disposes of it."""
    return _loader_class()(stream)


def _expanded_size(root: yaml.Node) -> int:
    """How many values the document holds with every alias expanded (stops past the limit)."""
    import yaml

    sizes: dict[int, int] = {}
    stack: list[tuple[yaml.Node, bool]] = [(root, False)]
    open_nodes: set[int] = set()
    while stack:
        node, children_done = stack.pop()
        if id(node) in sizes:
            continue
        children = [
            item
            for entry in (node.value if isinstance(node, yaml.CollectionNode) else [])
            for item in (entry if isinstance(entry, tuple) else (entry,))
        ]
        if children_done:
            open_nodes.discard(id(node))
            sizes[id(node)] = min(1 + sum(sizes[id(c)] for c in children), MAX_YAML_NODES + 1)
            continue
        if id(node) in open_nodes:
            raise InputError("a YAML alias refers to the value it is inside of")
        open_nodes.add(id(node))
        stack.append((node, True))
        stack.extend((child, False) for child in children if id(child) not in sizes)
    return sizes[id(root)]


def load_yaml(text: str, source: str = "YAML") -> Any:
    """Parse one YAML document within the limits above.

    Too large, too many aliases, too deep: InputError naming ``source``. A syntax error is
    PyYAML's own yaml.YAMLError (callers already report those with their position).
    """
    if len(text.encode("utf-8", "surrogatepass")) > MAX_INPUT_BYTES:
        raise InputError(f"{source} is larger than {_size(MAX_INPUT_BYTES)}; refusing it")
    loader = bounded_loader(text)
    try:
        try:
            node = loader.get_single_node()
        except InputError as error:
            raise InputError(f"{source}: {error}") from None
        if node is None:
            return None
        if _expanded_size(node) > MAX_YAML_NODES:
            raise InputError(
                f"{source}: more than {MAX_YAML_NODES} values once its aliases are expanded"
            )
        return loader.construct_document(node)
    finally:
        loader.dispose()


def read_params_file(path: str | os.PathLike, values: bool = True) -> dict[str, dict[str, Any]]:
    """A ROS 2 params file, read within the limits and checked before anything uses it:
    {node name: {"ros__parameters": {...}}}, one entry per node name in the file's order.

    As in rcl, a node name may also be written as nested keys (``ns: {node: {ros__parameters:
    ...}}`` is ``ns/node``). A node name that is not text, an entry without a
    ``ros__parameters`` mapping, or (with ``values``) a value no ROS parameter can hold is an
    InputError naming the file.
    """
    import yaml

    text = read_text(path)
    try:
        data = load_yaml(text, str(path))
    except yaml.YAMLError as error:
        raise InputError(f"{path} is not valid YAML: {' '.join(str(error).split())}") from None
    if not isinstance(data, dict):
        raise InputError(f"{path} is not a params file (expected 'node: ros__parameters: ...')")
    entries: dict[str, dict[str, Any]] = {}
    _params_entries(data, "", str(path), entries, values)
    return entries


def _params_entries(data: dict, prefix: str, source: str, entries: dict, values: bool) -> None:
    for key, value in data.items():
        if not isinstance(key, str):
            raise InputError(f"{source}: node name {key!r} is not a string")
        name = f"{prefix}/{key.strip('/')}" if prefix else key
        if not isinstance(value, dict) or not value:
            raise InputError(f"{source}: '{name}' has no 'ros__parameters:' mapping")
        params = value.get("ros__parameters", {})
        if not isinstance(params, dict):
            raise InputError(f"{source}: '{name}' has no 'ros__parameters:' mapping")
        problem = parameters_problem(params) if values else None
        if problem:
            raise InputError(f"{source}: {problem}")
        if "ros__parameters" in value:
            entries.setdefault(name, {"ros__parameters": {}})["ros__parameters"].update(params)
        namespaces = {k: v for k, v in value.items() if k != "ros__parameters"}
        _params_entries(namespaces, name, source, entries, values)


def parameter_problem(name: str, value: Any) -> str | None:
    """Why ``value`` cannot be a ROS parameter called ``name``, or None if it can."""
    if isinstance(value, bool | str | float) or value is None:
        return None
    if isinstance(value, int):
        if INT64_MIN <= value <= INT64_MAX:
            return None
        return f"parameter '{name}' = {value} does not fit a ROS integer (int64)"
    if isinstance(value, list):
        for item in value:
            if isinstance(item, list | dict):
                return f"parameter '{name}' is a list of lists or mappings; ROS lists are flat"
            problem = parameter_problem(name, item)
            if problem:
                return problem
        kinds = {type(item) for item in value}
        if len(kinds) > 1 and kinds != {int, float}:
            return f"parameter '{name}' mixes types in one list; a ROS list holds one type"
        return None
    if isinstance(value, datetime.date):
        return (
            f"parameter '{name}' = {value} is a YAML date; ROS parameters have no date type "
            "(quote it to make it a string)"
        )
    if isinstance(value, bytes):
        return f"parameter '{name}' is binary data; use a list of integers"
    return f"parameter '{name}' has a value of type {type(value).__name__}, not a ROS type"


def parameters_problem(values: Any, prefix: str = "") -> str | None:
    """Like parameter_problem, for a mapping of names (nested mappings are namespaces)."""
    if not isinstance(values, dict):
        return parameter_problem(prefix or "?", values)
    for key, value in values.items():
        if not isinstance(key, str):
            return f"key {key!r} under '{prefix or '/'}' is not a string; parameter names are text"
        name = f"{prefix}.{key}" if prefix else key
        problem = parameters_problem(value, name) if isinstance(value, dict) else None
        problem = problem or (None if isinstance(value, dict) else parameter_problem(name, value))
        if problem:
            return problem
    return None
