"""`envelope_clearance` on a Dask LocalCluster: the same clearance as the local run, bit for
bit, with two workers, and with a worker killed in the middle of the run (its points are
rescheduled by Dask, none lost)."""

import os
import signal
import threading
import time

import pytest

import roll_coupling as rc

distributed = pytest.importorskip("distributed")

SOURCE, H, M, BOX = "jsbsim:f104", "0:3000:3000", "0.4:0.8:0.2", "Cl_p=10%,Cn_r=0.02"


@pytest.fixture(scope="module")
def local():
    return rc.envelope_clearance(SOURCE, H, M, BOX).to_dict()


def cluster(n):
    return distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                    dashboard_address=None, silence_logs=40)


def test_two_workers_give_the_local_clearance(local):
    assert all("clearance" in p or "clearance_error" in p for p in local["points"] if p["trimmed"])
    with cluster(2) as c, distributed.Client(c) as client:
        env = rc.envelope_clearance(SOURCE, H, M, BOX, client=client)
    assert env.to_dict() == local


def test_a_worker_killed_mid_run_loses_no_point(local):
    with cluster(2) as c, distributed.Client(c) as client:
        pids = client.run(os.getpid)
        address, victim = sorted(pids.items())[0]
        done = {}

        def run():
            done["env"] = rc.envelope_clearance(SOURCE, H, M, BOX, client=client, retries=1)

        t = threading.Thread(target=run)
        t.start()
        # Kill one worker while it computes a point, before the run ends (its nanny starts a
        # new one; the scheduler gives the lost points to the workers alive).
        deadline = time.time() + 60
        while time.time() < deadline and not client.processing().get(address):
            time.sleep(0.05)
        in_flight = client.processing().get(address)
        assert in_flight and t.is_alive()
        os.kill(victim, signal.SIGKILL)
        t.join(300)
        assert not t.is_alive()
    assert done["env"].to_dict() == local
