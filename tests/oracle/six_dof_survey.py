#!/usr/bin/env python3
"""A survey with jsbsim_six_dof.py: aileron sweeps from the n-g trim at seeded envelope points,
and JSBSim's integrator convergence (the same run at dt, dt/2 and dt/4). Prints Markdown tables
on stdout and writes every sweep as JSON to the file given by --json.

Points: altitude uniform in [0, 12000] m (to 100 m) and Mach uniform in [0.4, 0.9] (to 0.01)
from random.Random(seed); points where the F-104 has no 1-g trim are listed and replaced by the
next draw until `--points` trimmed points are found.
"""
import argparse
import json
import math
import os
import random
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jsbsim_six_dof as six  # noqa: E402

SHOWN = (5, 10, 15, 20, 25, 30, 35, 40)


def options(model, alt, mach, n, thrust, **kw):
    base = dict(model=model, root=None, altitude_m=alt, mach=mach, load_factor=n,
                thrust=thrust, aileron_deg=0.0, time=10.0, dt=None, sweep=None,
                record_every=1, elevator_travel_deg=None)
    base.update(kw)
    return SimpleNamespace(**base)


def draw(rng):
    return round(rng.uniform(0.0, 12000.0), -2), round(rng.uniform(0.4, 0.9), 2)


def points(model, count, seed, refused, travel):
    rng = random.Random(seed)
    found = []
    while len(found) < count:
        alt, mach = draw(rng)
        try:
            six.run(options(model, alt, mach, 1.0, "off", time=0.0,
                            elevator_travel_deg=travel))
            found.append((alt, mach))
        except six.Untrimmable as e:
            refused.append((model, alt, mach, str(e)))
    return found


def sweep_row(model, alt, mach, n, thrust, spec, travel):
    try:
        out = six.run(options(model, alt, mach, n, thrust, sweep=spec,
                              elevator_travel_deg=travel))
    except six.Untrimmable as e:
        return {"model": model, "alt": alt, "mach": mach, "n": n, "thrust": thrust,
                "refused": str(e)}
    out.update({"alt": alt, "mach": mach, "n": n, "thrust": thrust})
    return out


def p_at(row, deg):
    for s in row["sweep"]:
        if abs(s["aileron_deg"] - deg) < 1e-9:
            return s
    return None


def table(rows):
    head = ("| model | h (m) | Mach | n | thrust | alpha (deg) | elevator (deg) | max resid. | "
            + " | ".join("p@%d" % d for d in SHOWN)
            + " | unsettled at (deg) | steepest rise (deg) | slope / median | jump |")
    print(head)
    print("|" + "---|" * (head.count("|") - 1))
    for r in rows:
        lead = "| %s | %.0f | %.2f | %g | %s |" % (r["model"], r["alt"], r["mach"], r["n"],
                                                  r["thrust"])
        if "refused" in r:
            print(lead + " refused: %s |" % r["refused"])
            continue
        t = r["trim"]
        resid = max(abs(v) for v in t["residuals"].values())
        ps = []
        for d in SHOWN:
            s = p_at(r, d)
            ps.append("%.2f%s" % (s["p_mean_last2s"], "" if s["settled"] else "*") if s else "")
        unsettled = [s["aileron_deg"] for s in r["sweep"] if not s["settled"]]
        j = r["jump"]
        print(lead + " %.2f | %.2f | %.0e | %s | %s | %g-%g | %.2f / %.3f | %s |" % (
            t["alpha_deg"], t["elevator_deg"], resid, " | ".join(ps),
            compress(unsettled) or "none", j["between_deg"][0], j["between_deg"][1],
            j["slope_rad_s_per_deg"], j["median_slope_rad_s_per_deg"],
            "**yes**" if j["jump"] else "no"))


