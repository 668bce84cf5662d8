"""Typed views of the toolkit's results: each wraps the dict of the command's JSON (``to_dict()``
gives it back unchanged), exposes its fields as attributes, and its series and grids as numpy
arrays."""

from __future__ import annotations

from typing import Any, Dict, List, Optional

import numpy as np


def _view(value: Any) -> Any:
    """A dict as a Record, a list element by element, anything else as it is."""
    if isinstance(value, dict):
        return Record(value)
    if isinstance(value, list):
        return [_view(v) for v in value]
    return value


class Record:
    """A result: the fields of the command's JSON as attributes (nested objects as Records)."""

    def __init__(self, data: Dict[str, Any]):
        self._data = data

    def __getattr__(self, name: str) -> Any:
        data = self.__dict__.get("_data", {})
        if name in data:
            return _view(data[name])
        raise AttributeError(f"{type(self).__name__} has no field {name!r}; fields: {sorted(data)}")

    def __dir__(self) -> List[str]:
        return sorted(set(super().__dir__()) | set(self._data))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Record) and self._data == other._data

    def __repr__(self) -> str:
        fields = ", ".join(f"{k}={v!r}" for k, v in self._data.items() if not isinstance(v, (dict, list)))
        return f"{type(self).__name__}({fields})"

    def to_dict(self) -> Dict[str, Any]:
        """The command's JSON as Python objects (a fresh copy)."""
        import copy

        return copy.deepcopy(self._data)


class Analysis(Record):
    """``model analyze --json``: divergence and jump roll rates, det K poles, the critical jump,
    the first departure and the zero-sideslip departure of one aircraft at one elevator."""

    def __repr__(self) -> str:
        c = self._data.get("critical")
        jump = (
            f"critical jump P0 = {c['p0']:.6f} rad/s at delta_a = {c['delta_a_deg']:.4f} deg"
            if c
            else f"no critical jump ({self._data.get('critical_note')})"
        )
        de = np.degrees(self._data["delta_e_rad"])
        return f"Analysis({self._data['aircraft']}, delta_e = {de:.4f} deg: {jump})"


class TimeHistory(Record):
    """``model simulate``: the time history of an aileron step from the trim, every series a
    numpy array (the columns of ``--csv``), with the steady values the command prints."""

    SERIES = ("t", "alpha", "beta", "p", "q", "r", "phi", "theta", "delta_a", "delta_r")

    def __getattr__(self, name: str) -> Any:
        if name in TimeHistory.SERIES:
            return np.asarray(self._data[name], dtype=float)
        return super().__getattr__(name)

    def records(self) -> List[Dict[str, float]]:
        """One dict per sample (for ``pandas.DataFrame``), the series that were integrated."""
        names = [s for s in TimeHistory.SERIES if len(self._data[s]) > 0]
        return [dict(zip(names, row)) for row in zip(*(self._data[s] for s in names))]


class SixDofHistory(Record):
    """``model simulate --six-dof``: the native 6-DOF's time history, every series a numpy array
    (the columns of its ``--csv``: SI units and rad), the trim it started from and the summary
    line the command prints."""

    SERIES = ("t", "alpha", "beta", "p", "q", "r", "speed", "altitude", "mach", "phi", "theta", "psi")

    def __getattr__(self, name: str) -> Any:
        if name in SixDofHistory.SERIES:
            return np.asarray(self._data[name], dtype=float)
        return super().__getattr__(name)

    def records(self) -> List[Dict[str, float]]:
        """One dict per sample (for ``pandas.DataFrame``)."""
        return [dict(zip(SixDofHistory.SERIES, row)) for row in zip(*(self._data[s] for s in SixDofHistory.SERIES))]


class Folder(Record):
    """What ``model report`` or ``model plot`` wrote: ``folder``, its ``files`` (paths relative
    to it) and the sections ``skipped`` with their reasons."""


