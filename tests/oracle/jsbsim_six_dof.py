#!/usr/bin/env python3
"""JSBSim's own nonlinear 6-DOF flight as the oracle of the roll-coupling analysis: trims a
catalogue model at an altitude, a Mach number and a load factor n with its flight control
system cut, steps the aileron surface and records the motion.

The model is a copy of the catalogue model (see `prepared_model`):
- its <flight_control>, <autopilot> and <system> elements are cut out of the XML text (as
  jsbsim_oracle.py does), so the surface positions set here are the ones the aerodynamics read
  for the whole run; what those systems would have moved stays at its rest value (gear up, flaps,
  speed brake and the F-16's leading-edge flap at 0);
- the terrain is set 30,000 ft below sea level, so that no gear touches the ground and no ground
  effect acts at the lowest altitudes;
- its <engine> elements are cut: no engine thrust, no engine torque, no fuel burnt (the tanks and
  their contents stay, so the mass, the centre of gravity and the inertia are the loaded model's
  and frozen; propulsion/fuel_freeze is also set);
- with `--flat-earth` a <planet> element puts it on a flat, non-rotating planet with standard
  gravity (no rotation, radius 1e10 ft, no J2, sea-level gravity 32.174049 ft/s^2): the Earth of
  the native 6-DOF (model/src/six_dof), which tests/tests/six_dof_native.rs compares with;
- with `--thrust trim` a body-axis force "oracle-thrust" is added at each engine's thruster
  location along its thrust line; its magnitude (the same for every engine) is a trim unknown and
  is held for the whole run (thrust held, not the engine's response to Mach and altitude; the
  engine's capability is not checked). With `--thrust off` there is no thrust and the speed is
  free to decay.

The trim is this script's own (JSBSim's FGTrim moves the pilot's commands, which do not reach the
surfaces once the flight control system is cut): with wings level, beta = 0, p = r = 0,
flight-path angle 0 and q = (n - 1) g / V (g JSBSim's local gravitation; a wings-level pull-up,
level flight at n = 1, a push-over at n = 0), Newton's method with a finite-difference Jacobian
and a backtracking line search finds alpha and the elevator surface (and with thrust held the
thrust) such that, at the initial instant, JSBSim's own accelerations after run_ic give
alpha-dot = 0 (from udot, wdot), q-dot = 0, and with thrust held V-dot = 0. The flight path then
curves at (n - 1) g / V relative to the rotating Earth, and the lift is m (n g - Omega^2 R): the
start (latitude 0, heading north) feels the Earth's centrifugal relief, 0.35 % of g, and no
Coriolis force. A trim whose elevator lies beyond the surface's travel (measured as below) is
refused.

Sign convention of the aileron: the deflection given here is JSBSim's, the left aileron's
position (fcs/left-aileron-pos-rad, positive rolls right: positive p); the right aileron is set to
its negative and every form the aerodynamics may read (-rad, -deg, -norm, mag-, and
fcs/aileron-pos-*) is set. This project's convention is the paper's, l_delta_a < 0 (positive
delta_a rolls left), so the project's delta_a is the negative of this deflection; the JSON gives
both.

The surfaces' travel (and the -norm scale) is measured in JSBSim itself: the catalogue model with
its flight control system intact, at the same flight condition, with the stick command
(fcs/aileron-cmd-norm, fcs/elevator-cmd-norm) held at +1 and then -1 for 1 s; the extreme
positions reached are the limits (a fly-by-wire stick, as the F-16's elevator's, may reach less
than the surface's travel: `--elevator-travel-deg` gives it).

Output (stdout, JSON): the trim (alpha, elevator, thrust, residuals and the load factors JSBSim
reports), and either one run's time histories (t, alpha, beta, p, q, r in body axes, V, Mach,
altitude, phi, theta, psi) or, with `--sweep A:B:S`, per aileron step the settled roll rate:
the mean of p over the last 2 s of the run, with p's minimum and maximum over the window from
6 s to the end (`settle_window`), a step being "settled" when that spread is below 0.05 rad/s +
5 % of |mean|. The steepest rise of the settled roll rate between neighbouring steps is reported
as a jump when its slope exceeds 3 times the median slope of the sweep and 0.3 rad/s per deg of
aileron. A jump that starts later than the window's start shows as an unsettled step.

Needs `pip install jsbsim==1.3.3`.
"""
import argparse
import json
import math
import os
import re
import shutil
import sys

