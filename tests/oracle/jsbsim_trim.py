#!/usr/bin/env python3
"""JSBSim's own trim (FGTrim) as the oracle of the import's n-g trim: for a catalogue model at
given flight conditions, JSBSim trims a wings-level pull-up at load factor n (FGTrim's `pullup`
mode: aerodynamic lift = n x weight by alpha, pitch acceleration zero by the pitch trim command,
forward acceleration zero by the throttle, pitch rate q = (n - cos gamma) g / V with gamma = 0)
and this script prints the trimmed state.

The model is loaded whole, its flight control system included: FGTrim moves the elevator through
`fcs/pitch-trim-cmd-norm`, which only the flight control system turns into a surface position.
So this trim includes what the import leaves out: the thrust (its pitching moment about the CG
and its share of the normal force does not enter JSBSim's load factor, which is the aerodynamic
lift over the weight, but the thrust's moment enters the pitch balance), the alpha-dot terms of
the aerodynamics at JSBSim's trim state, and the fed-back aero/cl-squared as JSBSim updates it.

Input (stdin, JSON): {"root": DIR, "model": NAME, "conditions": [{"h_ft", "mach", "n"}, ...]}.
Output (stdout, JSON): one object per condition, either {"ok": false, "error": text} or
{"ok": true, "alpha_deg", "elevator_rad", "q_rad_sec", "load_factor" (JSBSim's
forces/load-factor), "throttle", "thrust_lbs", "qdot", "udot", "wdot", "vt_fps", "weight_lbs",
"qbar_psf", "alphadot_rad_sec", "thrust_moment_lbsft" (the pitching moment of the thrust about
the CG)}.
Needs `pip install jsbsim==1.3.3`.
"""
import json
import re
import sys

import jsbsim

PULLUP = 3


MISSING = re.compile(r"The property (\S+) does not exist")


def loaded(root, model):
    """The model loaded with its systems and run through its initial conditions once: a property
    that only a simulator host creates (the F-104's radar range) is created at zero first."""
    created = []
    for _ in range(20):
        fdm = jsbsim.FGFDMExec(root)
        fdm.set_debug_level(0)
        for name in created:
            fdm[name] = 0.0
        if not fdm.load_model(model):
            sys.exit("JSBSim could not load %s" % model)
        try:
            fdm.run_ic()
            return fdm
        except Exception as e:  # a property the systems read that nothing creates
            found = MISSING.search(str(e))
            if not found:
                raise
            created.append(found.group(1))
    sys.exit("JSBSim could not initialise %s" % model)


def trim(root, model, c):
    """JSBSim's pull-up trim of `model` at condition `c`."""
    fdm = loaded(root, model)
    fdm["ic/h-sl-ft"] = c["h_ft"]
    fdm["ic/mach"] = c["mach"]
    fdm["ic/gamma-deg"] = 0.0
    fdm["ic/targetNlf"] = c["n"]
    fdm["gear/gear-cmd-norm"] = 0.0
    fdm["gear/gear-pos-norm"] = 0.0
    fdm.run_ic()
    fdm["propulsion/set-running"] = -1
    fdm["gear/gear-cmd-norm"] = 0.0
    fdm["gear/gear-pos-norm"] = 0.0
    try:
        fdm["simulation/do_simple_trim"] = PULLUP
    except Exception as e:  # JSBSim raises on a failed trim
        return {"ok": False, "error": str(e)}
    get = fdm.get_property_value
    return {
        "ok": True,
        "alpha_deg": get("aero/alpha-deg"),
        "elevator_rad": get("fcs/elevator-pos-rad"),
        "q_rad_sec": get("velocities/q-rad_sec"),
        "load_factor": get("forces/load-factor"),
        "throttle": get("fcs/throttle-pos-norm"),
        "thrust_lbs": get("propulsion/engine/thrust-lbs"),
        "qdot": get("accelerations/qdot-rad_sec2"),
        "udot": get("accelerations/udot-ft_sec2"),
        "wdot": get("accelerations/wdot-ft_sec2"),
        "vt_fps": get("velocities/vt-fps"),
        "qbar_psf": get("aero/qbar-psf"),
        "alphadot_rad_sec": get("aero/alphadot-rad_sec"),
        "thrust_moment_lbsft": get("moments/m-prop-lbsft"),
        "weight_lbs": get("inertia/weight-lbs"),
    }


def main():
    request = json.load(sys.stdin)
    out = [trim(request["root"], request["model"], c) for c in request["conditions"]]
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
