"""ONA (OpenNARS for Applications, PyPI ``ona``) run as a child process and driven through pipes.

robocog measures itself against ONA 0.9.2 in several places: NarsMind can run with ONA as
its reasoner (``minds/ona_shell.py``), the procedure-learning experiments drive ONA's
shell feed by feed (``experiments/procedures/reasoners.py``) and run ONA's own system
tests (``experiments/procedures/ona_builtin.py``), and tests hold robocog's output against
ONA's. Each of them needs the same careful handling of the child process, written once
here:

* finding the binary (:func:`ona_command`): the ``ona`` wheel's ``NAR`` script is a Python
  wrapper that starts the binary ``NARexe`` as its own child, so the binary is started
  directly when it can be found (one Python start-up less per run, and one process, which
  a kill then really ends); else ``NAR`` on the PATH;
* line-buffered output (:func:`line_buffered`): ONA's stdout is a pipe here, so the child
  runs under ``stdbuf -oL`` where that exists;
* the exchange (:meth:`OnaProcess.exchange`): lines are written, then a ``//sync N``
  comment; ONA echoes it as ``Comment: sync N`` after everything the lines caused, so the
  reply is read up to that echo. A reader thread copies the child's output into a queue,
  which lets every read wait at most ``timeout`` seconds instead of hanging on a child
  that no longer answers;
* failures raise :class:`OnaError` naming the command and quoting ONA's last output lines:
  a child that exits, one that does not answer in time, one that rejects an input (ONA
  prints ``Test failed.`` and exits on a line it cannot read); a missing binary raises
  :class:`OnaUnavailable`, which says how to install it;
* the end (:meth:`OnaProcess.close`): ``quit`` and end of input, a wait with a time limit,
  then a kill of the child's whole process group (a wrapper's own child included), and
  always a ``wait`` so that no zombie is left. A process that failed once is killed
  rather than asked, and one dropped without ``close`` is killed when collected.

This module knows no engine, mind or world (it imports nothing of robocog), so every
package may use it, as every package may use :mod:`robocog.atomic`.
"""

from __future__ import annotations

import os
import queue
import shutil
import signal
import subprocess
import threading
from collections import deque
from collections.abc import Callable, Iterable, Sequence
from types import TracebackType

#: what to install when ONA is missing
INSTALL_HINT = "pip install ona==0.9.2 provides `NAR`"


class OnaError(RuntimeError):
    """ONA's process failed: it exited, did not answer in time, or rejected an input."""


class OnaUnavailable(OnaError):
    """ONA cannot be started here; the message says why."""


def ona_command() -> list[str] | None:
    """The command that starts ONA's binary, or None when ONA is not installed.

    The ``ona`` wheel's binary is preferred to its ``NAR`` wrapper script: the wrapper
    costs a Python start-up and keeps the binary as a child of its own.
    """
    try:
        from ona.NAR import NARPKG_PATH  # type: ignore[import-not-found]

        binary = os.path.join(NARPKG_PATH, "NARexe")
        if os.access(binary, os.X_OK):
            return [binary]
    except Exception:  # noqa: BLE001 - any failure to import means "look on PATH"
        pass
    found = shutil.which("NAR")
    return [found] if found else None


def unavailable_reason(command: Sequence[str] | None = None) -> str | None:
    """None when ``command`` (by default ONA's, see :func:`ona_command`) can be started,
    else why not."""
    if command is None:
        return None if ona_command() else f"ONA is not installed ({INSTALL_HINT})"
    if not command or shutil.which(command[0]) is None:
        shown = command[0] if command else "(empty)"
        return f"no command {shown} is found ({INSTALL_HINT})"
    return None


def line_buffered(command: Sequence[str]) -> list[str]:
    """``command`` run under ``stdbuf -oL`` where that exists, so that a child writing to
    a pipe sends each line as it is printed rather than when its buffer fills."""
    return ["stdbuf", "-oL", *command] if shutil.which("stdbuf") else list(command)


def start_group(command: Sequence[str], **popen: object) -> subprocess.Popen[str]:
    """``subprocess.Popen(command, text=True, **popen)`` in a process group of its own,
    which :func:`kill_group` ends whole; :class:`OnaUnavailable` when the command is missing.
    """
    try:
        return subprocess.Popen(  # type: ignore[call-overload, no-any-return]
            list(command), text=True, start_new_session=True, **popen
        )
    except (FileNotFoundError, PermissionError) as exc:
        raise OnaUnavailable(f"cannot start `{' '.join(command)}`: {exc} ({INSTALL_HINT})") from exc


def kill_group(proc: subprocess.Popen[str]) -> None:
    """Kill a child started by :func:`start_group` with all its own children, and reap it.

    The group is signalled only while the child is not yet reaped: until then its id is
    its own and cannot have been given to another process.
    """
    if proc.returncode is None:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except OSError:  # no such group any more
            try:
                proc.kill()
            except OSError:
                pass
    proc.wait()