import jsbsim

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from jsbsim_oracle import prepared_root  # noqa: E402

FT = 0.3048
DT_DEFAULT = 1.0 / 120.0
SETTLE_WINDOW_START = 6.0
MEAN_SPAN = 2.0
# The ground, far below every condition: no gear contact and no ground effect at sea level.
TERRAIN_FT = -30000.0


class Untrimmable(Exception):
    """The trim cannot be reached (elevator beyond its travel, or Newton does not converge)."""


# ----------------------------------------------------------------------------------------------
# The model copy


def thruster_lines(text):
    """Each engine's thruster location (in) and unit thrust direction (body axes)."""
    lines = []
    for engine in re.findall(r"<engine\b.*?</engine>", text, flags=re.S):
        loc = re.search(r"<location\b[^>]*>(.*?)</location>", engine, flags=re.S)
        xyz = [float(re.search(r"<%s>\s*([-+0-9.eE]+)\s*</%s>" % (a, a), loc.group(1)).group(1))
               for a in "xyz"]
        unit = re.search(r"<location\b[^>]*unit=\"(\w+)\"", engine)
        if unit and unit.group(1).upper() in ("M",):
            xyz = [v / 0.0254 for v in xyz]
        orient = re.search(r"<orient\b[^>]*>(.*?)</orient>", engine, flags=re.S)
        pitch = yaw = 0.0
        if orient:
            deg = "DEG" in re.search(r"<orient\b([^>]*)>", engine).group(1).upper()
            k = math.pi / 180.0 if deg else 1.0
            m = re.search(r"<pitch>\s*([-+0-9.eE]+)", orient.group(1))
            pitch = float(m.group(1)) * k if m else 0.0
            m = re.search(r"<yaw>\s*([-+0-9.eE]+)", orient.group(1))
            yaw = float(m.group(1)) * k if m else 0.0
        direction = [math.cos(pitch) * math.cos(yaw), math.cos(pitch) * math.sin(yaw),
                     -math.sin(pitch)]
        lines.append((xyz, direction))
    return lines


def thrust_forces(lines):
    """The XML of one held body-axis force per thruster."""
    out = []
    for i, (xyz, d) in enumerate(lines):
        out.append(
            '<force name="oracle-thrust-%d" frame="BODY">'
            '<location unit="IN"><x>%r</x><y>%r</y><z>%r</z></location>'
            '<direction><x>%r</x><y>%r</y><z>%r</z></direction></force>'
            % ((i,) + tuple(xyz) + tuple(d)))
    return "\n".join(out)


# A planet that is locally the flat, non-rotating Earth of the native 6-DOF (model/src/six_dof):
# no rotation, a radius of 1e10 ft (over 10 s of flight the local vertical turns by 1e-7 rad and
# gravity falls by 5e-6 per 7 km of altitude), no J2, and GM such that gravity at sea level is
# standard gravity, 32.174049 ft/s^2.
FLAT_RADIUS_FT = 1.0e10
FLAT_PLANET = (
    '<planet name="flat">'
    '<semimajor_axis unit="FT">%r</semimajor_axis><semiminor_axis unit="FT">%r</semiminor_axis>'
    '<rotation_rate unit="RAD/SEC">0</rotation_rate><GM unit="FT3/SEC2">%r</GM><J2>0</J2>'
    '</planet>' % (FLAT_RADIUS_FT, FLAT_RADIUS_FT, 32.174049 * FLAT_RADIUS_FT ** 2))


