"""Every function against the command line's output for the same input: the same numbers bit
for bit (JSON and CSV print shortest round-trip decimals, which read back exactly)."""

import csv
import io
import math

import numpy as np
import pytest

import roll_coupling as rc
from conftest import ROOT, cli, cli_json

F104 = "jsbsim:f104 --altitude-m 6096 --mach 0.53"


def test_analyze_the_papers_aircraft_equals_the_cli_json():
    assert rc.analyze("A").to_dict() == cli_json("analyze", "A", "--json")
    assert rc.analyze("b", delta_e_deg=3.0).to_dict() == cli_json("analyze", "b", "--delta-e-deg", "3", "--json")


def test_analyze_certified_route_equals_the_cli_json():
    got = rc.analyze("A", certified=True).to_dict()
    assert got == cli_json("analyze", "A", "--json", "--certified")


def test_an_aircraft_as_path_text_or_dict_gives_the_files_analysis():
    tomllib = pytest.importorskip("tomllib")
    expected = cli_json("analyze", "aircraft/c.toml", "--json")
    text = (ROOT / "aircraft/c.toml").read_text()
    assert rc.analyze("aircraft/c.toml").to_dict() == expected
    for given in (text, tomllib.loads(text)):
        got = rc.analyze(given).to_dict()
        assert got == expected


def test_import_jsbsim_writes_the_clis_file_and_analyses_as_the_source():
    ac = rc.import_jsbsim("f104", 6096, mach=0.53)
    assert ac.toml == cli("import", "jsbsim", "f104", "--altitude-m", "6096", "--mach", "0.53").stdout
    assert ac.trim.load_factor == 1.0
    expected = cli_json("analyze", F104, "--json")
    assert rc.analyze(F104).to_dict() == expected
    # The imported file's analysis: the same numbers, under the file's own name.
    got = rc.analyze(ac).to_dict()
    assert got["critical"] == expected["critical"]
    assert got["jump"] == expected["jump"]


def test_simulate_series_equal_the_clis_csv(tmp_path):
    h = rc.simulate("A", delta_a_deg=-1.5, t_end=4.0)
    out = tmp_path / "a.csv"
    line = cli("simulate", "A", "--delta-a-deg", "-1.5", "--t-end", "4", "--csv", str(out)).stdout
    rows = list(csv.reader(io.StringIO(out.read_text())))
    table = np.array([[float(x) for x in r] for r in rows[1:]])
    names = ["t", "alpha", "beta", "p", "q", "r", "phi", "theta", "delta_a", "delta_r"]
    assert len(rows[0]) == len(names)
    for k, name in enumerate(names):
        assert np.array_equal(getattr(h, name), table[:, k]), name
    assert f"steady roll rate {h.steady.p_mean:.4f}" in line
    assert h.model in line


def test_clear_equals_the_cli_json():
    got = rc.clear("aircraft/a_uncertain.toml", samples=50).to_dict()
    assert got == cli_json("clear", "aircraft/a_uncertain.toml", "--samples", "50", "--json")


def test_clear_with_an_uncertainty_dict_equals_the_file_with_that_table():
    text = (ROOT / "aircraft/a_uncertain.toml").read_text().split("[uncertainty]")[0]
    box = {"l_p": "5%", "n_beta": 0.2, "l_beta": [-116.0, -105.0], "m_alpha": "5%"}
    got = rc.clear(text, uncertainty=box, samples=50).to_dict()
    expected = cli_json("clear", "aircraft/a_uncertain.toml", "--samples", "50", "--json")
    assert got == expected


def test_continue_equals_the_cli_json():
    got = rc.continue_("A", min_deg=-10, max_deg=10).to_dict()
    assert got == cli_json("continue", "A", "--min-deg", "-10", "--max-deg", "10", "--json")


ENVELOPE = ("jsbsim:f104", "0:6000:3000", "0.4:0.8:0.2")


