#!/usr/bin/env python3
"""JSBSim itself as the oracle of `model::jsbsim`: evaluates a catalogue model's aerodynamics
at given flight states and prints every value the Rust evaluation is compared with.

Input (stdin, JSON): {"root": DIR, "model": NAME, "inputs": [property, ...],
"functions": [property, ...], "states": [{"h_ft", "mach", "alpha_deg", "beta_deg",
"p", "q", "r" (rad/s), "set": {property: value}}, ...]}.
With "quasi_steady": true the copy's aerodynamics read zero for alpha-dot and beta-dot (their
properties renamed to ones held at zero) and run_ic is repeated until the fed-back
aero/cl-squared settles, so that JSBSim gives the quasi-steady coefficients the import
differentiates.
Output (stdout, JSON): one object per state with "inputs" (the value JSBSim's aerodynamics
read for each requested input), "functions" (each named function's value), "forces" (body
axes, lbs), "moments" (about the CG, body axes, lbs ft), "mass" (weight, CG, inertia) and
"atmosphere" (density, speed of sound, qbar, Mach).

JSBSim runs the model's flight control system and other systems during run_ic, which would move
the surfaces with the state; the oracle therefore loads a copy of the model whose
<flight_control>, <autopilot> and <system> elements are cut out of the XML text (everything else,
the aerodynamics included, byte-identical), so the surface positions and other system outputs
stay at the values set here. Needs `pip install jsbsim==1.3.3`.
"""
import json
import os
import re
import shutil
import sys
import tempfile

import jsbsim

SYSTEM_ELEMENTS = ("flight_control", "autopilot", "system")


def strip_systems(text):
    """The model XML without its systems (each element cut out of the text)."""
    for tag in SYSTEM_ELEMENTS:
        text = re.sub(r"<%s\b[^>]*/>" % tag, "", text)
        text = re.sub(r"<%s\b[^>]*>.*?</%s>" % (tag, tag), "", text, flags=re.S)
    return text


RATES = ("aero/alphadot-rad_sec", "aero/betadot-rad_sec", "aero/alphadot-deg_sec",
         "aero/betadot-deg_sec")


def held_rates(text):
    """The model XML with its alpha-dot and beta-dot reads renamed to properties held at zero."""
    for rate in RATES:
        text = text.replace(rate, "oracle/" + rate.split("/")[1])
    return text


def prepared_root(root, model, quasi_steady=False):
    """A temporary JSBSim root holding the stripped model, with engine/ and systems/ linked."""
    tmp = tempfile.mkdtemp(prefix="jsbsim-oracle-")
    os.makedirs(os.path.join(tmp, "aircraft"))
    src = os.path.join(root, "aircraft", model)
    dst = os.path.join(tmp, "aircraft", model)
    shutil.copytree(src, dst)
    xml = os.path.join(dst, model + ".xml")
    with open(xml, encoding="utf-8") as f:
        text = f.read()
    with open(xml, "w", encoding="utf-8") as f:
        text = strip_systems(text)
        f.write(held_rates(text) if quasi_steady else text)
    for d in ("engine", "systems"):
        if os.path.isdir(os.path.join(root, d)):
            os.symlink(os.path.join(root, d), os.path.join(tmp, d))
    return tmp


def evaluate(fdm, state, inputs, functions, passes=2):
    """Sets the state and runs the initial conditions `passes` times, the values set before each
    pass (so that values fed back from the previous pass, such as aero/cl-squared, are those the
    last pass used), then reads what the last pass used: an input that a model run before the
    aerodynamics overwrites (the throttle's position, from its command) is read as overwritten."""
    fdm["ic/h-sl-ft"] = state["h_ft"]
    fdm["ic/mach"] = state["mach"]
    fdm["ic/alpha-deg"] = state["alpha_deg"]
    fdm["ic/beta-deg"] = state["beta_deg"]
    fdm["ic/p-rad_sec"] = state["p"]
    fdm["ic/q-rad_sec"] = state["q"]
    fdm["ic/r-rad_sec"] = state["r"]
    for _ in range(passes):
        for name, value in state.get("set", {}).items():
            fdm[name] = value
        fdm.run_ic()
    get = fdm.get_property_value
    return {
        "h_ft": state["h_ft"],
        "inputs": {n: get(n) for n in inputs},
        "functions": {n: get(n) for n in functions},
        "forces": [get("forces/fb%s-aero-lbs" % a) for a in "xyz"],
        "moments": [get("moments/%s-aero-lbsft" % a) for a in "lmn"],
        "mass": {
            "weight": get("inertia/weight-lbs"),
            "cg": [get("inertia/cg-%s-in" % a) for a in "xyz"],
            "ixx": get("inertia/ixx-slugs_ft2"),
            "iyy": get("inertia/iyy-slugs_ft2"),
            "izz": get("inertia/izz-slugs_ft2"),
            "ixz": get("inertia/ixz-slugs_ft2"),
        },
        "atmosphere": {
            "rho": get("atmosphere/rho-slugs_ft3"),
            "a": get("atmosphere/a-fps"),
            "qbar": get("aero/qbar-psf"),
            "mach": get("velocities/mach"),
            "vt": get("velocities/vt-fps"),
            "alpha": get("aero/alpha-rad"),
            "beta": get("aero/beta-rad"),
        },
    }


def main():
    request = json.load(sys.stdin)
    quasi_steady = request.get("quasi_steady", False)
    root = prepared_root(request["root"], request["model"], quasi_steady)
    try:
        fdm = jsbsim.FGFDMExec(root)
        fdm.set_debug_level(0)
        # Inputs that only the stripped systems (or a simulator host) would create.
        for name in request["inputs"]:
            if not fdm.get_property_manager().hasNode(name):
                fdm[name] = 0.0
        if quasi_steady:
            for rate in RATES:
                fdm["oracle/" + rate.split("/")[1]] = 0.0
        if not fdm.load_model(request["model"]):
            sys.exit("JSBSim could not load %s" % request["model"])
        passes = 40 if quasi_steady else 2
        out = [evaluate(fdm, s, request["inputs"], request["functions"], passes)
               for s in request["states"]]
    finally:
        shutil.rmtree(root, ignore_errors=True)
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
