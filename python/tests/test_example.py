"""The notebook-style example of docs/ runs and draws its figure."""

import subprocess
import sys

from conftest import ROOT


def test_the_f104_example_runs_and_plots(tmp_path):
    pytest = __import__("pytest")
    pytest.importorskip("matplotlib")
    out = tmp_path / "f104.png"
    done = subprocess.run([sys.executable, str(ROOT / "docs/python_f104_envelope.py"), str(out),
                           "0:12000:6000", "0.3:0.9:0.3"],
                          capture_output=True, text=True, cwd=tmp_path, timeout=600)
    assert done.returncode == 0, done.stderr
    assert "critical jump" in done.stdout
    assert out.stat().st_size > 10_000