class OnaProcess:
    """A running ONA process (``NAR shell`` unless other arguments are given).

    ``send`` writes a line (buffered); ``exchange`` writes lines and a sync marker and
    returns ONA's reply up to the marker's echo, or raises :class:`OnaError`. ``command``
    is the program to run (by default ONA's binary); ``args`` follow it. ``timeout`` is
    how long one read of the reply may wait for the next line.
    """

    def __init__(
        self,
        command: Sequence[str] | None = None,
        args: Sequence[str] = ("shell",),
        timeout: float = 60.0,
        tail: int = 20,
    ) -> None:
        base = list(command) if command else ona_command()
        if base is None:
            raise OnaUnavailable(f"ONA is not installed ({INSTALL_HINT})")
        self.command = [*base, *args]
        #: how the command is named in errors
        self.name = " ".join(self.command)
        why = unavailable_reason(base)  # checked here: under stdbuf, Popen would not fail
        if why:
            raise OnaUnavailable(f"cannot start `{self.name}`: {why}")
        self.timeout = timeout
        self._tail: deque[str] = deque(maxlen=tail)
        self._lines: queue.Queue[str | None] = queue.Queue()
        self._sync = 0
        self._broken = False
        self.proc = start_group(
            line_buffered(self.command),
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            errors="replace",
        )
        self._reader = threading.Thread(
            target=self._read, args=(self.proc, self._lines), daemon=True
        )
        self._reader.start()

    @property
    def running(self) -> bool:
        """Whether the child is still alive (and not closed)."""
        return self.proc.poll() is None

    @property
    def tail(self) -> list[str]:
        """ONA's last output lines, oldest first (what error messages quote)."""
        return list(self._tail)

    def send(self, line: str) -> None:
        """Write one line; it reaches ONA with the next :meth:`exchange`."""
        stdin = self.proc.stdin
        if stdin is None or stdin.closed:
            raise OnaError(f"`{self.name}` is closed")
        try:
            stdin.write(line.strip() + "\n")
        except OSError as exc:
            raise OnaError(self._failure(f"closed its input ({exc})")) from exc

    def exchange(
        self, lines: Iterable[str] = (), on_line: Callable[[str], None] | None = None
    ) -> list[str]:
        """Write ``lines`` and a sync marker; ONA's output up to the marker's echo.

        ``on_line`` sees each output line as it arrives (an operation ONA executed can be
        acted on at once); if it raises, the process is treated as failed, since the rest
        of the reply stays unread.
        """
        for line in lines:
            self.send(line)
        self._sync += 1
        marker = f"sync {self._sync}"
        self.send("//" + marker)
        try:
            self.proc.stdin.flush()  # type: ignore[union-attr]
        except OSError as exc:
            raise OnaError(self._failure(f"closed its input ({exc})")) from exc
        echo = "Comment: " + marker
        reply: list[str] = []
        while True:
            try:
                line = self._lines.get(timeout=self.timeout)
            except queue.Empty:
                raise OnaError(self._failure(f"gave no reply within {self.timeout} s")) from None
            if line is None:
                raise OnaError(self._failure(f"exited (status {self.proc.wait()})"))
            self._tail.append(line)
            if line == echo:
                return reply
            if line.startswith("Test failed"):
                raise OnaError(self._failure("rejected an input"))
            reply.append(line)
            if on_line is not None:
                try:
                    on_line(line)
                except BaseException:
                    self._broken = True
                    raise

    def close(self) -> None:
        """End the child: politely with ``quit``, by force if it failed or does not end
        within five seconds; reap it either way."""
        proc = self.proc
        if proc.poll() is None:
            try:
                if self._broken:
                    kill_group(proc)
                else:
                    if proc.stdin and not proc.stdin.closed:
                        proc.stdin.write("quit\n")
                        proc.stdin.close()
                    proc.wait(timeout=5)
            except (OSError, ValueError, subprocess.TimeoutExpired):
                kill_group(proc)
        proc.wait()
        if proc.stdin and not proc.stdin.closed:
            try:
                proc.stdin.close()
            except OSError:
                pass  # the pipe broke with the child
        self._reader.join(timeout=5)  # it ends at the child's end of output
        if proc.stdout and not self._reader.is_alive():
            proc.stdout.close()

    def __enter__(self) -> OnaProcess:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    def __del__(self) -> None:
        proc = getattr(self, "proc", None)
        if proc is not None and proc.poll() is None:
            kill_group(proc)

    @staticmethod
    def _read(proc: subprocess.Popen[str], sink: queue.Queue[str | None]) -> None:
        """Copy the child's output lines into a queue; None marks its end."""
        assert proc.stdout is not None
        try:
            for line in proc.stdout:
                sink.put(line.rstrip("\n"))
        except (OSError, ValueError):
            pass  # the pipe was closed under us; the end marker follows
        sink.put(None)

    def _failure(self, what: str) -> str:
        """The error message: the command, what went wrong, ONA's last output lines.

        A process that failed once is not trusted again: it is killed on close.
        """
        self._broken = True
        last = "\n  ".join(self._tail) if self._tail else "(none)"
        return f"`{self.name}` {what}; last output:\n  {last}"
