//! Refused files whose inertia is incomplete, mixed or not that of a rigid body.

use super::*;

pub(super) fn inertia_refusals() -> Vec<Refusal> {
    vec![
        refused(
            "moments of inertia together with coefficients",
            replace("E = 0.705\n", "E = 0.705\nix = 1.0\niy = 2\niz = 3\n"),
            6,
            &[
                "`inertia.ix` given together with `inertia.C`",
                "expected either",
            ],
        )
        .kind(is!(InertiaSet)),
        refused(
            "no inertia at all",
            replace(CDE, ""),
            2,
            &["`inertia`", "no inertia given", "expected either"],
        )
        .kind(is!(InertiaSet)),
        refused(
            "two of the three coefficients",
            replace("E = 0.705\n", ""),
            2,
            &[
                "missing `inertia.E`",
                "`inertia.C`, `inertia.D`",
                "expected either",
            ],
        )
        .kind(is!(InertiaSet)),
        refused(
            "one of the three moments of inertia",
            replace(CDE, "iz = 2\n"),
            2,
            &["missing `inertia.ix`, `inertia.iy`", "expected either"],
        ),
        refused(
            "a zero moment of inertia",
            replace(CDE, "ix = 1\niy = 0\niz = 3\n"),
            4,
            &["inertia.iy", "expected a moment of inertia > 0", "0"],
        )
        .kind(is!(NonPositiveInertia)),
        refused(
            "a negative moment of inertia",
            replace(CDE, "ix = 1\niy = -1.5\niz = 3\n"),
            4,
            &["inertia.iy", "expected a moment of inertia > 0", "-1.5"],
        )
        .kind(is!(NonPositiveInertia)),
        refused(
            "a zero moment of inertia written 0.0",
            replace(CDE, "ix = 1\niy = 0.0\niz = 3\n"),
            4,
            &["inertia.iy", "expected a moment of inertia > 0", "0.0"],
        )
        .kind(is!(NonPositiveInertia)),
        // ix + iy < iz is analysed with a warning, but E = 0.6 / 1e-309 leaves f64.
        refused(
            "moments of inertia whose coefficient E leaves f64",
            replace(CDE, "ix = 1e-309\niy = 5.5\niz = 6.1\n"),
            2,
            &[
                "[inertia]",
                "coefficient E = inf, beyond f64",
                "ix = 1e-309",
            ],
        )
        .kind(is!(UnphysicalInertia)),
        refused(
            "a coefficient C above 1",
            replace("C = 0.959", "C = 1.5"),
            3,
            &["inertia.C", "within [-1, 1]", "unphysical"],
        ),
        refused(
            "a coefficient E below -1",
            replace("E = 0.705", "E = -1.01"),
            5,
            &["inertia.E", "within [-1, 1]", "unphysical"],
        ),
        // C = D = 0 is ix = iy = iz, so E = 0.
        refused(
            "coefficients C = D = 0 with E far from 0",
            replace("C = 0.959\nD = 0.786\nE = 0.705", "C = 0\nD = 0\nE = 0.9"),
            5,
            &[
                "`inertia.E` = 0.9",
                "C and D imply E = (C - D)/(1 - C D) = 0",
                "within 0.001 of those of one rigid body",
            ],
        )
        .kind(is!(InconsistentInertia)),
        // C = D = 1: iz = ix + iy and iy = ix + iz, so ix = 0 and E = (iz - iy)/ix is undefined.
        refused(
            "coefficients C = D = 1",
            replace("C = 0.959\nD = 0.786\nE = 0.705", "C = 1\nD = 1\nE = 0.5"),
            4,
            &[
                "`inertia.C` = 1 and `inertia.D` = 1",
                "ix = 0",
                "rigid body",
            ],
        )
        .kind(is!(InconsistentInertia)),
    ]
}
