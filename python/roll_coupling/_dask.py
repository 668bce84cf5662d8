"""``envelope_clearance``: an envelope whose every point is the certified clearance of its
uncertainty box, on the local cores or spread over a Dask cluster, one task per grid point.

Dask schedules, retries and moves the work; this module only plans the grid (every option
checked before any task starts, as the command checks it), submits one task per point and puts
the answers back in the command's order. A task that still fails after its retries is reported
by :class:`IncompleteEnvelope`, never dropped."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Tuple

from . import _core
from ._records import Envelope


class IncompleteEnvelope(RuntimeError):
    """Some points failed on the cluster after every retry. ``failed`` lists them as
    ``(altitude_m, mach, error)``; ``envelope`` holds the points that were computed, the
    failed ones with their ``error`` field set, so that none is silently missing."""

    def __init__(self, failed: List[Tuple[float, float, str]], envelope: Envelope):
        self.failed = failed
        self.envelope = envelope
        where = "; ".join(f"{h} m, Mach {m}: {e}" for h, m, e in failed[:5])
        super().__init__(f"{len(failed)} of {len(envelope.points)} points failed after their retries: {where}")


def point(altitude_m: float, mach: float, source: str, load_factor: float, increment_rad: float,
          uncertainty: Optional[str]) -> Dict[str, Any]:
    """One grid point, as the envelope's JSON holds it (the task each worker runs; the worker
    reads the model on its first point and keeps it)."""
    return _core.envelope_point(source, altitude_m, mach, load_factor, increment_rad, uncertainty)


def assembled(source: str, aircraft: str, elevator: str, uncertainty: Optional[str],
              points: List[Dict[str, Any]]) -> Envelope:
    """The envelope's JSON around its points, as ``model envelope`` writes it."""
    data: Dict[str, Any] = {
        "source": source,
        "aircraft": aircraft,
        "elevator": elevator,
        "untrimmed": sum(1 for p in points if not p["trimmed"]),
        "exact_fallbacks": sum(1 for p in points if p["route"] == "exact"),
    }
    if uncertainty is not None:
        data["uncertainty"] = uncertainty
    data["points"] = points
    return Envelope(data)


def envelope_clearance(
    source: str,
    altitudes_m: Any,
    machs: Any,
    uncertainty: Optional[str],
    load_factor: Optional[float] = None,
    delta_e_deg: Optional[float] = None,
    client: Any = None,
    retries: int = 2,
) -> Envelope:
    """``model envelope SOURCE ... --uncertainty SPEC --json``: every grid point's nominal
    analysis and the certified clearance of its box (``uncertainty`` as the command takes it:
    ``"10%"``, ``"Cl_p=10%,Cn_r=0.02"`` or a TOML file with an ``[uncertainty]`` table, which
    every worker must be able to read; ``None`` for the nominal envelope alone).

    Without ``client``, on the local cores (as :func:`roll_coupling.envelope`). With a
    ``distributed.Client``, each grid point is a task on the cluster's workers, retried up to
    ``retries`` times when it fails (a task on a worker that dies is rescheduled by Dask
    itself); the answers are gathered into the same arrays, bit for bit the local run's. Points
    that still fail raise :class:`IncompleteEnvelope`, which names them."""
    from . import axis

    h_axis, m_axis = axis(altitudes_m), axis(machs)
    if client is None:
        return Envelope(_core.envelope(source, h_axis, m_axis, load_factor, delta_e_deg, uncertainty))
    plan = _core.envelope_plan(source, h_axis, m_axis, load_factor, delta_e_deg, uncertainty)
    hs = [h for h, _ in plan["points"]]
    ms = [m for _, m in plan["points"]]
    futures = client.map(
        point, hs, ms,
        source=source,
        load_factor=plan["load_factor"],
        increment_rad=plan["increment_rad"],
        uncertainty=uncertainty,
        retries=retries,
        pure=False,
    )
    points: List[Dict[str, Any]] = []
    failed: List[Tuple[float, float, str]] = []
    for h, m, f in zip(hs, ms, futures):
        try:
            points.append(f.result())
        except Exception as e:  # a task that failed on every try: reported, never dropped
            failed.append((h, m, f"{type(e).__name__}: {e}"))
            points.append({"altitude_m": h, "mach": m, "trimmed": False, "route": None,
                           "error": f"task failed after {retries} retries: {type(e).__name__}: {e}"})
    env = assembled(source, plan["aircraft"], plan["elevator"], uncertainty, points)
    if failed:
        raise IncompleteEnvelope(failed, env)
    return env
