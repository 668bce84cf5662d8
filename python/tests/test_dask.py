"""`envelope_clearance` on a Dask LocalCluster of two worker processes: the same clearance as
the local run, bit for bit, and again with a worker killed while it computes a point (Dask gives
its points to the worker alive; none is lost)."""

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
    env = rc.envelope_clearance(SOURCE, H, M, BOX).to_dict()
    assert len(env["points"]) == 6
    assert all("clearance" in p for p in env["points"] if p["trimmed"]), env
    return env


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, silence_logs=40) as c:
        with distributed.Client(c) as client:
            yield client


def test_two_workers_give_the_local_clearance(local, client):
    assert len(client.scheduler_info()["workers"]) == 2
    env = rc.envelope_clearance(SOURCE, H, M, BOX, client=client)
    assert env.to_dict() == local


def test_a_worker_killed_mid_run_loses_no_point(local, client):
    address, victim = sorted(client.run(os.getpid).items())[0]
    done = {}

    def run():
        done["env"] = rc.envelope_clearance(SOURCE, H, M, BOX, client=client, retries=1)

    t = threading.Thread(target=run)
    t.start()
    # Kill one worker while it computes a point, before the run ends (its nanny starts a new
    # one; the scheduler gives the lost point to a worker alive).
    deadline = time.time() + 60
    while time.time() < deadline and not client.processing().get(address):
        time.sleep(0.02)
    assert client.processing().get(address) and t.is_alive()
    os.kill(victim, signal.SIGKILL)
    t.join(300)
    assert not t.is_alive()
    assert done["env"].to_dict() == local