def prepared_model(root, model, thrust, flat_earth=False):
    """A temporary JSBSim root with the model's systems and engines cut (see the module doc),
    on the flat planet with `flat_earth`; returns (root, number of thrust forces)."""
    tmp = prepared_root(root, model)
    xml = os.path.join(tmp, "aircraft", model, model + ".xml")
    with open(xml, encoding="utf-8") as f:
        text = f.read()
    if flat_earth:
        text = re.sub(r"<planet\b.*?</planet>", "", text, flags=re.S)
        text = re.sub(r"(<metrics\b)", FLAT_PLANET + r"\n\1", text, count=1)
    lines = thruster_lines(text)
    text = re.sub(r"<engine\b.*?</engine>", "", text, flags=re.S)
    forces = 0
    if thrust == "trim":
        if not lines:
            shutil.rmtree(tmp, ignore_errors=True)
            raise Untrimmable("%s has no <engine> with a thruster: use --thrust off" % model)
        block = thrust_forces(lines)
        if "</external_reactions>" in text:
            text = text.replace("</external_reactions>", block + "\n</external_reactions>", 1)
        else:
            text = text.replace("</fdm_config>",
                                "<external_reactions>\n%s\n</external_reactions>\n</fdm_config>"
                                % block, 1)
        forces = len(lines)
    with open(xml, "w", encoding="utf-8") as f:
        f.write(text)
    return tmp, forces, text


def referenced_properties(text):
    """Property names the model's remaining elements read."""
    names = re.findall(r"<(?:property|independentVar)\b[^>]*>\s*-?([A-Za-z][\w\-/\[\]]*)\s*<",
                       text)
    return sorted(set(names))


# ----------------------------------------------------------------------------------------------
# Surfaces


AILERON_FORMS = (("fcs/left-aileron-pos", 1.0), ("fcs/aileron-pos", 1.0),
                 ("fcs/right-aileron-pos", -1.0))
ELEVATOR_FORMS = (("fcs/elevator-pos", 1.0),)


def norm_of(rad, limits):
    """The -norm form: the position over the travel on its side of zero."""
    lo, hi = limits
    if rad >= 0.0:
        return rad / hi if hi > 0.0 else 0.0
    return -rad / lo if lo < 0.0 else 0.0


def set_surface(fdm, forms, rad, limits):
    """Sets every form of a surface's position (rad, deg, norm, magnitude)."""
    pm = fdm.get_property_manager()
    for base, sign in forms:
        value = sign * rad
        fdm[base + "-rad"] = value
        fdm[base + "-deg"] = math.degrees(value)
        fdm[base + "-norm"] = norm_of(value, limits)
        mag = base.replace("fcs/", "fcs/mag-") + "-rad"
        if not pm.hasNode(mag) or abs(fdm[mag] - abs(value)) > 1e-15:
            fdm[mag] = abs(value)


HOST_INPUTS = set()


def run_creating_inputs(fdm, action):
    """Runs `action`; a property that a system reads but only a simulator host would create
    (the F-104's systems/radar/range) is created at 0 and the action repeated. Names met once
    are created up front on later runs."""
    pm = fdm.get_property_manager()
    for name in HOST_INPUTS:
        if not pm.hasNode(name):
            fdm[name] = 0.0
    for _ in range(100):
        try:
            return action()
        except Exception as e:  # JSBSim raises its LogExceptionError
            m = re.search(r"The property (\S+) does not exist", str(e))
            if not m:
                raise
            HOST_INPUTS.add(m.group(1))
            fdm[m.group(1)] = 0.0
    raise Untrimmable("too many undefined properties")


def set_condition(fdm, h_ft, mach):
    """The flight condition of the initial state, over the terrain far below."""
    fdm["ic/terrain-elevation-ft"] = TERRAIN_FT
    fdm["ic/h-sl-ft"] = h_ft
    fdm["ic/mach"] = mach


def read_position(text, forms):
    """The rad form of a surface's position that the model's aerodynamics read (the first of
    `forms` referenced), else the first form's."""
    read = referenced_properties(text)
    for base, _ in forms:
        if base + "-rad" in read:
            return base + "-rad"
    return forms[0][0] + "-rad"