def test_envelope_equals_the_cli_json_and_its_arrays_the_csv(tmp_path):
    source, h, m = ENVELOPE
    env = rc.envelope(source, h, m)
    out = tmp_path / "env"
    expected = cli_json("envelope", source, "--altitude-m", h, "--mach", m, "--json", "--out", str(out))
    assert env.to_dict() == expected
    assert list(env.altitudes_m) == [0.0, 3000.0, 6000.0]
    assert np.allclose(env.machs, [0.4, 0.6, 0.8], rtol=0, atol=1e-12)
    rows = list(csv.DictReader(io.StringIO((out / "envelope.csv").read_text())))
    assert len(rows) == env.p0.size
    for r in rows:
        i = list(env.altitudes_m).index(float(r["altitude_m"]))
        j = int(np.argmin(abs(env.machs - float(r["mach"]))))
        for column, grid in (("p0_rad_s", env.p0), ("delta_a_deg", env.delta_a_deg), ("margin_deg", env.margin_deg)):
            if column in r:
                cell = r[column]
                assert (math.isnan(grid[i, j]) and cell in ("", "-")) or float(cell) == grid[i, j], (column, r)


def test_envelope_axes_as_lists_arrays_or_numbers_mean_the_ranges():
    a = rc.envelope("jsbsim:f104", [0, 3000], 0.6).to_dict()
    b = rc.envelope("jsbsim:f104", "0:3000:3000", "0.6").to_dict()
    assert a["points"] == b["points"]
    c = rc.envelope("jsbsim:f104", np.arange(0.0, 3001.0, 3000.0), np.array([0.5, 0.75])).to_dict()
    assert c == cli_json("envelope", "jsbsim:f104", "--altitude-m", "0:3000:3000", "--mach", "0.5:0.75:0.25",
                         "--json")
    assert rc.axis([0.3, 0.4, 0.5], "--mach") == "0.3:0.5:0.1"
    for bad in ([0.5, 0.6, 0.8], [0.8, 0.6], []):
        with pytest.raises(rc.InputError) as e:
            rc.envelope("jsbsim:f104", "0", bad)
        assert str(e.value).startswith("--mach [") and ("evenly spaced" in str(e.value) or "no values" in str(e.value))


SPEEDS = ("jsbsim:f104", "0:6000:6000", "150:250:100")


def isa_sound_speed(h):
    """The U.S. Standard Atmosphere 1976's speed of sound below 11 km (its own constants), m/s."""
    z = h * 6356766.0 / (6356766.0 + h)
    return math.sqrt(1.4 * 8.31432 / 0.0289644 * (288.15 - 0.0065 * z))


def test_envelope_over_true_airspeed_equals_the_cli_json_and_its_arrays_the_csv(tmp_path):
    source, h, v = SPEEDS
    env = rc.envelope(source, h, speeds_m_s=v)
    out = tmp_path / "env"
    expected = cli_json("envelope", source, "--altitude-m", h, "--speed", v, "--json", "--out", str(out))
    assert env.to_dict() == expected
    assert env.speed_axis == "speed_m_s"
    assert list(env.altitudes_m) == [0.0, 6000.0]
    assert list(env.speeds) == list(env.speeds_m_s) == [150.0, 250.0]
    with pytest.raises(ValueError):
        env.machs
    mach = env.grid("mach")
    assert mach.shape == (2, 2)
    for i, alt in enumerate(env.altitudes_m):
        for j, speed in enumerate(env.speeds):
            assert abs(mach[i, j] / (speed / isa_sound_speed(alt)) - 1) < 1e-5
    rows = list(csv.DictReader(io.StringIO((out / "envelope.csv").read_text())))
    assert len(rows) == 4
    for r in rows:
        i = list(env.altitudes_m).index(float(r["altitude_m"]))
        j = list(env.speeds).index(float(r["speed_m_s"]))
        assert float(r["mach"]) == mach[i, j]
        for column, grid in (("alpha_deg", env.alpha_deg), ("margin_deg", env.margin_deg)):
            cell = r[column]
            assert (math.isnan(grid[i, j]) and cell == "") or float(cell) == grid[i, j], (column, r)


