//! The LaTeX dump (`docs/formulas.tex`): the document carries the paper's equation
//! numbers, is deterministic, states the comparisons with the paper's print, and compiles.
//!
//! The compile test typesets `model::emit::latex::document()` in a temporary directory (never
//! the committed file, which `emit` writes) with `pdflatex`. Without `pdflatex` on PATH it
//! fails when the environment variable `CI` is set (CI installs texlive-latex-base) and is
//! skipped otherwise, with a notice that the test runner prints even without --nocapture.

use model::aircraft::Param;
use model::algebra::Poly;
use model::derivation::Derivation;
use model::emit::latex::{document, TAGS};
use model::emit::paper::{self, parse};
use model::equations::symbols;
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::sync::OnceLock;

fn doc() -> &'static str {
    static D: OnceLock<String> = OnceLock::new();
    D.get_or_init(document)
}

/// The equation numbers of the paper that the derivation covers, each carried by `\tag{N}`.
const COVERED: [u32; 35] = [
    1, 2, 3, 4, 5, // pseudo-steady states: A, b u + b1 P0, x0, det A, the biquadratic
    6, 7, 8, 9, 10, // linearized equations
    11, 12, // q and r eliminated
    13, 14, // second-order form
    15, 16, // y'' + C y' + K y = 0, K0
    17, 18, 19, 20, // f_ij through the partials of p_s
    21, // roll mode
    22, 23, 24, 25, 26, // static residual and its partials
    27, 28, 29, 30, 31, // det K and the f_ij
    32, 33, 34, 35, // zero sideslip
];

#[test]
fn document_carries_every_covered_tag_and_is_deterministic() {
    assert_eq!(
        TAGS, COVERED,
        "the emitter's tag list is the list the derivation covers"
    );
    let d = doc();
    for n in COVERED {
        assert!(d.contains(&format!("\\tag{{{n}}}")), "missing \\tag{{{n}}}");
    }
    assert!(
        d.contains("\\tag{A.2}"),
        "the model of Appendix A.2 is shown"
    );
    assert_eq!(d, document(), "two calls give byte-identical output");
}

#[test]
fn document_is_well_formed_latex() {
    let d = doc();
    assert!(d.contains("\\documentclass"));
    assert!(d.trim_end().ends_with("\\end{document}"));
    for env in ["align*", "pmatrix", "vmatrix"] {
        let open = d.matches(&format!("\\begin{{{env}}}")).count();
        let close = d.matches(&format!("\\end{{{env}}}")).count();
        assert_eq!(open, close, "unbalanced {env}");
    }
    assert_eq!(
        d.matches('{').count(),
        d.matches('}').count(),
        "unbalanced braces"
    );
    for bad in [
        "+ -",
        "- -",
        "+ +",
        "1 \\alpha",
        "^{1}",
        "\\left",
        "\\right",
    ] {
        assert!(
            !d.contains(bad),
            "sign, coefficient or delimiter artifact {bad:?}"
        );
    }
    for pkg in [
        "\\usepackage{amsmath}",
        "\\usepackage[margin=2cm]{geometry}",
    ] {
        assert!(d.contains(pkg));
    }
    assert_eq!(
        d.matches("\\usepackage").count(),
        2,
        "only texlive-latex-base packages"
    );
}

#[test]
fn document_states_the_identity_and_the_comparisons_with_the_print() {
    let d = doc();
    assert!(
        d.contains("identically zero"),
        "det J5 = d det K verified symbolically"
    );
    assert!(!d.contains("WARNING"), "the identity residual is zero");
    // Eq. 13's printed p-terms contradict Eqs 17 and 28; the derivation agrees with the latter.
    assert!(d.contains("Eq.~13: differs from the paper's print"));
    assert!(d.contains("The first factor of Eqs.~28--29: agrees with the paper's print."));
    assert!(d.contains("$g_1$ (the factor in Eqs.~17--18): agrees with the paper's print."));
    for n in 6..=12 {
        assert!(
            d.contains(&format!("Eq.~{n}: agrees with the paper's print.")),
            "Eq. {n}"
        );
    }
    assert!(d.contains("Eq.~21: agrees with the paper's print."));
    assert!(d.contains("gives the paper's monic Eq.~5 exactly (checked)"));
    assert!(d.contains("$K_0$ agrees with Eq.~16 as printed."));
    assert!(d.contains("$A_1$ agrees with Eq.~34 as printed"));
    assert!(d.contains("\\det A_1 = n_{\\delta r} \\Delta_1$ (checked)"));
    assert!(d.contains("the compact form above was checked against the expansion"));
    assert!(
        d.contains("has 1447 terms"),
        "the jump polynomial is listed in full"
    );
}