def measured_limits(root, model, h_ft, mach):
    """The aileron and elevator travel (rad) that JSBSim's intact flight control system reaches
    at full stick, of the position the aerodynamics read: {control: (min, max)}."""
    with open(os.path.join(root, "aircraft", model, model + ".xml"), encoding="utf-8") as f:
        text = f.read()
    fdm = jsbsim.FGFDMExec(root)
    fdm.set_debug_level(0)
    if not fdm.load_model(model):
        raise Untrimmable("JSBSim could not load %s" % model)
    out = {}
    for control, forms in (("aileron", AILERON_FORMS), ("elevator", ELEVATOR_FORMS)):
        prop = read_position(text, forms)
        ends = []
        for cmd in (-1.0, 1.0):
            set_condition(fdm, h_ft, mach)
            for name in ("gear/gear-cmd-norm", "fcs/aileron-cmd-norm", "fcs/elevator-cmd-norm"):
                fdm[name] = 0.0
            fdm["fcs/%s-cmd-norm" % control] = cmd
            run_creating_inputs(fdm, fdm.run_ic)
            reached = fdm[prop]
            for _ in range(120):
                fdm["fcs/%s-cmd-norm" % control] = cmd
                fdm.run()
                reached = max(reached, fdm[prop]) if cmd > 0 else min(reached, fdm[prop])
            ends.append(reached)
        out[control] = (min(ends[0], 0.0), max(ends[1], 0.0))
        if out[control] == (0.0, 0.0):
            raise Untrimmable(
                "%s: full stick does not move %s (the model's %s is read in another form, "
                "e.g. -norm only, which this oracle does not drive)" % (model, prop, control))
        out[control + "_property"] = prop
    return out


# ----------------------------------------------------------------------------------------------
# The cut model and its initial state


