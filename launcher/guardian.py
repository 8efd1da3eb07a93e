"""The launcher's guardian: the process the user started stands over the launcher.

``python -m launcher`` (and ``roslaunch``) fork once the launch is planned and its log folder
made, just before the first process starts (``--print``, ``--show-args`` and errors never
fork). The child goes on to be the launcher; the original process, the PID the shell, a test
or a service manager sees, becomes its guardian and does nothing but this:

- it is a child subreaper (Linux ``PR_SET_CHILD_SUBREAPER``): whatever loses its parent below
  it and has no closer subreaper comes to it, not to init. The launcher is one too while it
  supervises, so that is where orphans go first; once the launcher is gone they come here;
- it passes on each SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1 and SIGUSR2 it gets to the
  launcher. The launcher runs in a process group of its own, so a Ctrl-C in the terminal
  (sent to the terminal's foreground group) reaches it once, through here. Ctrl-Z stops
  both; ``fg``/``bg`` continue both;
- the launcher gets SIGTERM when the guardian dies (``PR_SET_PDEATHSIG``), even by SIGKILL;
  it then sees that its guardian is gone and kills everything it started at once, setsid
  grandchildren included, as if it had been killed itself (see ``abandoned``);
- when the launcher has ended, for whatever reason, it SIGKILLs every process still below it
  (after a normal end there is none), reaps them, and ends as the launcher did: with its exit
  code, or killed by the same signal.

Not covered: SIGKILL to the guardian and the launcher at the same moment (``kill -9`` naming
both, ``pkill -9 -f launcher``). The launcher's children still die (PDEATHSIG) and the
launcher's group keeper kills what they left in their process groups, but a grandchild that
called setsid while its parent was alive is then no one's to stop.

The fork costs about a millisecond of CPU; the two processes share the interpreter's memory
until one of them writes to it, and the guardian writes almost nothing.
"""

from __future__ import annotations

import contextlib
import ctypes
import gc
import os
import signal
import sys
import time

PR_SET_PDEATHSIG = 1
PR_SET_NAME = 15
PR_SET_CHILD_SUBREAPER = 36
FORWARDED = {
    signal.SIGINT,
    signal.SIGTERM,
    signal.SIGHUP,
    signal.SIGQUIT,
    signal.SIGUSR1,
    signal.SIGUSR2,
}
WAITED_FOR = FORWARDED | {signal.SIGCHLD, signal.SIGTSTP, signal.SIGCONT}
CLEAR_SECONDS = 10.0  # after the launcher: how long to keep killing and reaping what is left
REAP_POLL_SECONDS = 0.1

_guarded = False  # guard() has run in this process
_guardian_pid: int | None = None  # in the launcher: its guardian's pid


def abandoned() -> bool:
    """In the launcher: has its guardian died (killed, since it outlives the launcher)?"""
    return _guardian_pid is not None and os.getppid() != _guardian_pid


