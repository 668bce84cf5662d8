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


class FlakyPoint(distributed.WorkerPlugin):
    """A transient failure injected on the workers: the point at (altitude_m, mach) raises
    while the token file `once` does not exist (`always`: on every try), then computes. The
    token is a file, so that "once" holds across the worker processes a retry may land on."""

    name = "flaky-point"

    def __init__(self, altitude_m, mach, token, always=False):
        self.at, self.token, self.always = (altitude_m, mach), str(token), always

    def setup(self, worker):
        from roll_coupling import _dask

        real = _dask._core
        at, token, always = self.at, self.token, self.always

        class Core:
            def __getattr__(self, name):
                return getattr(real, name)

            @staticmethod
            def envelope_point(source, h, m, *rest):
                if (h, m) == at:
                    try:
                        os.close(os.open(token, os.O_CREAT | os.O_EXCL))
                        first = True
                    except FileExistsError:
                        first = False
                    if first or always:
                        raise ConnectionError(f"injected transient failure at {h} m, Mach {m}")
                return real.envelope_point(source, h, m, *rest)

        self.real, _dask._core = real, Core()

    def teardown(self, worker):
        from roll_coupling import _dask

        _dask._core = self.real


@pytest.fixture
def flaky(client, tmp_path):
    """Installs a FlakyPoint (on every worker, and any worker that starts later) and removes it."""

    def install(altitude_m, mach, always=False):
        client.register_plugin(FlakyPoint(altitude_m, mach, tmp_path / "once", always))
        return tmp_path / "once"

    yield install
    client.unregister_worker_plugin(FlakyPoint.name)


def grid_point(local, k):
    """The k-th point of the grid, (altitude m, Mach) exactly as the plan computes them."""
    p = local["points"][k]
    return p["altitude_m"], p["mach"]


def test_a_task_that_raises_once_is_retried_and_the_clearance_is_complete(local, client, flaky):
    token = flaky(*grid_point(local, 4))
    env = rc.envelope_clearance(SOURCE, H, M, BOX, client=client, retries=1)
    assert token.exists(), "the injected failure did not happen"
    assert env.to_dict() == local


def test_without_retries_the_same_transient_failure_is_reported(local, client, flaky):
    flaky(*grid_point(local, 4))
    with pytest.raises(rc.IncompleteEnvelope) as raised:
        rc.envelope_clearance(SOURCE, H, M, BOX, client=client, retries=0)
    assert [f[:2] for f in raised.value.failed] == [grid_point(local, 4)]


def test_a_point_failing_every_retry_raises_incomplete_envelope_naming_it(local, client, flaky):
    assert grid_point(local, 2) == (0.0, 0.8)
    flaky(0.0, 0.8, always=True)
    with pytest.raises(rc.IncompleteEnvelope) as raised:
        rc.envelope_clearance(SOURCE, H, M, BOX, client=client, retries=2)
    e = raised.value
    assert [f[:2] for f in e.failed] == [(0.0, 0.8)]
    assert "injected transient failure at 0.0 m, Mach 0.8" in e.failed[0][2]
    assert "1 of 6 points failed" in str(e) and "0.0 m, Mach 0.8" in str(e)
    # Every other point is there, as the local run computed it; the failed one says why.
    got = e.envelope.to_dict()["points"]
    assert len(got) == 6
    for g, want in zip(got, local["points"]):
        if (g["altitude_m"], g["mach"]) == (0.0, 0.8):
            assert "after 2 retries" in g["error"]
        else:
            assert g == want
