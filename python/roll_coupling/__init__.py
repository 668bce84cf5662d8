"""The roll-coupling jump criterion (Mahale & Ananthkrishnan, AIAA 2006-6267) from Python.

Every function is a command of ``model`` with the same names and defaults, computed by the same
library (not by parsing its output): ``analyze``, ``continue_``, ``simulate``, ``clear``,
``import_jsbsim``, ``import_jsbsim_list``, ``convert``, ``report``, ``plot``, ``validate``,
``envelope`` and ``envelope_clearance`` (the envelope with each point's
uncertainty box cleared, on the local cores or spread over a Dask cluster). Bad input raises
``InputError`` with the command line's message. Long work releases the GIL; Ctrl-C interrupts
the wait.

>>> from roll_coupling import analyze
>>> analyze("A").critical.p0  # doctest: +SKIP
"""

from __future__ import annotations

import os
from typing import Any, Dict, Mapping, Optional, Sequence, Tuple, Union

from . import _core
from ._core import InputError
from ._dask import IncompleteEnvelope, envelope_clearance
from ._records import (
    Aircraft,
    Analysis,
    Clearance,
    Diagram,
    Envelope,
    Folder,
    Record,
    SixDofHistory,
    TimeHistory,
    Validation,
)
from ._toml import toml_text

__all__ = [
    "InputError",
    "Aircraft",
    "Analysis",
    "Clearance",
    "Diagram",
    "Envelope",
    "Folder",
    "Record",
    "SixDofHistory",
    "TimeHistory",
    "Validation",
    "analyze",
    "continue_",
    "simulate",
    "clear",
    "import_jsbsim",
    "import_jsbsim_list",
    "convert",
    "report",
    "plot",
    "validate",
    "envelope",
    "envelope_clearance",
    "IncompleteEnvelope",
]

AircraftLike = Union[str, "os.PathLike[str]", Aircraft, Mapping[str, Any]]


def _aircraft(aircraft: AircraftLike, uncertainty: Optional[Mapping[str, Any]] = None) -> Tuple[str, bool]:
    """The argument of ``_core``: (a name, path or ``jsbsim:`` source, False) or (TOML text,
    True)."""
    if isinstance(aircraft, Aircraft):
        text = aircraft.toml
    elif isinstance(aircraft, Mapping):
        text = toml_text(aircraft)
    else:
        arg = os.fspath(aircraft)
        is_text = "\n" in arg or ("=" in arg and not arg.startswith("jsbsim:"))
        if uncertainty is None or arg.startswith("jsbsim:") or arg.upper() in ("A", "B"):
            if uncertainty is not None:
                raise InputError(f"{arg}: an uncertainty box needs an aircraft file, TOML text or dict")
            return arg, is_text
        text = arg if is_text else open(arg, encoding="utf-8").read()
    if uncertainty is not None:
        text += "\n" + toml_text({"uncertainty": dict(uncertainty)})
    return text, True


def analyze(aircraft: AircraftLike, delta_e_deg: Optional[float] = None, certified: bool = False) -> Analysis:
    """``model analyze AIRCRAFT --json``: divergence and jump roll rates, det K poles, the
    critical jump, the first departure and the zero-sideslip departure.

    ``aircraft`` is ``"A"``/``"B"`` (the paper's), a file path, a ``"jsbsim:MODEL --altitude-m H
    --mach M"`` source, the text of an aircraft TOML file, a dict of its keys, or an
    :class:`Aircraft` from :func:`import_jsbsim`. ``delta_e_deg``: the elevator, deg (the
    increment from the trim for an imported aircraft, default 0; else from zero lift, default 2).
    The numbers are the exact path's (correctly rounded roots), the certified route's with
    ``certified=True``."""
    arg, toml = _aircraft(aircraft)
    return Analysis(_core.analyze(arg, toml, delta_e_deg, certified))


def continue_(
    aircraft: AircraftLike,
    param: str = "delta_a",
    min_deg: float = -45.8366,
    max_deg: float = 45.8366,
    delta_e_deg: Optional[float] = None,
    zero_sideslip: bool = False,
) -> Diagram:
    """``model continue AIRCRAFT --json``: continuation of the PSS equilibria in ``param``
    (``delta_a``, ``delta_e`` or ``delta_r``) over [min_deg, max_deg]: every branch, the folds,
    Hopf and branch points."""
    arg, toml = _aircraft(aircraft)
    return Diagram(_core.continue_(arg, toml, param, min_deg, max_deg, delta_e_deg, zero_sideslip))