def guard() -> None:
    """Fork. Returns in the child, which is the launcher; the parent guards it until it ends
    and then exits as it did, never returning. A second call does nothing."""
    global _guarded, _guardian_pid
    if _guarded:
        return
    _guarded = True
    libc = ctypes.CDLL(None, use_errno=True)
    guardian = os.getpid()
    # Blocked from before the fork: no signal is lost or handled twice in between.
    inherited_mask = signal.pthread_sigmask(signal.SIG_BLOCK, WAITED_FOR)
    inherited_sigchld = signal.signal(signal.SIGCHLD, signal.SIG_DFL)  # SIG_IGN would auto-reap
    # The two processes share the interpreter's memory until one writes to a page. Frozen,
    # the objects made so far are never walked by the launcher's garbage collector, whose
    # first full pass would otherwise copy most of those pages (about 7 ms of CPU, measured).
    gc.freeze()
    try:
        pid = os.fork()
    except OSError:  # no fork possible: run the launcher unguarded, as before
        pid = 0
        guardian = None
    if pid == 0:
        if inherited_sigchld is not None:
            signal.signal(signal.SIGCHLD, inherited_sigchld)
        if guardian is not None:
            os.setpgid(0, 0)  # the terminal's Ctrl-C reaches the guardian alone, which passes it on
            # Writing to the terminal from outside its foreground group must not stop the launcher
            # (stty tostop); its children get the default back (launcher/supervise.py).
            signal.signal(signal.SIGTTOU, signal.SIG_IGN)
            libc.prctl(PR_SET_PDEATHSIG, signal.SIGTERM, 0, 0, 0)
            _guardian_pid = guardian
            if os.getppid() != guardian:  # the guardian died before prctl took effect
                os.kill(os.getpid(), signal.SIGTERM)
        signal.pthread_sigmask(signal.SIG_SETMASK, inherited_mask)
        return
    with contextlib.suppress(OSError):  # also done by the child; whichever runs first
        os.setpgid(pid, pid)
    libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
    libc.prctl(PR_SET_NAME, b"launch guardian", 0, 0, 0)  # as `ps -o comm` and top show it
    status = _stand_guard(pid)
    _clear_below()
    _end_like(status)


def _stand_guard(launcher: int) -> int:
    """Pass signals on until the launcher ends; its wait status."""
    while True:
        sig = signal.sigwaitinfo(WAITED_FOR).si_signo
        if sig == signal.SIGCHLD:
            status = _reap(launcher)
            if status is not None:
                return status
        elif sig == signal.SIGTSTP:  # Ctrl-Z: stop the launcher, then stop as a job would
            _send(launcher, signal.SIGSTOP)
            os.kill(os.getpid(), signal.SIGSTOP)
        else:  # SIGCONT after fg/bg, and the forwarded signals
            _send(launcher, sig)


def _send(pid: int, sig: int) -> None:
    with contextlib.suppress(ProcessLookupError):  # ended meanwhile: SIGCHLD is on its way
        os.kill(pid, sig)


def _reap(launcher: int | None = None) -> int | None:
    """Reap every child that has ended; the launcher's wait status if it was one of them."""
    found = None
    while True:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return found
        if pid == 0:
            return found
        if pid == launcher:
            found = status


def _children() -> list[int]:
    """Our live and zombie children: the launcher's leftovers adopted after it ended."""
    me, found = os.getpid(), []
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat", "rb") as stat:
                ppid = int(stat.read().rsplit(b")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue  # gone meanwhile
        if ppid == me:
            found.append(int(entry.name))
    return found


def _has_children() -> bool:
    try:
        os.waitid(os.P_ALL, 0, os.WEXITED | os.WNOHANG | os.WNOWAIT)
    except ChildProcessError:
        return False
    return True


def _clear_below() -> None:
    """SIGKILL what is left below us, layer by layer (a killed process's children come to
    us in turn), until nothing is, or CLEAR_SECONDS have passed (a process in state D)."""
    deadline = time.monotonic() + CLEAR_SECONDS
    while _has_children():
        left = _children()
        if time.monotonic() > deadline:
            print(f"[launcher] still running after SIGKILL: pid(s) {left}", file=sys.stderr)
            return
        for pid in left:
            _send(pid, signal.SIGKILL)
        signal.sigtimedwait({signal.SIGCHLD}, REAP_POLL_SECONDS)
        _reap()


def _end_like(status: int) -> None:
    """Exit as the launcher did: its exit code, or killed by the signal that killed it."""
    if os.WIFSIGNALED(status):
        sig = os.WTERMSIG(status)
        with contextlib.suppress(OSError, ValueError):  # SIGKILL and SIGSTOP keep their action
            signal.signal(sig, signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {sig})
        os.kill(os.getpid(), sig)
        os._exit(128 + sig)  # a signal whose default action is not to end a process
    os._exit(os.waitstatus_to_exitcode(status))
