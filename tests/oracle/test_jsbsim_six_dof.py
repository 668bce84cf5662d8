"""Tests of jsbsim_six_dof.py (the 6-DOF oracle) itself: `python3 -m pytest tests/oracle` (needs
`pip install pytest jsbsim==1.3.3`), or `python3 tests/oracle/test_jsbsim_six_dof.py` without
pytest. The trim is checked through JSBSim's own forces (lift against weight), not through the
residuals the trim drove to zero."""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jsbsim  # noqa: E402
import jsbsim_six_dof as six  # noqa: E402

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "jsbsim_six_dof.py")
FT = six.FT


def trimmed(model="f104", alt=6000.0, mach=0.7, n=1.0, thrust="off"):
    """The cut model and its trim (the caller closes the model)."""
    root = jsbsim.get_default_root_dir()
    h_ft = alt / FT
    ac = six.Aircraft(root, model, thrust, six.measured_limits(root, model, h_ft, mach))
    return ac, six.trim(ac, h_ft, mach, n, thrust), h_ft


EARTH_RATE = 7.292115e-5  # rad/s, JSBSim's (WGS84)


def lift_error(ac, n):
    """Lift (JSBSim's wind-axis force, positive up) plus the thrust's component normal to the
    flight path, against what n-g flight with an unrotating body at the equator heading north
    needs: m (n g - Omega^2 R), g the local gravitation and Omega^2 R the Earth's centrifugal
    relief (the Coriolis force is zero there, the velocity being parallel to the Earth's axis),
    as a fraction of m g."""
    f = ac.fdm
    assert f["position/lat-geod-deg"] == 0.0 and f["attitude/psi-rad"] == 0.0
    thrust = sum(f["external_reactions/oracle-thrust-%d/magnitude" % i] for i in range(ac.forces))
    normal = f["forces/fwz-aero-lbs"] + thrust * math.sin(f["aero/alpha-rad"])
    m, g = f["inertia/mass-slugs"], f["accelerations/gravity-ft_sec2"]
    need = m * (n * g - EARTH_RATE ** 2 * f["position/radius-to-vehicle-ft"])
    return (normal - need) / (m * g)


def test_level_trim_balances_weight_and_pitch():
    ac, t, _ = trimmed()
    try:
        assert max(abs(v) for v in t["residuals"].values()) < 1e-9, t["residuals"]
        lo, hi = t["elevator_travel_deg"]
        assert lo < t["elevator_deg"] < hi
        assert 0.0 < t["alpha_deg"] < 15.0
        assert abs(lift_error(ac, 1.0)) < 1e-6, lift_error(ac, 1.0)
        assert abs(ac.fdm["accelerations/qdot-rad_sec2"]) < 1e-9
        assert abs(ac.fdm["flight-path/gamma-rad"]) < 1e-9
    finally:
        ac.close()


def test_load_factor_sets_lift_and_pitch_rate():
    for n in (0.0, 2.0):
        ac, t, _ = trimmed(n=n)
        try:
            assert max(abs(v) for v in t["residuals"].values()) < 1e-9, (n, t["residuals"])
            assert abs(lift_error(ac, n)) < 1e-6, (n, lift_error(ac, n))
            g = ac.fdm["accelerations/gravity-ft_sec2"]
            assert abs(ac.fdm["velocities/q-rad_sec"] - (n - 1.0) * g
                       / ac.fdm["velocities/vt-fps"]) < 1e-9
        finally:
            ac.close()


def test_held_thrust_holds_speed():
    ac, t, _ = trimmed(thrust="trim")
    try:
        assert max(abs(v) for v in t["residuals"].values()) < 1e-9, t["residuals"]
        assert t["thrust_lbs"] > 0.0
        assert abs(t["check"]["rates_of_change"]["V_dot"]) < 1e-6
        assert abs(lift_error(ac, 1.0)) < 1e-6, lift_error(ac, 1.0)
    finally:
        ac.close()


