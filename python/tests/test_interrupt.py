"""Ctrl-C during a long computation raises KeyboardInterrupt at once, not when it ends."""

import signal
import subprocess
import sys
import time

from conftest import ROOT

# The child handles SIGINT as an interactive Python does, whatever it inherits: a shell that
# starts the tests in the background without job control hands them SIGINT ignored.
LONG = """
import roll_coupling as rc, signal, sys, time
signal.signal(signal.SIGINT, signal.default_int_handler)
print("start", flush=True)
t = time.perf_counter()
try:
    rc.envelope("jsbsim:f104", "0:12000:50", "0.3:0.9:0.005")
except KeyboardInterrupt:
    print(f"interrupted after {time.perf_counter() - t:.2f} s", flush=True)
    sys.exit(0)
print("finished", flush=True)
"""


def test_ctrl_c_interrupts_a_long_envelope():
    p = subprocess.Popen([sys.executable, "-c", LONG], cwd=ROOT, stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "start"
    time.sleep(1.0)
    t = time.perf_counter()
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    # A 29,161-point envelope takes a minute or more (about 5 ms of CPU a point on two cores);
    # the interrupt returns within a second or so.
    assert out.startswith("interrupted"), out
    assert time.perf_counter() - t < 10