#[test]
fn printed_transcriptions_parse() {
    assert_eq!(
        parse("P0*(C + 1)*beta_dot - 2*E^2"),
        parse("C*P0*beta_dot + P0*beta_dot - E*E - E^2")
    );
    assert_eq!(parse(paper::EQ11).len(), 4);
    assert_eq!(parse(paper::EQ13).len(), 14);
    assert_eq!(parse(paper::EQ21).len(), 14);
    assert_eq!(parse(paper::EQ5_TIMES_CD).len(), 9);
}

#[test]
#[should_panic(expected = "unknown symbol")]
fn printed_transcriptions_reject_unknown_names() {
    parse("m_q + x_unknown");
}

fn pdflatex_available() -> bool {
    Command::new("pdflatex")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

#[test]
fn document_compiles_with_pdflatex() {
    if !pdflatex_available() {
        assert!(
            std::env::var_os("CI").is_none(),
            "pdflatex is not on PATH but CI is set: install texlive-latex-base"
        );
        // Through the stderr handle, not `eprintln!`: the test harness captures the macros
        // (shown only on failure or with --nocapture) but not the handle, so the runner's
        // output carries this line.
        use std::io::Write;
        let _ = writeln!(
            std::io::stderr(),
            "SKIPPED document_compiles_with_pdflatex: pdflatex not on PATH \
             (apt-get install texlive-latex-base); set CI=1 to make this a failure"
        );
        return;
    }
    let dir: PathBuf = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("paper-tests-latex-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("formulas.tex"), doc()).expect("write formulas.tex");
    let out = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "formulas.tex"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .output()
        .expect("run pdflatex");
    let log = std::fs::read_to_string(dir.join("formulas.log")).unwrap_or_default();
    let pdf = dir.join("formulas.pdf");
    let ok = out.status.success() && pdf.is_file();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        ok,
        "pdflatex failed ({}):\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout)
    );
    // Overfull boxes are warnings for TeX; here any line sticking out by more than a few
    // points into the margin counts as a layout bug of the emitter.
    let worst = log
        .lines()
        .filter_map(|l| l.strip_prefix("Overfull \\hbox ("))
        .filter_map(|l| l.split("pt too wide").next()?.parse::<f64>().ok())
        .fold(0.0, f64::max);
    assert!(worst <= 5.0, "a line overruns the text width by {worst} pt");
}

// ---- the paper's print, difference by difference --------------------------------------------
//
// Each statement "differs from the paper's print" of `docs/formulas.tex` pinned as the exact
// polynomial `derived - printed`, so that a change of the model, of the derivation or of a
// transcription in `model::emit::paper` fails here by name and not only in the prose.

fn derivation() -> &'static Derivation {
    static D: OnceLock<Derivation> = OnceLock::new();
    D.get_or_init(Derivation::parametric)
}

fn sym(p: Param) -> Poly {
    Poly::var(symbols().param(p))
}

/// `p` in the case the paper prints: no trim lift, the principal axis on the flight path.
fn papers_case(p: &Poly) -> Poly {
    p.subs(symbols().param(Param::Z0), &Poly::zero())
        .subs(symbols().param(Param::AlphaT), &Poly::zero())
}

#[test]
fn eq_13_p_terms_differ_from_the_print_by_minus_2_c_r0_plus_p0_alpha0_times_p() {
    let s = symbols();
    let diff = &papers_case(&derivation().second_order[0]) - &parse(paper::EQ13);
    // -2 C (R0 + P0 alpha0) p: the print has the wrong sign on both C-terms of the p coefficient.
    let r0_p0_alpha0 = &Poly::var(s.r0) + &(&Poly::var(s.p0) * &Poly::var(s.alpha0));
    let expected = &(&(&Poly::int(-2) * &sym(Param::C)) * &r0_p0_alpha0) * &Poly::var(s.p);
    assert_eq!(diff, expected);
}

#[test]
fn eq_14_drops_n_p_times_p() {
    let diff = &papers_case(&derivation().second_order[1]) - &parse(paper::EQ14);
    assert_eq!(diff, &sym(Param::Np) * &Poly::var(symbols().p));
}

#[test]
fn eqs_17_18_factor_g1_agrees_and_eqs_19_20_factor_g2_drops_n_p() {
    let g = derivation().g.each_ref().map(papers_case);
    assert_eq!(g[0], parse(paper::EQ17_20_G[0]));
    assert_eq!(&g[1] - &parse(paper::EQ17_20_G[1]), sym(Param::Np));
}

#[test]
fn eqs_28_29_factor_agrees_and_eqs_30_31_factor_drops_n_p() {
    let g = derivation().g.each_ref().map(papers_case);
    assert_eq!(-&g[0], parse(paper::EQ28_31[0]));
    assert_eq!(&-&g[1] - &parse(paper::EQ28_31[1]), -&sym(Param::Np));
}
