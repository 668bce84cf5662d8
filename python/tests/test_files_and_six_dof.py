"""The commands that write folders (`report`, `plot`, `validate`), the 6-DOF `simulate
--six-dof`, `convert` and the catalogue (`import jsbsim --list [--analyze]`) against the command
line for the same input: the same files byte for byte, the same printed text, the same CSV
numbers bit for bit, the same error messages."""

import csv
import io
import os

import numpy as np
import pytest

import roll_coupling as rc
from conftest import ROOT, cli

F104 = "jsbsim:f104 --altitude-m 6096 --mach 0.53"


def message(*args: str) -> str:
    """The command's message for bad input: its stderr after `error: `, exit 2."""
    done = cli(*args, check=False)
    assert done.returncode == 2, done.stderr
    return done.stderr.split("error: ", 1)[1].strip()


def same_folders(a, b):
    files = sorted(os.path.relpath(os.path.join(d, f), a) for d, _, fs in os.walk(a) for f in fs)
    assert files == sorted(os.path.relpath(os.path.join(d, f), b) for d, _, fs in os.walk(b) for f in fs)
    for f in files:
        assert (a / f).read_bytes() == (b / f).read_bytes(), f
    return [f for f in files if f != ".model-output"]


def test_report_writes_the_clis_folder(tmp_path):
    got = rc.report("aircraft/c.toml", out=tmp_path / "py")
    cli("report", "aircraft/c.toml", "--out", str(tmp_path / "cli"))
    files = same_folders(tmp_path / "py", tmp_path / "cli")
    assert got.folder == str(tmp_path / "py") and got.files == files
    assert "summary.json" in files and "summary.md" in files


