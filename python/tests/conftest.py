"""The command line the Python package is checked against: the workspace's `model` binary
(``$ROLL_COUPLING_MODEL``, else target/debug/model, else target/release/model)."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def model_binary() -> Path:
    given = os.environ.get("ROLL_COUPLING_MODEL")
    candidates = [Path(given)] if given else [ROOT / "target/debug/model", ROOT / "target/release/model"]
    for c in candidates:
        if c.is_file():
            return c
    pytest.fail(f"no model binary at {candidates}: build it with `cargo build -p model`")


def cli(*args: str, check: bool = True) -> subprocess.CompletedProcess:
    """`model ARGS...` run in the workspace root."""
    done = subprocess.run([str(model_binary()), *args], cwd=ROOT, capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"model {' '.join(args)} failed: {done.stderr}")
    return done


def cli_json(*args: str):
    return json.loads(cli(*args).stdout)


@pytest.fixture(autouse=True)
def in_root(monkeypatch):
    """Relative paths (aircraft/c.toml) mean the same to the package as to the command line."""
    monkeypatch.chdir(ROOT)
