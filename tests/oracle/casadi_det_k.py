"""det K of the PSS model (AIAA 2006-6267, Appendix A.2) built in CasADi SX, written out as C
by CasADi's code generator at its defaults: the comparison point of issue 11's benchmark
(`cargo bench -p paper-tests --bench det_k`), compiled into it by tests/build.rs.

Nothing here comes from the Rust workspace: the model is typed in below from the paper, the trim
is CasADi's symbolic linear solve of the four non-roll equations (affine in the aileron), the
aileron the root of the roll equation along it on the branch of the generated crate's `det_k`
(the root of smaller magnitude, by the cancellation-free quadratic formula), J5 CasADi's
symbolic Jacobian, d the static-residual denominator from J5's entries (Eqs 11-12, 22) and
det K = det J5 / d (the identity of the paper's step 7).

Run from the workspace root (CasADi 3.8.2, `pip install casadi`):

    python3 tests/oracle/casadi_det_k.py

It writes tests/oracle/casadi_det_k.c, which is committed. The C function is
`casadi_det_k(arg, res, iw, w, mem)` with inputs p0, delta_e, delta_r and the 18 data of an
aircraft in the order of `model::aircraft::Param::ALL`, output det K.
"""

import os

import casadi as ca

NAMES = [
    "C", "D", "E", "z_alpha", "y_beta", "l_p", "l_r", "l_beta", "l_delta_a", "m_q",
    "m_alpha", "m_delta_e", "n_p", "n_r", "n_beta", "n_delta_a", "n_delta_r", "l_delta_r",
]


def pss(k, x, u):
    """Appendix A.2: d/dt [alpha, beta, p, q, r] for controls [delta_a, delta_e, delta_r]."""
    a, b, p, q, r = x[0], x[1], x[2], x[3], x[4]
    da, de, dr = u[0], u[1], u[2]
    return ca.vertcat(
        q - p * b + k["z_alpha"] * a,
        p * a - r + k["y_beta"] * b,
        k["l_p"] * p + k["l_beta"] * b + k["l_r"] * r - k["E"] * q * r
        + k["l_delta_a"] * da + k["l_delta_r"] * dr,
        k["m_q"] * q + k["m_alpha"] * a + k["C"] * p * r + k["m_delta_e"] * de,
        k["n_r"] * r + k["n_beta"] * b + k["n_p"] * p - k["D"] * p * q
        + k["n_delta_r"] * dr + k["n_delta_a"] * da,
    )


def main():
    p0 = ca.SX.sym("p0")
    de = ca.SX.sym("delta_e")
    dr = ca.SX.sym("delta_r")
    kv = ca.SX.sym("k", len(NAMES))
    k = {n: kv[i] for i, n in enumerate(NAMES)}
    da = ca.SX.sym("delta_a")
    y = ca.SX.sym("y", 4)  # alpha, beta, q, r
    x = ca.vertcat(y[0], y[1], p0, y[2], y[3])
    f = pss(k, x, ca.vertcat(da, de, dr))
    rows = ca.vertcat(f[0], f[1], f[3], f[4])
    # The four non-roll equations are linear in y and affine in delta_a: A y + b0 + da b1 = 0.
    a = ca.jacobian(rows, y)
    b0 = ca.substitute(rows, ca.vertcat(y, da), ca.DM.zeros(5))
    b1 = ca.jacobian(rows, da)
    y0 = ca.solve(a, -b0)
    y1 = ca.solve(a, -b1)
    # The roll equation along the trim, a quadratic in delta_a.
    xt = ca.vertcat(y0[0] + da * y1[0], y0[1] + da * y1[1], p0, y0[2] + da * y1[2], y0[3] + da * y1[3])
    roll = pss(k, xt, ca.vertcat(da, de, dr))[2]
    g0 = ca.substitute(roll, da, 0)
    g1 = ca.substitute(ca.jacobian(roll, da), da, 0)
    g2 = ca.substitute(ca.hessian(roll, da)[0], da, 0) / 2
    root = -2 * g0 / (g1 + ca.sign(g1) * ca.sqrt(g1 * g1 - 4 * g0 * g2))
    trim = ca.substitute(xt, da, root)
    # J5 at the trim, d from its entries (Eqs 11-12, 22), det K = det J5 / d.
    xs = ca.SX.sym("x", 5)
    j5 = ca.substitute(ca.jacobian(pss(k, xs, ca.vertcat(da, de, dr)), xs), ca.vertcat(xs, da), ca.vertcat(trim, root))
    d = j5[2, 2] + j5[2, 3] * (-j5[0, 2] / j5[0, 3]) + j5[2, 4] * (-j5[1, 2] / j5[1, 4])
    det_k = ca.det(j5) / d
    fun = ca.Function("casadi_det_k", [p0, de, dr, kv], [det_k])
    here = os.path.dirname(os.path.abspath(__file__))
    cwd = os.getcwd()
    os.chdir(here)
    try:
        fun.generate("casadi_det_k.c")
    finally:
        os.chdir(cwd)
    print(f"wrote {os.path.join(here, 'casadi_det_k.c')}: {fun.n_instructions()} instructions, "
          f"{fun.nnz_in()} inputs (casadi {ca.__version__})")


if __name__ == "__main__":
    main()