def test_envelope_clearance_over_true_airspeed_equals_the_cli_json():
    got = rc.envelope_clearance("jsbsim:f104", "3000", speeds_m_s=[200.0], uncertainty="Cl_p=10%").to_dict()
    expected = cli_json("envelope", "jsbsim:f104", "--altitude-m", "3000", "--speed", "200",
                        "--uncertainty", "Cl_p=10%", "--json")
    assert got == expected
    assert got["speed_axis"] == "speed_m_s" and "clearance" in got["points"][0]


def test_envelope_validate_equals_the_cli_json_and_gives_arrays():
    env = rc.envelope("jsbsim:f104", "6000", "0.5:0.7:0.2", load_factor=0, validate=True, validate_sample=1.0)
    expected = cli_json("envelope", "jsbsim:f104", "--altitude-m", "6000", "--mach", "0.5:0.7:0.2",
                        "--load-factor", "0", "--validate", "--validate-sample", "1", "--json")
    assert env.to_dict() == expected
    assert env.validate_sample == 1.0
    assert env.validated.shape == (1, 2)
    for j, p in enumerate(expected["points"]):
        v = p.get("validation")
        assert env.validated[0, j] == (v is not None)
        if v is not None:
            assert env.validation_agrees[0, j] == float(v["agrees"])
            assert env.validation_jumps[0, j] == float(v["jumps"])
    records = env.records()
    assert "validation.agrees" in records[0] or "validation_error" in records[0]


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: rc.envelope("jsbsim:f104", "0"), ["--mach or --speed is required"]),
        (lambda: rc.envelope("jsbsim:f104", "0", 0.5, speeds_m_s=200), ["--mach and --speed: give one"]),
        (lambda: rc.envelope("jsbsim:f104", "0", speeds_m_s="0:200:100"),
         ["--speed: 0 is not a positive true airspeed, m/s"]),
        (lambda: rc.envelope("jsbsim:f104", "0", 0.5, validate_sample=0.5), ["--validate-sample needs --validate"]),
        (lambda: rc.envelope_clearance("jsbsim:f104", "0", uncertainty="10%"), ["--mach or --speed is required"]),
    ],
)
def test_envelope_speed_axis_errors_name_the_options(call, words):
    with pytest.raises(rc.InputError) as e:
        call()
    for w in words:
        assert w in str(e.value)


def test_speed_refusal_is_the_clis_message():
    with pytest.raises(rc.InputError) as e:
        rc.envelope("jsbsim:f104", "0", speeds_m_s="0:200:100")
    done = cli("envelope", "jsbsim:f104", "--altitude-m", "0", "--speed", "0:200:100", check=False)
    assert done.returncode == 2
    assert done.stderr.strip() == f"error: {e.value}"


@pytest.mark.parametrize(
    "call, args",
    [
        (lambda: rc.analyze("nonesuch"), ["analyze", "nonesuch"]),
        (lambda: rc.analyze("A", delta_e_deg=100.0), ["analyze", "A", "--delta-e-deg", "100"]),
        (lambda: rc.simulate("A", delta_a_deg=1.0, t_end=-1.0), ["simulate", "A", "--delta-a-deg", "1", "--t-end", "-1"]),
        (lambda: rc.analyze("name = 1\n"), None),
        (lambda: rc.envelope("jsbsim:f104", "6000:0:1000", "0.5"), ["envelope", "jsbsim:f104", "--altitude-m", "6000:0:1000", "--mach", "0.5"]),
        (lambda: rc.import_jsbsim("nonesuch", 1000, mach=0.5), ["import", "jsbsim", "nonesuch", "--altitude-m", "1000.0", "--mach", "0.5"]),
    ],
)
def test_errors_raise_with_the_clis_message(call, args):
    with pytest.raises(rc.InputError) as e:
        call()
    if args is None:
        assert "<aircraft TOML>" in str(e.value)
        return
    done = cli(*args, check=False)
    assert done.returncode == 2
    assert done.stderr.strip().splitlines()[-1] == f"error: {e.value}".splitlines()[-1]
    assert f"error: {e.value}" in done.stderr