def test_plot_writes_the_clis_folder_and_defaults_to_out_plot_aircraft(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    got = rc.plot("A", delta_e_deg=3.0)
    assert got.folder == os.path.join("out", "plot-a")
    done = cli("plot", "A", "--delta-e-deg", "3", "--out", str(tmp_path / "cli"))
    assert got.files == same_folders(tmp_path / "out/plot-a", tmp_path / "cli")
    assert not any(f.startswith("summary") for f in got.files)
    assert [f"skipped: {s}" for s in got.skipped] == [l for l in done.stdout.splitlines() if l.startswith("skipped")]


def test_report_refuses_a_bad_elevator_with_the_clis_message(tmp_path):
    with pytest.raises(rc.InputError) as e:
        rc.report("A", out=tmp_path / "x", delta_e_deg=100)
    assert str(e.value) == message("report", "A", "--delta-e-deg", "100", "--out", str(tmp_path / "y"))


def test_six_dof_series_equal_the_clis_csv_and_its_summary_line(tmp_path):
    h = rc.simulate(F104, -4.0, six_dof=True, t_end=3.0, thrust="trim", out=tmp_path / "py")
    out = tmp_path / "h.csv"
    line = cli("simulate", F104, "--six-dof", "--delta-a-deg", "-4", "--t-end", "3",
               "--thrust", "trim", "--csv", str(out), "--out", str(tmp_path / "cli")).stdout
    rows = list(csv.reader(io.StringIO(out.read_text())))
    table = np.array([[float(x) for x in r] for r in rows[1:]])
    names = ["t", "alpha", "beta", "p", "q", "r", "speed", "altitude", "mach", "phi", "theta", "psi"]
    assert len(rows[0]) == len(names) + 1
    for k, name in enumerate(names):
        assert np.array_equal(getattr(h, name), table[:, k]), name
    assert np.all(table[:, -1] == h.jsbsim_aileron)
    assert h.summary == line.strip()
    assert h.folder.files == same_folders(tmp_path / "py", tmp_path / "cli")


def test_six_dof_takes_the_condition_as_options_and_refuses_as_the_cli():
    a = rc.simulate("jsbsim:f104", -4.0, six_dof=True, t_end=1.0, altitude_m=6096, mach=0.53)
    b = rc.simulate(F104, -4.0, six_dof=True, t_end=1.0)
    assert np.array_equal(a.p, b.p) and a.trim.alpha_deg == b.trim.alpha_deg
    with pytest.raises(rc.InputError) as e:
        rc.simulate("A", -4.0, six_dof=True)
    assert str(e.value) == message("simulate", "A", "--six-dof", "--delta-a-deg", "-4")
    with pytest.raises(rc.InputError) as e:
        rc.simulate(F104, -4.0, six_dof=True, pss=True)
    assert str(e.value) == message("simulate", F104, "--six-dof", "--pss", "--delta-a-deg", "-4")
    with pytest.raises(rc.InputError, match="--altitude-m"):
        rc.simulate("A", -4.0, altitude_m=6096)


def test_validate_prints_and_writes_what_the_cli_does(tmp_path):
    v = rc.validate("jsbsim:f104", altitude_m=6096, mach=0.53, delta_a_deg=(2, 6, 2), t_end=4.0,
                    out=tmp_path / "py")
    printed = cli("validate", "jsbsim:f104", "--altitude-m", "6096", "--mach", "0.53",
                  "--delta-a-deg", "2:6:2", "--t-end", "4", "--out", str(tmp_path / "cli")).stdout
    assert v.lines == printed.splitlines()
    assert v.files == same_folders(tmp_path / "py", tmp_path / "cli")
    assert np.array_equal(v.delta_a_deg, [2.0, 4.0, 6.0])
    rows = list(csv.DictReader(io.StringIO((tmp_path / "cli/plateau.csv").read_text())))
    # The figure's CSV holds both models' settled |p| against |delta_a|, as the result does.
    for label, p in (("7th-order model", v.seventh_order_p), ("6-DOF", v.six_dof_p)):
        line = [(float(r["x"]), float(r["y"])) for r in rows if r["label"] == label]
        assert line == list(zip(v.delta_a_deg, p)), label
    with pytest.raises(rc.InputError) as e:
        rc.validate("jsbsim:f104", altitude_m=6096, mach=0.53, t_end=1.0)
    assert str(e.value) == message("validate", "jsbsim:f104", "--altitude-m", "6096", "--mach", "0.53", "--t-end", "1")


def test_convert_prints_the_clis_file_and_refuses_a_dimensional_one():
    assert rc.convert("aircraft/fighter.toml") == cli("convert", "aircraft/fighter.toml").stdout
    with pytest.raises(rc.InputError) as e:
        rc.convert(ROOT / "aircraft/a.toml")
    assert str(e.value) == message("convert", str(ROOT / "aircraft/a.toml"))


@pytest.fixture(scope="module")
def small_root(tmp_path_factory):
    """A JSBSim root of two catalogue models (one imports, one is refused), so that the
    catalogue's table takes seconds."""
    jsbsim = pytest.importorskip("jsbsim")
    real = jsbsim.get_default_root_dir()
    root = tmp_path_factory.mktemp("jsbsim")
    (root / "aircraft").mkdir()
    for name in ("f104", "ZLT-NT"):
        os.symlink(os.path.join(real, "aircraft", name), root / "aircraft" / name)
    for d in ("engine", "systems"):
        if os.path.isdir(os.path.join(real, d)):
            os.symlink(os.path.join(real, d), root / d)
    return str(root)


def test_the_catalogue_equals_the_clis_listing(small_root):
    assert rc.import_jsbsim_list(jsbsim_root=small_root) == \
        cli("import", "jsbsim", "--list", "--jsbsim-root", small_root).stdout
    got = rc.import_jsbsim_list(analyze=True, altitude_m=6096, mach=0.53, jsbsim_root=small_root)
    assert got == cli("import", "jsbsim", "--list", "--analyze", "--altitude-m", "6096", "--mach", "0.53",
                      "--jsbsim-root", small_root).stdout
    assert got.startswith("2 models of") and "| f104 | yes |" in got and "| ZLT-NT | no:" in got
    with pytest.raises(rc.InputError) as e:
        rc.import_jsbsim_list(analyze=True)
    assert str(e.value) == message("import", "jsbsim", "--list", "--analyze")
