"""The module leaves the interpreter's signal handlers as it found them (issue 30, finding 10): an
output it writes holds the temporaries' cleanup handler only while it writes and only where the
disposition was the default, so Ctrl-C (and a Jupyter kernel's interrupt) still raise
KeyboardInterrupt afterwards, and SIGTERM is the default again at the C level."""

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