class Aircraft:
    """The cut model loaded in JSBSim."""

    def __init__(self, root, model, thrust, limits, dt=DT_DEFAULT, flat_earth=False,
                 integrators=None):
        self.tmp, self.forces, text = prepared_model(root, model, thrust, flat_earth)
        self.limits = limits
        fdm = jsbsim.FGFDMExec(self.tmp)
        fdm.set_debug_level(0)
        if not fdm.load_model(model):
            raise Untrimmable("JSBSim could not load the cut copy of %s" % model)
        pm = fdm.get_property_manager()
        self.created = [n for n in referenced_properties(text) if not pm.hasNode(n)]
        for name in self.created:
            fdm[name] = 0.0
        fdm.set_dt(dt)
        # JSBSim's integrators (FGPropagate): 0 none, 1 rectangular Euler, 2 trapezoidal, 3-5
        # Adams-Bashforth 2-4; the defaults are 1, 2, 1, 3 for the rotational rate, the
        # translational rate, the attitude and the position.
        for name, value in zip(("rate/rotational", "rate/translational", "position/rotational",
                                "position/translational"), integrators or ()):
            fdm["simulation/integrator/" + name] = value
        self.fdm = fdm

    def close(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def configure(self, elevator, aileron, thrust_lbs):
        """The surfaces and held thrust, and the rest configuration (gear up, fuel frozen)."""
        fdm = self.fdm
        fdm["gear/gear-cmd-norm"] = 0.0
        fdm["gear/gear-pos-norm"] = 0.0
        fdm["propulsion/fuel_freeze"] = 1.0
        set_surface(fdm, ELEVATOR_FORMS, elevator, self.limits["elevator"])
        set_surface(fdm, AILERON_FORMS, aileron, self.limits["aileron"])
        for i in range(self.forces):
            fdm["external_reactions/oracle-thrust-%d/magnitude" % i] = thrust_lbs / self.forces

    def start(self, h_ft, mach, alpha, q, elevator, aileron=0.0, thrust_lbs=0.0, passes=2):
        """Sets the initial state (wings level, beta 0, gamma 0, p = r = 0, pitch rate q) and runs
        the initial conditions `passes` times so that values fed back from one pass (alpha-dot)
        are the ones the last pass used."""
        fdm = self.fdm
        set_condition(fdm, h_ft, mach)
        fdm["ic/alpha-rad"] = alpha
        fdm["ic/beta-rad"] = 0.0
        fdm["ic/gamma-rad"] = 0.0
        fdm["ic/phi-rad"] = 0.0
        fdm["ic/psi-true-rad"] = 0.0
        fdm["ic/p-rad_sec"] = 0.0
        fdm["ic/q-rad_sec"] = q
        fdm["ic/r-rad_sec"] = 0.0
        for _ in range(passes):
            self.configure(elevator, aileron, thrust_lbs)
            fdm.run_ic()

    def state(self):
        fdm = self.fdm
        return {
            "t": fdm.get_sim_time(),
            "alpha": fdm["aero/alpha-rad"],
            "beta": fdm["aero/beta-rad"],
            "p": fdm["velocities/p-rad_sec"],
            "q": fdm["velocities/q-rad_sec"],
            "r": fdm["velocities/r-rad_sec"],
            "V": fdm["velocities/vt-fps"] * FT,
            "mach": fdm["velocities/mach"],
            "altitude": fdm["position/h-sl-ft"] * FT,
            "phi": fdm["attitude/phi-rad"],
            "theta": fdm["attitude/theta-rad"],
            "psi": fdm["attitude/psi-rad"],
        }

    def rates_of_change(self):
        """alpha-dot (rad/s), q-dot (rad/s^2) and V-dot (ft/s^2) from JSBSim's accelerations."""
        f = self.fdm
        u, v, w = f["velocities/u-fps"], f["velocities/v-fps"], f["velocities/w-fps"]
        ud, vd, wd = (f["accelerations/udot-ft_sec2"], f["accelerations/vdot-ft_sec2"],
                      f["accelerations/wdot-ft_sec2"])
        vt2 = u * u + v * v + w * w
        return {
            "alpha_dot": (u * wd - w * ud) / (u * u + w * w),
            "q_dot": f["accelerations/qdot-rad_sec2"],
            "V_dot": (u * ud + v * vd + w * wd) / math.sqrt(vt2),
            "p_dot": f["accelerations/pdot-rad_sec2"],
            "r_dot": f["accelerations/rdot-rad_sec2"],
            "beta_dot": f["aero/betadot-rad_sec"],
        }


def fuel_lbs(fdm):
    """The fuel in the tanks."""
    pm, total, i = fdm.get_property_manager(), 0.0, 0
    while pm.hasNode("propulsion/tank[%d]/contents-lbs" % i):
        total += fdm["propulsion/tank[%d]/contents-lbs" % i]
        i += 1
    return total


# ----------------------------------------------------------------------------------------------
# The trim


def pitch_rate(ac, h_ft, mach, n):
    """q = (n - 1) g / V at the condition, with JSBSim's gravity and speed."""
    ac.start(h_ft, mach, 0.0, 0.0, 0.0)
    g = ac.fdm["accelerations/gravity-ft_sec2"]
    return (n - 1.0) * g / ac.fdm["velocities/vt-fps"], g


def residuals(ac, h_ft, mach, q, x, thrust):
    alpha, elevator = x[0], x[1]
    thrust_lbs = x[2] if thrust == "trim" else 0.0
    ac.start(h_ft, mach, alpha, q, elevator, 0.0, thrust_lbs)
    rc = ac.rates_of_change()
    r = [rc["alpha_dot"], rc["q_dot"]]
    if thrust == "trim":
        r.append(rc["V_dot"] / 32.174)
    return r


def solve(a, b):
    """Gaussian elimination with partial pivoting (2x2 or 3x3)."""
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(n):
        piv = max(range(c, n), key=lambda i: abs(m[i][c]))
        if abs(m[piv][c]) < 1e-300:
            raise Untrimmable("singular trim Jacobian")
        m[c], m[piv] = m[piv], m[c]
        for i in range(c + 1, n):
            k = m[i][c] / m[c][c]
            for j in range(c, n + 1):
                m[i][j] -= k * m[c][j]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (m[i][n] - sum(m[i][j] * x[j] for j in range(i + 1, n))) / m[i][i]
    return x


def line_search(f, x, dx, r):
    """x + s dx with the largest s in 1, 1/2, ... 1/1024 whose residual's max norm is below r's
    (the step limited to 5 deg in alpha and elevator), else the shortest step."""
    scale = 1.0
    if abs(dx[0]) > math.radians(5.0) or abs(dx[1]) > math.radians(5.0):
        scale = math.radians(5.0) / max(abs(dx[0]), abs(dx[1]))
    norm = max(abs(v) for v in r)
    for _ in range(11):
        xt = [xi + scale * di for xi, di in zip(x, dx)]
        if max(abs(v) for v in f(xt)) < norm:
            return xt
        scale /= 2.0
    return xt


def trim(ac, h_ft, mach, n, thrust, tol=1e-10, max_iter=40, log=None):
    """alpha, elevator (and thrust) of the n-g wings-level trim (see the module doc)."""
    q, g = pitch_rate(ac, h_ft, mach, n)
    x = [math.radians(2.0), 0.0] + ([1000.0] if thrust == "trim" else [])
    steps = [1e-6, 1e-6, 1.0]
    history = []
    for it in range(max_iter):
        r = residuals(ac, h_ft, mach, q, x, thrust)
        history.append({"iteration": it, "x": list(x), "residuals": r})
        if log:
            log("trim %2d: alpha=%.9f deg elevator=%.9f deg%s residuals=%s" % (
                it, math.degrees(x[0]), math.degrees(x[1]),
                (" thrust=%.3f lbs" % x[2]) if len(x) > 2 else "",
                " ".join("%.3e" % v for v in r)))
        if max(abs(v) for v in r) < tol:
            break
        jac = [[0.0] * len(x) for _ in r]
        for j in range(len(x)):
            xp = list(x)
            xp[j] += steps[j]
            rp = residuals(ac, h_ft, mach, q, xp, thrust)
            for i in range(len(r)):
                jac[i][j] = (rp[i] - r[i]) / steps[j]
        dx = solve(jac, [-v for v in r])
        x = line_search(lambda xt: residuals(ac, h_ft, mach, q, xt, thrust), x, dx, r)
        if abs(x[0]) > math.radians(40.0):
            raise Untrimmable("no trim: alpha left +-40 deg (%.1f deg)" % math.degrees(x[0]))
    else:
        raise Untrimmable("trim did not converge in %d iterations: residuals %s"
                          % (max_iter, r))
    lo, hi = ac.limits.get("elevator_travel", ac.limits["elevator"])
    if not lo <= x[1] <= hi:
        raise Untrimmable(
            "untrimmable: the elevator surface needed is %.2f deg, beyond its travel %.2f to %.2f "
            "deg (%s)" % (math.degrees(x[1]), math.degrees(lo), math.degrees(hi),
                          "as given" if "elevator_travel" in ac.limits
                          else "JSBSim's full stick"))
    ac.start(h_ft, mach, x[0], q, x[1], 0.0, x[2] if thrust == "trim" else 0.0)
    f = ac.fdm
    return {
        "altitude_m": h_ft * FT,
        "mach": mach,
        "load_factor": n,
        "thrust_mode": thrust,
        "alpha_deg": math.degrees(x[0]),
        "elevator_deg": math.degrees(x[1]),
        "elevator_travel_deg": [math.degrees(lo), math.degrees(hi)],
        "aileron_travel_deg": [math.degrees(v) for v in ac.limits["aileron"]],
        "travel_of": [ac.limits["aileron_property"], ac.limits["elevator_property"]],
        "thrust_lbs": x[2] if thrust == "trim" else 0.0,
        "q_rad_s": q,
        "gravity_ft_s2": g,
        "residuals": dict(zip(["alpha_dot_rad_s", "q_dot_rad_s2", "V_dot_g"],
                              history[-1]["residuals"])),
        "iterations": len(history) - 1,
        "check": {
            "rates_of_change": ac.rates_of_change(),
            "Nz": f["accelerations/Nz"],
            "n_pilot_z": f["accelerations/n-pilot-z-norm"],
            "gamma_deg": f["flight-path/gamma-deg"],
            "theta_deg": f["attitude/theta-deg"],
            "V_m_s": f["velocities/vt-fps"] * FT,
            "qbar_psf": f["aero/qbar-psf"],
            "weight_lbs": f["inertia/weight-lbs"],
            "gear_pos_norm": f["gear/gear-pos-norm"],
            "h_agl_ft": f["position/h-agl-ft"],
            "wow": f["gear/wow"] if f.get_property_manager().hasNode("gear/wow") else None,
            "fuel_lbs": fuel_lbs(f),
        },
        "created_properties": ac.created,
    }


# ----------------------------------------------------------------------------------------------
# The aileron step


def step_run(ac, trimmed, aileron, seconds, h_ft):
    """From the trim, the aileron surfaces stepped to `aileron` (rad, JSBSim's sign) at t = 0;
    the states every integration step for `seconds`."""
    x = trimmed
    ac.start(h_ft, x["mach"], math.radians(x["alpha_deg"]), x["q_rad_s"],
             math.radians(x["elevator_deg"]), 0.0, x["thrust_lbs"])
    ac.fdm.set_sim_time(0.0)
    ac.configure(math.radians(x["elevator_deg"]), aileron, x["thrust_lbs"])
    fuel, weight = fuel_lbs(ac.fdm), ac.fdm["inertia/weight-lbs"]
    rows = [ac.state()]
    dt = ac.fdm.get_delta_t()
    steps = int(round(seconds / dt))
    for _ in range(steps):
        ac.fdm.run()
        rows.append(ac.state())
    if fuel_lbs(ac.fdm) != fuel or ac.fdm["inertia/weight-lbs"] != weight:
        raise Untrimmable("fuel changed during the run")
    return rows


def settled(rows, seconds):
    """The settled roll rate (see the module doc)."""
    t_end = rows[-1]["t"]
    window = [r for r in rows if r["t"] >= min(SETTLE_WINDOW_START, t_end / 2) - 1e-9]
    last = [r["p"] for r in rows if r["t"] >= t_end - MEAN_SPAN - 1e-9]
    mean = sum(last) / len(last)
    lo = min(r["p"] for r in window)
    hi = max(r["p"] for r in window)
    return {
        "p_mean_last2s": mean,
        "p_min_window": lo,
        "p_max_window": hi,
        "settled": hi - lo < 0.05 + 0.05 * abs(mean),
        "p_peak": max((r["p"] for r in rows), key=abs),
        "alpha_max_deg": math.degrees(max(r["alpha"] for r in rows)),
        "alpha_min_deg": math.degrees(min(r["alpha"] for r in rows)),
        "beta_maxabs_deg": math.degrees(max(abs(r["beta"]) for r in rows)),
        "mach_end": rows[-1]["mach"],
        "altitude_end_m": rows[-1]["altitude"],
        "theta_end_deg": math.degrees(rows[-1]["theta"]),
        "finite": all(math.isfinite(v) for r in rows for v in r.values()),
    }


JUMP_RATIO = 3.0
JUMP_MIN_SLOPE = 0.3


def find_jump(sweep):
    """The steepest rise of the settled roll rate between neighbouring steps (rad/s per deg of
    aileron), a jump when that slope exceeds JUMP_RATIO times the sweep's median slope and
    JUMP_MIN_SLOPE rad/s per deg."""
    if len(sweep) < 3:
        return None
    slopes = [((b["p_mean_last2s"] - a["p_mean_last2s"]) / (b["aileron_deg"] - a["aileron_deg"]),
               a, b) for a, b in zip(sweep, sweep[1:])]
    mags = sorted(abs(s[0]) for s in slopes)
    median = mags[len(mags) // 2]
    big = max(slopes, key=lambda s: abs(s[0]))
    return {
        "between_deg": [big[1]["aileron_deg"], big[2]["aileron_deg"]],
        "slope_rad_s_per_deg": big[0],
        "median_slope_rad_s_per_deg": median,
        "jump": abs(big[0]) > max(JUMP_RATIO * median, JUMP_MIN_SLOPE),
    }


def frange(spec):
    a, b, s = (float(v) for v in spec.split(":"))
    if s <= 0 or b < a:
        raise SystemExit("--sweep %s: expected A:B:S with A <= B and S > 0 (deg)" % spec)
    n = int(math.floor((b - a) / s + 1e-9))
    return [a + i * s for i in range(n + 1)]


def run(args, log=None):
    """The trim and then one run or a sweep, as a dict."""
    root = args.root or jsbsim.get_default_root_dir()
    if not os.path.isfile(os.path.join(root, "aircraft", args.model, args.model + ".xml")):
        raise Untrimmable("no model %s under %s/aircraft" % (args.model, root))
    h_ft = args.altitude_m / FT
    limits = measured_limits(root, args.model, h_ft, args.mach)
    if args.elevator_travel_deg:
        lo, hi = (math.radians(float(v)) for v in args.elevator_travel_deg.split(":"))
        if not lo < 0.0 < hi:
            raise Untrimmable("--elevator-travel-deg %s: expected MIN:MAX with MIN < 0 < MAX"
                              % args.elevator_travel_deg)
        limits["elevator_travel"] = (lo, hi)
        limits["elevator_property"] += " (travel given; -norm scaled by the measured one)"
    integrators = [int(v) for v in args.integrators.split(",")] if args.integrators else None
    ac = Aircraft(root, args.model, args.thrust, limits, args.dt or DT_DEFAULT, args.flat_earth,
                  integrators)
    try:
        trimmed = trim(ac, h_ft, args.mach, args.load_factor, args.thrust, log=log)
        out = {"model": args.model, "dt": ac.fdm.get_delta_t(), "trim": trimmed,
               "aileron_sign": "JSBSim's: the left aileron's position, positive rolls right "
                               "(p > 0); the project's delta_a is its negative"}
        if args.sweep:
            sweep = []
            for deg in frange(args.sweep):
                rows = step_run(ac, trimmed, math.radians(deg), args.time, h_ft)
                s = settled(rows, args.time)
                s.update({"aileron_deg": deg, "project_delta_a_deg": -deg})
                sweep.append(s)
                if log:
                    log("aileron %5.1f deg: p settled %.4f rad/s (window %.4f..%.4f)" % (
                        deg, s["p_mean_last2s"], s["p_min_window"], s["p_max_window"]))
            out["sweep"] = sweep
            out["jump"] = find_jump(sweep)
        else:
            rows = step_run(ac, trimmed, math.radians(args.aileron_deg), args.time, h_ft)
            out["aileron_deg"] = args.aileron_deg
            out["project_delta_a_deg"] = -args.aileron_deg
            out["settled"] = settled(rows, args.time)
            every = max(1, args.record_every)
            out["history"] = {k: [r[k] for r in rows[::every]] for k in rows[0]}
        return out
    finally:
        ac.close()


def parser():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--model", default="f104", help="catalogue model (default f104)")
    p.add_argument("--root", help="JSBSim root (default: the jsbsim package's)")
    p.add_argument("--altitude-m", type=float, default=6000.0)
    p.add_argument("--mach", type=float, default=0.7)
    p.add_argument("--load-factor", type=float, default=1.0,
                   help="n: 1 = 1-g level flight, 0 = unloaded (zero-lift) start")
    p.add_argument("--thrust", choices=("off", "trim"), default="off")
    p.add_argument("--aileron-deg", type=float, default=0.0,
                   help="aileron surface step, JSBSim's sign (positive rolls right)")
    p.add_argument("--time", type=float, default=10.0, help="seconds after the step")
    p.add_argument("--dt", type=float, help="integration step, s (default 1/120)")
    p.add_argument("--elevator-travel-deg",
                   help="MIN:MAX elevator travel instead of the one measured at full stick "
                        "(a fly-by-wire stick may not reach the surface's travel in 1 s); "
                        "write it --elevator-travel-deg=-25:25")
    p.add_argument("--sweep", help="A:B:S aileron steps in deg")
    p.add_argument("--flat-earth", action="store_true",
                   help="fly on a flat, non-rotating planet with standard gravity (the native "
                        "6-DOF's Earth) instead of JSBSim's rotating WGS84 Earth")
    p.add_argument("--integrators",
                   help="R,T,A,P: JSBSim's integrators of the rotational and translational rates, "
                        "the attitude and the position (1 Euler, 2 trapezoidal, 3-5 "
                        "Adams-Bashforth 2-4; default 1,2,1,3)")
    p.add_argument("--record-every", type=int, default=1, help="keep every k-th step")
    p.add_argument("--verbose", action="store_true", help="print the trim iterations on stderr")
    return p


def main():
    args = parser().parse_args()
    # JSBSim's messages go to Python's sys.stdout: standard error while JSBSim runs.
    json_out, sys.stdout = sys.stdout, sys.stderr
    log = (lambda s: print(s, file=sys.stderr)) if args.verbose else None
    try:
        out = run(args, log)
    except Untrimmable as e:
        print("jsbsim_six_dof: %s (model %s, %.0f m, Mach %.3f, n = %g)" % (
            e, args.model, args.altitude_m, args.mach, args.load_factor), file=sys.stderr)
        sys.exit(2)
    sys.stdout = json_out
    json.dump(out, sys.stdout)
    print()


if __name__ == "__main__":
    main()
