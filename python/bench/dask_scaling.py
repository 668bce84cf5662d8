"""Wall time of one envelope clearance on a Dask LocalCluster of 1 and of 2 single-threaded
worker processes, and on the local cores without Dask (the same grid and box), each run once
after a warm-up point, with the machine's load average beside it: the scaling figure of
docs/envelope_distributed.md.

Run: python python/bench/dask_scaling.py [ALTITUDES_M MACHS SPEC]
"""

import os
import sys
import time

import distributed

import roll_coupling as rc

SOURCE = "jsbsim:f104"
H, M, BOX = sys.argv[1:4] if len(sys.argv) > 3 else ("0:9000:3000", "0.4:0.8:0.2", "Cl_p=10%,Cn_r=0.02")


def timed(client):
    t = time.perf_counter()
    env = rc.envelope_clearance(SOURCE, H, M, BOX, client=client)
    return time.perf_counter() - t, env.to_dict()


def main():
    print(f"{SOURCE}, altitudes {H} m, Mach {M}, uncertainty {BOX}; load average {os.getloadavg()}")
    wall, reference = timed(None)
    print(f"local cores (rayon, no Dask): {wall:.1f} s for {len(reference['points'])} points")
    for n in (1, 2):
        with distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                      dashboard_address=None, silence_logs=40) as c:
            with distributed.Client(c) as client:
                client.run(rc._core.envelope_point, SOURCE, 0.0, 0.5, 1.0, 0.0, None)  # read the model
                wall, env = timed(client)
        assert env == reference, "a Dask run differs from the local one"
        print(f"{n} worker(s): {wall:.1f} s, load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
