#!/usr/bin/env python3
"""JSBSim itself as the oracle of the control surfaces' travel: for each model, with its flight
control system intact, sets each pilot command (fcs/aileron-cmd-norm, fcs/elevator-cmd-norm,
fcs/rudder-cmd-norm) to +1 and then to -1 (the others at zero, back to zero in between) and
reads the surface positions once the actuators, lags and kinematic travels have settled.

The flight state is frozen (JSBSim's suspended integration: the flight control system runs
with its own time step while the aircraft does not move) at 3,000 m, Mach 0.3, alpha 2 deg,
wings level, no rates and no sideslip, so that a damper's feedback adds nothing, as in the
state the import analyses. A position counts as settled when a further second of frames
changes no read position by more than 1e-14 (at most 120 s of frames).

Input (stdin, JSON): {"root": DIR, "models": [NAME, ...], "properties": [property, ...]}.
Output (stdout, JSON): {NAME: {command: {"+1": {property: value}, "-1": {...}}}}, a property
missing from JSBSim's tree left out; {NAME: {"error": text}} when JSBSim cannot load it. A
property that only a simulator host would set (FlightGear's /sim/...) is created at zero.
Needs `pip install jsbsim==1.3.3`.
"""
import json
import re
import sys

import jsbsim

COMMANDS = ("fcs/aileron-cmd-norm", "fcs/elevator-cmd-norm", "fcs/rudder-cmd-norm")
FRAMES_PER_BLOCK = 120
MAX_BLOCKS = 120
SETTLED = 1e-14


def read(fdm, properties):
    pm = fdm.get_property_manager()
    return {p: fdm.get_property_value(p) for p in properties if pm.hasNode(p)}


def settle(fdm, properties):
    """Runs blocks of frames until no read position moves; returns the positions."""
    last = read(fdm, properties)
    for _ in range(MAX_BLOCKS):
        for _ in range(FRAMES_PER_BLOCK):
            fdm.run()
        now = read(fdm, properties)
        if all(abs(now[p] - last[p]) <= SETTLED for p in now):
            return now
        last = now
    return last


MISSING = re.compile(r"property (\S+) does not exist")


def travel(root, name, properties, host=()):
    """The settled positions; a property that only a simulator host would create (the error
    names it) is created at zero and the model run again."""
    try:
        return run(root, name, properties, host)
    except Exception as e:  # JSBSim raises on a property no part of the model creates
        missing = MISSING.search(str(e))
        if not missing or missing.group(1) in host or len(host) > 20:
            return {"error": str(e)}
        return travel(root, name, properties, host + (missing.group(1),))


def run(root, name, properties, host):
    fdm = jsbsim.FGFDMExec(root)
    fdm.set_debug_level(0)
    for p in host:
        fdm[p] = 0.0
    if not fdm.load_model(name):
        return {"error": "JSBSim could not load %s" % name}
    fdm["ic/h-sl-ft"] = 3000.0 / 0.3048
    fdm["ic/mach"] = 0.3
    fdm["ic/alpha-deg"] = 2.0
    fdm["ic/beta-deg"] = 0.0
    for axis in "pqr":
        fdm["ic/%s-rad_sec" % axis] = 0.0
    fdm.run_ic()
    fdm.suspend_integration()
    out = {}
    for command in COMMANDS:
        out[command] = {}
        for value in (1.0, -1.0):
            fdm[command] = value
            out[command]["%+d" % value] = settle(fdm, properties)
            fdm[command] = 0.0
            settle(fdm, properties)
    return out


def main():
    request = json.load(sys.stdin)
    out = {}
    for name in request["models"]:
        out[name] = travel(request["root"], name, request["properties"])
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
