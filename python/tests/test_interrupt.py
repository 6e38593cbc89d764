"""Long calls release the GIL, report progress, and stop on Ctrl-C."""
import os
import signal
import threading
import time

import pytest
import volmesh


def test_a_raising_callback_stops_the_call():
    def stop(stage, fraction):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        volmesh.mesh("cutcell", "builtin:primitives", level=5, progress=stop)
    assert volmesh.mesh("grid", "builtin:box", level=1).num_cells == 8


def test_ctrl_c_raises_keyboard_interrupt():
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        volmesh.mesh("cutcell", "builtin:primitives", level=8)
    assert time.monotonic() - start < 10.0
    timer.join()


def test_other_threads_run_meanwhile():
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = len(ticks)
    volmesh.mesh("cutcell", "builtin:primitives", level=5)
    during = len(ticks) - start
    done.set()
    counter.join()
    assert during > 10
