"""The module as a guest in the interpreter (issue 30). It leaves the interpreter's signal handlers
as it found them (finding 10): an output it writes holds the temporaries' cleanup handler only while
it writes and only where the disposition was the default, so Ctrl-C (and a Jupyter kernel's
interrupt) still raise KeyboardInterrupt afterwards, and SIGTERM is the default again at the C level.
And it takes its memory and time budget from os.environ at each call (finding 11)."""

import ctypes
import os
import signal
import time

import numpy as np
import pytest

import geartrib as gt


def c_handler(signum):
    """The process's handler of a signal as the kernel has it (not Python's table): the first field
    of glibc's struct sigaction on x86-64 and aarch64; 0 is SIG_DFL."""
    libc = ctypes.CDLL(None, use_errno=True)
    buffer = ctypes.create_string_buffer(256)  # larger than struct sigaction (152 bytes)
    assert libc.sigaction(signum, None, buffer) == 0, os.strerror(ctypes.get_errno())
    return int.from_bytes(buffer.raw[:ctypes.sizeof(ctypes.c_void_p)], "little")


def interrupted():
    """True when SIGINT to this process raises KeyboardInterrupt (else the process dies of it)."""
    try:
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.5)  # the handler runs at the next bytecode; a dead process never returns here
    except KeyboardInterrupt:
        return True
    return False


@pytest.mark.parametrize("name", ["probe.x3p", "probe.h5", "probe.csv"])
def test_ctrl_c_still_raises_keyboard_interrupt_after_a_write(tmp_path, name):
    python_sigint = c_handler(signal.SIGINT)
    assert python_sigint != 0 and c_handler(signal.SIGTERM) == 0  # Python's SIGINT handler; SIGTERM default
    gt.write_surface(tmp_path / name, np.random.default_rng(0).normal(0.0, 3e-7, (16, 16)), 5e-7)
    assert (tmp_path / name).exists()
    assert c_handler(signal.SIGINT) == python_sigint
    assert c_handler(signal.SIGTERM) == 0  # the cleanup handler gone with the temporaries
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert interrupted()
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]  # no temporary left


def test_the_budget_comes_from_os_environ_at_each_call(monkeypatch):
    case = gt.load_case("gears/m6z30-deterministic.toml", **{"running_in.meshes": 100000,
                                                             "running_in.tolerance": "2e-15 m"})
    with pytest.raises(gt.InputError) as refused:  # ~16 h of strip solves against the default 1 h
        gt.run(case)
    assert refused.value.key == "running_in.meshes" and "GEARTRIB_TIME_BUDGET" in str(refused.value)
    monkeypatch.setenv("GEARTRIB_TIME_BUDGET", "soon")
    with pytest.raises(gt.InputError) as malformed:
        gt.run(gt.load_case("gears/m6z30-deterministic.toml", **{"contact.positions": 11}))
    assert malformed.value.key == "GEARTRIB_TIME_BUDGET" and "expected a number and a unit" in str(malformed.value)
