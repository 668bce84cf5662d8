"""Notebook-style example: import the F-104 from JSBSim, analyse it at one flight state, map its
1-g envelope and plot the critical jump's roll rate and the aileron margin with matplotlib.

Run: python docs/python_f104_envelope.py [OUT.png [ALTITUDES_M MACHS]]   (after
`pip install ./python`; the grid defaults to 0:12000:3000 m by Mach 0.3:0.9:0.1)
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import roll_coupling as rc  # noqa: E402

# %% One flight state: 6096 m (20,000 ft), Mach 0.53, trimmed in level flight (1 g).
f104 = rc.import_jsbsim("f104", altitude_m=6096, mach=0.53)
print(f104)
a = rc.analyze(f104)
print(a)

# %% The envelope: every altitude x Mach point trimmed at 1 g and analysed (local cores).
altitudes_m, machs = sys.argv[2:4] if len(sys.argv) > 3 else ("0:12000:3000", "0.3:0.9:0.1")
env = rc.envelope("jsbsim:f104", altitudes_m=altitudes_m, machs=machs)
print(f"{len(env.points)} points, {env.untrimmed} untrimmable ({env.elevator})")

# %% Plot: arrays over altitude x Mach, straight into pcolormesh (NaN where no trim or no jump).
fig, axes = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
for ax, grid, label in ((axes[0], env.p0, "critical jump P0, rad/s"),
                        (axes[1], env.margin_deg, "aileron limit - |critical aileron|, deg")):
    mesh = ax.pcolormesh(env.machs, env.altitudes_m, grid, shading="nearest")
    fig.colorbar(mesh, ax=ax, label=label)
    ax.set_xlabel("Mach")
    ax.set_ylabel("altitude, m")
fig.suptitle("F-104 (JSBSim), 1-g trim at every point")
out = sys.argv[1] if len(sys.argv) > 1 else "f104_envelope.png"
fig.savefig(out, dpi=80)
print(f"wrote {out}")