def simulate(
    aircraft: AircraftLike,
    delta_a_deg: float,
    delta_e_deg: Optional[float] = None,
    t_end: float = 20.0,
    zero_sideslip: bool = False,
    pss: bool = False,
    six_dof: bool = False,
    altitude_m: Optional[float] = None,
    mach: Optional[float] = None,
    load_factor: Optional[float] = None,
    thrust: str = "off",
    dt: Optional[float] = None,
    out: Optional["os.PathLike[str]"] = None,
) -> Union[TimeHistory, SixDofHistory]:
    """``model simulate AIRCRAFT --delta-a-deg D``: the time history of an aileron step of
    ``delta_a_deg`` from the trim over ``t_end`` s (7th-order model, the PSS model with
    ``pss=True``; the rudder on the zero-sideslip schedule with ``zero_sideslip=True``). Angles
    in rad, rates in rad/s, as in ``--csv``.

    With ``six_dof=True`` (``--six-dof``) the native nonlinear 6-DOF of a ``"jsbsim:MODEL ..."``
    source from its trim at ``load_factor`` g (default 1) at ``altitude_m`` and ``mach`` (or
    inside the source): a :class:`SixDofHistory`; ``thrust`` ``"off"`` (gliding) or ``"trim"``,
    ``dt`` the step in s (default 1/120), ``out`` a folder for its figure (SVG, PNG, CSV)."""
    if six_dof:
        arg = aircraft if isinstance(aircraft, str) else _aircraft(aircraft)[0]
        return SixDofHistory(_core.simulate_six_dof(
            arg, delta_a_deg, t_end, altitude_m, mach, load_factor, thrust, dt,
            None if out is None else os.fspath(out), delta_e_deg, zero_sideslip, pss))
    given = {"altitude_m": altitude_m, "mach": mach, "load_factor": load_factor, "dt": dt, "out": out}
    for name, value in list(given.items()) + [("thrust", None if thrust == "off" else thrust)]:
        if value is not None:
            flag = "--" + name.replace("_", "-")
            raise InputError(f"{flag}: an option of the 6-DOF (expected six_dof=True, as --six-dof)")
    arg, toml = _aircraft(aircraft)
    return TimeHistory(_core.simulate(arg, delta_a_deg, toml, delta_e_deg, t_end, zero_sideslip, pss))


def clear(
    aircraft: AircraftLike,
    uncertainty: Optional[Mapping[str, Any]] = None,
    delta_e_deg: Optional[float] = None,
    delta_e_range: Optional[str] = None,
    samples: int = 1000,
    tolerance: float = 1e-3,
    seed: int = 1,
) -> Union[Clearance, list]:
    """``model clear AIRCRAFT --json``: the certified clearance of the critical jump over the
    aircraft's ``[uncertainty]`` box, with a Monte Carlo comparison. ``uncertainty``: the
    ``[uncertainty]`` table as a dict (``{"l_p": "5%", "n_beta": 0.2, "l_beta": [-116, -105]}``),
    added to the aircraft's file; without it the file's own table. With ``delta_e_range``
    (``"A:B:STEP"`` in deg) a list, one clearance per elevator setting."""
    arg, toml = _aircraft(aircraft, uncertainty)
    runs = _core.clear(arg, toml, delta_e_deg, delta_e_range, samples, tolerance, seed)
    return [Clearance(r) for r in runs] if isinstance(runs, list) else Clearance(runs)


def _number(x: float) -> str:
    """``x`` as the command line reads it back bit for bit."""
    return repr(float(x))


def import_jsbsim(
    model: str,
    altitude_m: float,
    mach: Optional[float] = None,
    speed: Optional[float] = None,
    load_factor: Optional[float] = None,
    alpha_deg: Optional[float] = None,
    settings: Optional[Mapping[str, float]] = None,
    jsbsim_root: Optional[str] = None,
) -> Aircraft:
    """``model import jsbsim MODEL --altitude-m H --mach M``: the aircraft file of a JSBSim model
    linearised at its trim at ``load_factor`` g (default 1, level flight), or at ``alpha_deg``
    (not a trim). Give ``mach`` or ``speed`` (true airspeed, m/s). ``settings``: JSBSim
    properties set before the import (``{"fcs/flap-pos-norm": 0.5}``)."""
    spec = f"jsbsim:{model} --altitude-m {_number(altitude_m)}"
    if mach is not None:
        spec += f" --mach {_number(mach)}"
    if speed is not None:
        spec += f" --speed {_number(speed)}"
    if load_factor is not None:
        spec += f" --load-factor {_number(load_factor)}"
    if alpha_deg is not None:
        spec += f" --alpha-deg {_number(alpha_deg)}"
    for k, v in (settings or {}).items():
        spec += f" --set {k}={_number(v)}"
    if jsbsim_root is not None:
        spec += f" --jsbsim-root {os.fspath(jsbsim_root)}"
    text, trim = _core.import_jsbsim(spec)
    return Aircraft(text, spec, trim)


Axis = Union[str, float, Sequence[float]]


def axis(values: Axis) -> str:
    """An envelope's axis as the command line takes it: ``"START:STOP:STEP"``, one value, or a
    (start, stop, step) triple."""
    if isinstance(values, str):
        return values
    if isinstance(values, (int, float)):
        return _number(values)
    parts = list(values)
    if len(parts) != 3:
        raise InputError(f"{parts!r}: expected START:STOP:STEP, (start, stop, step) or one value")
    return ":".join(_number(v) for v in parts)