def compress(values):
    """1,2,3,5 -> '1-3, 5'."""
    out, run = [], []
    for v in values:
        if run and abs(v - run[-1] - 1.0) > 1e-9:
            out.append(run)
            run = []
        run.append(v)
    if run:
        out.append(run)
    return ", ".join("%g" % r[0] if len(r) == 1 else "%g-%g" % (r[0], r[-1]) for r in out)


def convergence(model, alt, mach, n, aileron, travel):
    """max |p(dt) - p(dt/2)| and max |p(dt/2) - p(dt/4)| over 10 s at common times; the first
    also from 2 s on, and the difference of the settled roll rates (mean of the last 2 s)."""
    p, t, settled = [], None, []
    for k in (1, 2, 4):
        out = six.run(options(model, alt, mach, n, "off", aileron_deg=aileron,
                              dt=six.DT_DEFAULT / k, record_every=k,
                              elevator_travel_deg=travel))
        p.append(out["history"]["p"])
        t = out["history"]["t"]
        settled.append(out["settled"]["p_mean_last2s"])
    d1 = max(abs(a - b) for a, b in zip(p[0], p[1]))
    d2 = max(abs(a - b) for a, b in zip(p[1], p[2]))
    late = max(abs(a - b) for a, b, s in zip(p[0], p[1], t) if s >= 2.0 - 1e-9)
    pmax = max(abs(v) for v in p[0])
    return pmax, d1, d2, late, abs(settled[0] - settled[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=43)
    ap.add_argument("--points", type=int, default=8)
    ap.add_argument("--other", default="f15:2,f16:2", help="model:count,... of other jets")
    ap.add_argument("--sweep", default="1:40:1")
    ap.add_argument("--json", help="file for every sweep")
    args = ap.parse_args()
    # JSBSim's messages go to Python's sys.stdout: standard error while JSBSim runs.
    tables_out, sys.stdout = sys.stdout, sys.stderr
    travel = {"f16": "-25:25"}
    refused = []
    plan = [("f104", args.points)] + [(m, int(c)) for m, c in
                                     (x.split(":") for x in args.other.split(",") if x)]
    rows, conv = [], []
    for model, count in plan:
        for alt, mach in points(model, count, args.seed, refused, travel.get(model)):
            for n in (1.0, 0.0):
                for thrust in ("off", "trim"):
                    rows.append(sweep_row(model, alt, mach, n, thrust, args.sweep,
                                          travel.get(model)))
            if model == "f104":
                for n, aileron in ((1.0, 10.0), (1.0, 30.0), (0.0, 10.0), (0.0, 30.0)):
                    try:
                        conv.append((model, alt, mach, n, aileron)
                                    + convergence(model, alt, mach, n, aileron,
                                                  travel.get(model)))
                    except six.Untrimmable as e:
                        conv.append((model, alt, mach, n, aileron, str(e)))
    sys.stdout = tables_out
    print("## Sweeps (seed %d; settled p in rad/s, * = not settled)\n" % args.seed)
    table(rows)
    print("\n## Points without a 1-g trim (drawn, replaced)\n")
    for m, alt, mach, e in refused:
        print("- %s at %.0f m, Mach %.2f: %s" % (m, alt, mach, e))
    print("\n## Integrator convergence (thrust off; max |dp| over 10 s, rad/s)\n")
    print("| model | h (m) | Mach | n | aileron (deg) | max abs p | dt vs dt/2 | dt/2 vs dt/4 "
          "| ratio | dt vs dt/2, t >= 2 s | settled p, dt vs dt/2 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for c in conv:
        if len(c) == 6:
            print("| %s | %.0f | %.2f | %g | %g | refused: %s |" % c)
            continue
        m, alt, mach, n, a, pmax, d1, d2, late, ds = c
        print("| %s | %.0f | %.2f | %g | %g | %.3f | %.2e | %.2e | %.2f | %.2e | %.2e |" % (
            m, alt, mach, n, a, pmax, d1, d2, d1 / d2 if d2 > 0 else math.inf, late, ds))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"rows": rows, "refused": refused, "convergence": conv}, f)


if __name__ == "__main__":
    main()
