"""Type stubs of roll_coupling: the commands of `model` as Python functions."""

import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from ._dask import IncompleteEnvelope as IncompleteEnvelope

class InputError(ValueError):
    """Bad input (a file, key or value), with the command line's message."""

class Record:
    def __init__(self, data: Dict[str, Any]) -> None: ...
    def __getattr__(self, name: str) -> Any: ...
    def to_dict(self) -> Dict[str, Any]: ...

class Analysis(Record):
    aircraft: str
    delta_e_rad: float
    trim: Optional[Record]
    warnings: List[str]
    critical: Optional[Record]
    critical_note: Optional[str]
    first_departure: Optional[Record]
    divergence_roll_rates: List[float]
    det_k_poles: List[Record]
    jump: List[Record]
    hopf: List[Record]
    zero_sideslip: Record

class TimeHistory(Record):
    aircraft: str
    model: str
    settings: Record
    start: List[float]
    t: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    p: np.ndarray
    q: np.ndarray
    r: np.ndarray
    phi: np.ndarray
    theta: np.ndarray
    delta_a: np.ndarray
    delta_r: np.ndarray
    stats: Record
    steady: Record
    def records(self) -> List[Dict[str, float]]: ...

class SixDofHistory(Record):
    model: str
    summary: str
    trim: Record
    jsbsim_aileron: float
    thrust_lbs: float
    folder: Optional[Record]
    t: np.ndarray
    alpha: np.ndarray
    beta: np.ndarray
    p: np.ndarray
    q: np.ndarray
    r: np.ndarray
    speed: np.ndarray
    altitude: np.ndarray
    mach: np.ndarray
    phi: np.ndarray
    theta: np.ndarray
    psi: np.ndarray
    def records(self) -> List[Dict[str, float]]: ...

class Folder(Record):
    folder: str
    files: List[str]
    skipped: List[str]

class Validation(Record):
    delta_a_deg: np.ndarray
    seventh_order_p: np.ndarray
    six_dof_p: np.ndarray
    critical_deg: Optional[float]
    limit_deg: Optional[float]
    folder: str
    files: List[str]
    lines: List[str]

class Diagram(Record):
    aircraft: str
    parameter: str
    branches: List[Record]
    special_points: List[Record]

class Clearance(Record):
    monte_carlo: Record

class Envelope(Record):
    source: str
    aircraft: str
    elevator: str
    untrimmed: int
    exact_fallbacks: int
    uncertainty: Optional[str]
    points: List[Record]
    @property
    def altitudes_m(self) -> np.ndarray: ...
    @property
    def machs(self) -> np.ndarray: ...
    def grid(self, path: str) -> np.ndarray: ...
    @property
    def p0(self) -> np.ndarray: ...
    @property
    def delta_a_deg(self) -> np.ndarray: ...
    @property
    def margin_deg(self) -> np.ndarray: ...
    @property
    def alpha_deg(self) -> np.ndarray: ...
    @property
    def trimmed(self) -> np.ndarray: ...
    def records(self) -> List[Dict[str, Any]]: ...

class Aircraft(Record):
    toml: str
    source: Optional[str]
    trim: Optional[Record]
    def __init__(self, toml: str, source: Optional[str] = ..., trim: Optional[Dict[str, Any]] = ...) -> None: ...

AircraftLike = Union[str, os.PathLike[str], Aircraft, Mapping[str, Any]]
Axis = Union[str, float, Sequence[float]]

def analyze(aircraft: AircraftLike, delta_e_deg: Optional[float] = ..., certified: bool = ...) -> Analysis:
    """`model analyze AIRCRAFT --json`."""

def continue_(aircraft: AircraftLike, param: str = ..., min_deg: float = ..., max_deg: float = ...,
              delta_e_deg: Optional[float] = ..., zero_sideslip: bool = ...) -> Diagram:
    """`model continue AIRCRAFT --json`."""

def simulate(aircraft: AircraftLike, delta_a_deg: float, delta_e_deg: Optional[float] = ..., t_end: float = ...,
             zero_sideslip: bool = ..., pss: bool = ..., six_dof: bool = ..., altitude_m: Optional[float] = ...,
             mach: Optional[float] = ..., load_factor: Optional[float] = ..., thrust: str = ...,
             dt: Optional[float] = ..., out: Optional[os.PathLike[str]] = ...) -> Union[TimeHistory, SixDofHistory]:
    """`model simulate AIRCRAFT --delta-a-deg D`; with six_dof=True `--six-dof`, the native 6-DOF
    of a jsbsim: source (a SixDofHistory)."""

def clear(aircraft: AircraftLike, uncertainty: Optional[Mapping[str, Any]] = ..., delta_e_deg: Optional[float] = ...,
          delta_e_range: Optional[str] = ..., samples: int = ..., tolerance: float = ...,
          seed: int = ...) -> Union[Clearance, List[Clearance]]:
    """`model clear AIRCRAFT --json`."""

def import_jsbsim(model: str, altitude_m: float, mach: Optional[float] = ..., speed: Optional[float] = ...,
                  load_factor: Optional[float] = ..., alpha_deg: Optional[float] = ...,
                  settings: Optional[Mapping[str, float]] = ..., jsbsim_root: Optional[str] = ...) -> Aircraft:
    """`model import jsbsim MODEL --altitude-m H --mach M`."""

def axis(values: Axis) -> str: ...

def envelope(source: str, altitudes_m: Axis, machs: Axis, load_factor: Optional[float] = ...,
             delta_e_deg: Optional[float] = ..., uncertainty: Optional[str] = ...) -> Envelope:
    """`model envelope SOURCE --altitude-m H --mach M --json`."""

def envelope_clearance(source: str, altitudes_m: Axis, machs: Axis, uncertainty: Optional[str],
                       load_factor: Optional[float] = ..., delta_e_deg: Optional[float] = ...,
                       client: Any = ..., retries: int = ...) -> Envelope:
    """The envelope with every point's box cleared, locally or one Dask task per point."""

def import_jsbsim_list(analyze: bool = ..., altitude_m: Optional[float] = ..., mach: Optional[float] = ...,
                       speed: Optional[float] = ..., load_factor: Optional[float] = ...,
                       alpha_deg: Optional[float] = ..., settings: Optional[Mapping[str, float]] = ...,
                       jsbsim_root: Optional[str] = ...) -> str:
    """`model import jsbsim --list [--analyze] ...`: the text the command prints."""

def convert(file: Union[str, os.PathLike[str]]) -> str:
    """`model convert FILE`: the dimensional principal-axis TOML."""

def report(aircraft: AircraftLike, out: Optional[os.PathLike[str]] = ...,
           delta_e_deg: Optional[float] = ...) -> Folder:
    """`model report AIRCRAFT [--out DIR]` (default out/report-<aircraft>)."""

def plot(aircraft: AircraftLike, out: Optional[os.PathLike[str]] = ...,
         delta_e_deg: Optional[float] = ...) -> Folder:
    """`model plot AIRCRAFT [--out DIR]` (default out/plot-<aircraft>)."""

def validate(source: str, altitude_m: Optional[float] = ..., mach: Optional[float] = ...,
             load_factor: Optional[float] = ..., delta_a_deg: Optional[Axis] = ..., t_end: float = ...,
             out: Optional[os.PathLike[str]] = ...) -> Validation:
    """`model validate jsbsim:MODEL` (default folder out/validate-<model>)."""