def envelope(
    source: str,
    altitudes_m: Axis,
    machs: Axis,
    load_factor: Optional[float] = None,
    delta_e_deg: Optional[float] = None,
    uncertainty: Optional[str] = None,
) -> Envelope:
    """``model envelope SOURCE --altitude-m H --mach M --json`` on the local cores: the
    analysis at every altitude (m) and Mach of the grid, each point linearised at its own trim
    at ``load_factor`` g (default 1). ``source``: ``"jsbsim:MODEL [--set P=V]..."``. With
    ``uncertainty`` (``"10%"``, ``"Cl_p=10%,Cn_r=0.02"`` or a TOML file) every point is also the
    certified clearance of its box. The result's arrays are over altitude x Mach."""
    return Envelope(_core.envelope(source, axis(altitudes_m), axis(machs), load_factor, delta_e_deg, uncertainty))


def import_jsbsim_list(
    analyze: bool = False,
    altitude_m: Optional[float] = None,
    mach: Optional[float] = None,
    speed: Optional[float] = None,
    load_factor: Optional[float] = None,
    alpha_deg: Optional[float] = None,
    settings: Optional[Mapping[str, float]] = None,
    jsbsim_root: Optional[str] = None,
) -> str:
    """``model import jsbsim --list``: JSBSim's catalogue, every model and whether it imports
    (read and evaluated at a reference condition). With ``analyze=True`` (``--list --analyze``)
    the Markdown table of every model imported at ``altitude_m`` and ``mach`` (or ``speed``),
    linearised at its trim at ``load_factor`` g (default 1) and analysed: its critical jump and
    first departure. The text the command prints."""
    args = ["--list"] + (["--analyze"] if analyze else [])
    for flag, value in (("--altitude-m", altitude_m), ("--mach", mach), ("--speed", speed),
                        ("--load-factor", load_factor), ("--alpha-deg", alpha_deg)):
        if value is not None:
            args += [flag, str(value) if isinstance(value, int) else _number(value)]
    for k, v in (settings or {}).items():
        args += ["--set", f"{k}={_number(v)}"]
    if jsbsim_root is not None:
        args += ["--jsbsim-root", os.fspath(jsbsim_root)]
    return _core.import_jsbsim_list(args)


def convert(file: "Union[str, os.PathLike[str]]") -> str:
    """``model convert FILE``: the dimensional principal-axis aircraft TOML of a nondimensional
    body-axis file (its text, as the command prints it)."""
    return _core.convert(os.fspath(file))


def _out(out: Optional["os.PathLike[str]"]) -> Optional[str]:
    return None if out is None else os.fspath(out)


def report(aircraft: AircraftLike, out: Optional["os.PathLike[str]"] = None,
           delta_e_deg: Optional[float] = None) -> Folder:
    """``model report AIRCRAFT [--out DIR]``: the figures, tables, summary.md and summary.json
    written into ``out`` (default ``out/report-<aircraft>`` under the working directory,
    ``<aircraft>`` the letter, the file's stem, the JSBSim model or a TOML text's name), the
    folder replaced whole or not at all. Returns the folder, its files (relative paths) and the
    sections skipped with their reasons; a file that cannot be written raises ``OSError``."""
    arg, toml = _aircraft(aircraft)
    return Folder(_core.report(arg, toml, _out(out), delta_e_deg))


def plot(aircraft: AircraftLike, out: Optional["os.PathLike[str]"] = None,
         delta_e_deg: Optional[float] = None) -> Folder:
    """``model plot AIRCRAFT [--out DIR]``: the report's figures alone (default folder
    ``out/plot-<aircraft>``), as :func:`report`."""
    arg, toml = _aircraft(aircraft)
    return Folder(_core.plot(arg, toml, _out(out), delta_e_deg))


def validate(
    source: str,
    altitude_m: Optional[float] = None,
    mach: Optional[float] = None,
    load_factor: Optional[float] = None,
    delta_a_deg: Optional[Axis] = None,
    t_end: float = 10.0,
    out: Optional["os.PathLike[str]"] = None,
) -> Validation:
    """``model validate jsbsim:MODEL``: aileron steps ``delta_a_deg`` (``"A:B:STEP"`` or a
    triple, deg of |delta_a|; default 1 to the aileron limit + 4, every 1) of ``t_end`` s in the
    7th-order model and in the native 6-DOF from the same trim at ``load_factor`` g (default 1),
    at ``altitude_m`` and ``mach`` (or inside the source). Returns each model's settled |p|
    (mean over the last 2 s, rad/s) at each step, the criterion's critical aileron, the lines
    the command prints (a verdict per model) and the folder of the plateau figure (default
    ``out/validate-<model>``)."""
    steps = None if delta_a_deg is None else axis(delta_a_deg)
    return Validation(_core.validate(source, altitude_m, mach, load_factor, steps, t_end, _out(out)))