def test_zero_aileron_keeps_wings_level_for_2_s():
    ac, t, h_ft = trimmed(thrust="trim")
    try:
        rows = six.step_run(ac, t, 0.0, 2.0, h_ft)
    finally:
        ac.close()
    assert len(rows) == 241
    for r in rows:
        assert abs(r["phi"]) < 1e-9 and abs(r["p"]) < 1e-9 and abs(r["r"]) < 1e-9
        assert abs(r["beta"]) < 1e-9
        assert abs(math.degrees(r["alpha"]) - t["alpha_deg"]) < 0.05
        assert abs(r["V"] / rows[0]["V"] - 1.0) < 1e-3


def test_positive_aileron_rolls_right():
    ac, t, h_ft = trimmed()
    try:
        rows = six.step_run(ac, t, math.radians(5.0), 1.0, h_ft)
    finally:
        ac.close()
    assert rows[-1]["p"] > 0.1 and rows[-1]["phi"] > 0.0


def cli(*args):
    return subprocess.run([sys.executable, SCRIPT] + list(args), capture_output=True,
                          text=True, timeout=300)


def test_cli_prints_json_and_refuses_beyond_the_elevator_travel():
    ok = cli("--aileron-deg", "3", "--time", "1", "--record-every", "12")
    assert ok.returncode == 0, ok.stderr
    out = json.loads(ok.stdout)
    assert out["project_delta_a_deg"] == -3.0
    assert len(out["history"]["t"]) == 11
    assert all(math.isfinite(v) for k in out["history"] for v in out["history"][k])
    bad = cli("--elevator-travel-deg=-1:1")
    assert bad.returncode == 2
    assert "untrimmable" in bad.stderr and "beyond its travel" in bad.stderr, bad.stderr
    assert bad.stdout == ""


def test_find_jump_rule():
    def sweep(ps):
        return [{"aileron_deg": float(i + 1), "p_mean_last2s": p} for i, p in enumerate(ps)]
    assert six.find_jump(sweep([0.1, 0.2, 0.3, 0.4, 1.9, 2.0]))["jump"]
    assert six.find_jump(sweep([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]))["jump"] is False


if __name__ == "__main__":
    tests = [v for k, v in sorted(globals().items()) if k.startswith("test_")]
    failed = 0
    for test in tests:
        try:
            test()
        except Exception as e:  # report every test, as pytest would
            failed += 1
            print("FAILED %s: %r" % (test.__name__, e))
    print("%d passed, %d failed" % (len(tests) - failed, failed))
    sys.exit(1 if failed else 0)


def test_flat_earth_is_standard_gravity_without_rotation():
    """On the flat planet the trim's lift is n m g exactly (no centrifugal relief), gravity is
    32.174049 ft/s^2 scaled by (R / (R + h))^2 with R = 1e10 ft, and the Earth does not turn."""
    root = jsbsim.get_default_root_dir()
    h_ft = 6000.0 / FT
    limits = six.measured_limits(root, "f104", h_ft, 0.7)
    ac = six.Aircraft(root, "f104", "off", limits, flat_earth=True)
    try:
        t = six.trim(ac, h_ft, 0.7, 1.0, "off")
        r = six.FLAT_RADIUS_FT
        want = 32.174049 * (r / (r + h_ft)) ** 2
        assert abs(t["gravity_ft_s2"] - want) < 1e-9 * want, (t["gravity_ft_s2"], want)
        f = ac.fdm
        m, g = f["inertia/mass-slugs"], f["accelerations/gravity-ft_sec2"]
        # JSBSim's wind-axis z force is the lift, positive up (as in lift_error).
        assert abs((f["forces/fwz-aero-lbs"] - m * g) / (m * g)) < 1e-6
        assert f["velocities/psidot-rad_sec"] == 0.0 or abs(f["velocities/psidot-rad_sec"]) < 1e-12
    finally:
        ac.close()