class Validation(Record):
    """``model validate``: the aileron steps (``delta_a_deg``), each model's settled |p| at each
    (``seventh_order_p``, ``six_dof_p``, rad/s, numpy arrays), ``critical_deg``, ``limit_deg``,
    the printed ``lines``, the ``folder`` of the plateau figure and its ``files``."""

    SERIES = ("delta_a_deg", "seventh_order_p", "six_dof_p")

    def __getattr__(self, name: str) -> Any:
        if name in Validation.SERIES:
            return np.asarray(self._data[name], dtype=float)
        return super().__getattr__(name)


class Diagram(Record):
    """``model continue --json``: the branches of the PSS equilibria and their special points."""


class Clearance(Record):
    """``model clear --json``: the certified bounds and worst cases over the uncertainty box,
    with the Monte Carlo comparison."""


class Envelope(Record):
    """``model envelope --json``: every grid point, and arrays over altitude x Mach (rows by
    altitude, columns by Mach, ready for ``pcolormesh(machs, altitudes_m, grid)``)."""

    @property
    def altitudes_m(self) -> np.ndarray:
        """The grid's altitudes, m, ascending."""
        return np.array(sorted({p["altitude_m"] for p in self._data["points"]}))

    @property
    def machs(self) -> np.ndarray:
        """The grid's Mach numbers, ascending."""
        return np.array(sorted({p["mach"] for p in self._data["points"]}))

    def grid(self, path: str) -> np.ndarray:
        """The field ``path`` of every point (dotted for nested ones: ``"critical.p0"``,
        ``"clearance.p0_lower"``) as a float array over altitude x Mach; NaN where a point has
        none (untrimmable, no critical jump)."""
        h, m = self.altitudes_m, self.machs
        out = np.full((len(h), len(m)), np.nan)
        row = {v: i for i, v in enumerate(h)}
        col = {v: j for j, v in enumerate(m)}
        for p in self._data["points"]:
            v: Any = p
            for key in path.split("."):
                v = v.get(key) if isinstance(v, dict) else None
            if isinstance(v, bool):
                v = float(v)
            if isinstance(v, (int, float)):
                out[row[p["altitude_m"]], col[p["mach"]]] = v
        return out

    @property
    def p0(self) -> np.ndarray:
        """Roll rate of the critical jump, rad/s, over altitude x Mach."""
        return self.grid("critical.p0")

    @property
    def delta_a_deg(self) -> np.ndarray:
        """Aileron of the critical jump, deg, over altitude x Mach."""
        return self.grid("critical.delta_a_deg")

    @property
    def margin_deg(self) -> np.ndarray:
        """Aileron limit minus |critical aileron|, deg, over altitude x Mach."""
        return self.grid("margin_deg")

    @property
    def alpha_deg(self) -> np.ndarray:
        """The trim's angle of attack, deg, over altitude x Mach."""
        return self.grid("alpha_deg")

    @property
    def trimmed(self) -> np.ndarray:
        """Whether each point has a trim, over altitude x Mach."""
        return self.grid("trimmed") == 1.0

    def records(self) -> List[Dict[str, Any]]:
        """One flat dict per point (nested fields joined with ``.``), for ``pandas.DataFrame``."""

        def flat(d: Dict[str, Any], prefix: str = "") -> Dict[str, Any]:
            out: Dict[str, Any] = {}
            for k, v in d.items():
                if isinstance(v, dict):
                    out.update(flat(v, f"{prefix}{k}."))
                else:
                    out[f"{prefix}{k}"] = v
            return out

        return [flat(p) for p in self._data["points"]]


class Aircraft(Record):
    """An aircraft file's text (``toml``) and where it came from: what ``import_jsbsim``
    writes, usable wherever an aircraft is expected."""

    def __init__(self, toml: str, source: Optional[str] = None, trim: Optional[Dict[str, Any]] = None):
        super().__init__({"toml": toml, "source": source, "trim": trim})

    def __repr__(self) -> str:
        return f"Aircraft(source={self._data['source']!r}, trim={self._data['trim']!r})"
