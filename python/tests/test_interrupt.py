"""Ctrl-C during a long meshing run: KeyboardInterrupt at the next phase, not when the run ends."""
import os
import signal
import threading

import numpy as np
import pytest

import dtlab


def unit_square():
    points = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.uint32)
    return points, segments


@pytest.mark.skipif(not hasattr(signal, "SIGINT") or os.name != "posix", reason="needs POSIX signals")
def test_ctrl_c_stops_a_long_mesh_run_inside_cpp():
    points, segments = unit_square()
    # h = 0.004: over a hundred thousand triangles, some 10 s to the end here; the signal comes after
    # 0.3 s, when the field points are being inserted.
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as info:
            dtlab.mesh(points, segments, size=0.004)
    finally:
        timer.cancel()
        timer.join()
    notes = getattr(info.value, "__notes__", [])
    # The note is added where the C++ run stopped: proof that it did not run to its end.
    assert any(n.startswith("dtlab: interrupted mesh2d") or n.startswith("dtlab: interrupted optimize2d")
               for n in notes), notes
    # The module is still usable afterwards.
    m = dtlab.mesh(points, segments, size=0.25)
    assert len(m.cells) > 0
