//! The C twin of the generated crate (`generated/c/roll_criterion.h`), checked as a C project
//! would use it: it compiles warning-free as C99 and as C++ under strict flags, its self-test
//! passes, its function bodies are straight-line code, and on 10^5 random inputs every C result
//! has the same bits as the Rust crate's (both are printed from the same DAG in the same order),
//! with gcc, g++ and clang at each optimisation level of [`OPTS`].
//!
//! gcc and g++ are required when `CI` is set; without them elsewhere, and without clang
//! anywhere, the affected checks print a notice on stderr (not captured by the test harness).

/// Written by `emit` from the same function list as the header (model/src/emit/cross.rs).
#[rustfmt::skip]
#[path = "c_header/calls.rs"]
mod calls;

use paper_tests::Lcg;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The flags of every build (`-ffp-contract=off`: no fused multiply-add, which would round
/// differently from the Rust code); the optimisation level comes from [`OPTS`].
const FLAGS: &[&str] = &[
    "-Wall",
    "-Wextra",
    "-Werror",
    "-pedantic",
    "-Wconversion",
    "-Wdouble-promotion",
    "-Wshadow",
    "-ffp-contract=off",
];

/// An optimisation level the header is built at.
struct Opt {
    /// The flags, as a user writes them.
    flags: &'static [&'static str],
    /// Whether this machine runs the code: x86-64-v3 needs AVX2 and FMA, and its vectorised
    /// code is where gcc fuses multiplies into add/subtract pairs.
    runs_here: fn() -> bool,
}

/// The optimisation levels of the documented bit-identity: the default `-O2`, `-O3` (more
/// vectorisation) and `-O3 -march=x86-64-v3` (vectorised code with FMA instructions available).
const OPTS: &[Opt] = &[
    Opt {
        flags: &["-O2"],
        runs_here: || true,
    },
    Opt {
        flags: &["-O3"],
        runs_here: || true,
    },
    Opt {
        flags: &["-O3", "-march=x86-64-v3"],
        runs_here: runs_x86_64_v3,
    },
];

/// Whether this machine has every instruction set of x86-64-v3.
fn runs_x86_64_v3() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx")
            && std::arch::is_x86_feature_detected!("avx2")
            && std::arch::is_x86_feature_detected!("bmi1")
            && std::arch::is_x86_feature_detected!("bmi2")
            && std::arch::is_x86_feature_detected!("f16c")
            && std::arch::is_x86_feature_detected!("fma")
            && std::arch::is_x86_feature_detected!("lzcnt")
            && std::arch::is_x86_feature_detected!("movbe")
            && std::arch::is_x86_feature_detected!("xsave")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Number of random records of the cross-check.
const RECORDS: usize = 100_000;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn c_dir() -> PathBuf {
    root().join("generated/c")
}

fn tmp_dir() -> &'static Path {
    Path::new(env!("CARGO_TARGET_TMPDIR"))
}

/// A notice the test harness does not capture, so that a skipped check is seen.
fn notice(msg: &str) {
    let _ = writeln!(std::io::stderr(), "NOTICE c_header: {msg}");
}

fn available(compiler: &str) -> bool {
    Command::new(compiler)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// A compiler the checks require: missing is a failure under CI, a notice elsewhere.
fn required(compiler: &str) -> bool {
    if available(compiler) {
        return true;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "{compiler} is not on PATH but CI is set: install gcc and g++ (apt-get install gcc g++)"
    );
    notice(&format!(
        "SKIPPED the {compiler} checks: {compiler} is not on PATH; set CI=1 to make this a failure"
    ));
    false
}

/// One way to compile the header: compiler and language flags.
struct Build {
    compiler: &'static str,
    language: &'static [&'static str],
}

const GCC: Build = Build {
    compiler: "gcc",
    language: &["-std=c99"],
};
const GXX: Build = Build {
    compiler: "g++",
    language: &["-x", "c++", "-std=c++11"],
};
const CLANG: Build = Build {
    compiler: "clang",
    language: &["-std=c99"],
};

/// A compiled self-test: compiler, optimisation flags and the executable.
struct Built {
    compiler: &'static str,
    opt: &'static [&'static str],
    exe: PathBuf,
}

impl Built {
    /// The compiler and its optimisation flags, for messages.
    fn name(&self) -> String {
        format!("{} {}", self.compiler, self.opt.join(" "))
    }
}

/// Compiles `dir/test_roll_criterion.c` (with the header next to it) with `build` at `opt`
/// into `exe`; panics with the compiler's output on any warning.
fn compile_self_test(build: &Build, opt: &[&str], dir: &Path, exe: &Path) {
    let out = Command::new(build.compiler)
        .args(build.language)
        .args(FLAGS)
        .args(opt)
        .arg("-o")
        .arg(exe)
        .arg(dir.join("test_roll_criterion.c"))
        .arg("-lm")
        .output()
        .unwrap_or_else(|e| panic!("run {}: {e}", build.compiler));
    assert!(
        out.status.success() && out.stderr.is_empty(),
        "{} {:?} {FLAGS:?} {opt:?} failed or warned:\n{}",
        build.compiler,
        build.language,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// `generated/c/test_roll_criterion.c` built by gcc, g++ and clang (when present) at every
/// optimisation level this machine runs, compiled in parallel once for all tests of this file.
fn builds() -> &'static [Built] {
    static BUILDS: OnceLock<Vec<Built>> = OnceLock::new();
    BUILDS.get_or_init(|| {
        let mut compilers: Vec<Build> = [GCC, GXX]
            .into_iter()
            .filter(|b| required(b.compiler))
            .collect();
        if available(CLANG.compiler) {
            compilers.push(CLANG);
        } else {
            notice("SKIPPED the clang builds: clang is not on PATH");
        }
        let opts: Vec<&Opt> = OPTS
            .iter()
            .filter(|o| {
                let runs = (o.runs_here)();
                if !runs {
                    notice(&format!(
                        "SKIPPED the builds with {}: this machine does not run their code",
                        o.flags.join(" ")
                    ));
                }
                runs
            })
            .collect();
        std::thread::scope(|s| {
            let handles: Vec<_> = compilers
                .iter()
                .flat_map(|b| opts.iter().map(move |o| (b, o)))
                .map(|(b, o)| {
                    s.spawn(move || {
                        let exe = tmp_dir().join(format!(
                            "test_roll_criterion_{}{}",
                            b.compiler.replace('+', "x"),
                            o.flags.concat()
                        ));
                        // Built under a name of this process, then renamed: a concurrent run
                        // never sees half a file.
                        let tmp = exe.with_extension(format!("tmp{}", std::process::id()));
                        compile_self_test(b, o.flags, &c_dir(), &tmp);
                        std::fs::rename(&tmp, &exe).unwrap();
                        Built {
                            compiler: b.compiler,
                            opt: o.flags,
                            exe,
                        }
                    })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        })
    })
}

fn run_self_test(name: &str, exe: &Path) {
    let out = Command::new(exe).output().expect("run the self-test");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success() && stdout.contains(" 0 failed"),
        "{name} self-test failed:\n{stdout}"
    );
    let checks: usize = stdout
        .split_whitespace()
        .nth(1)
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    assert!(
        checks > 100,
        "{name} self-test checked too little: {stdout}"
    );
}

/// Every build: C99 with gcc and clang, C++11 with g++, at each level of [`OPTS`], under the
/// strict warnings of [`FLAGS`].
#[test]
fn every_build_is_warning_free_and_passes_the_self_test() {
    for b in builds() {
        run_self_test(&b.name(), &b.exe);
    }
}

/// Compiles `source` (in the temporary directory, with the header on the include path) to an
/// object file and returns what `nm` lists in it.
fn object_symbols(build: &Build, name: &str, source: &str) -> String {
    let src = tmp_dir().join(format!("{name}_{}.c", std::process::id()));
    let obj = src.with_extension("o");
    std::fs::write(&src, source).unwrap();
    let out = Command::new(build.compiler)
        .args(build.language)
        .args(FLAGS)
        .args(OPTS[0].flags)
        .arg("-I")
        .arg(c_dir())
        .arg("-c")
        .arg(&src)
        .arg("-o")
        .arg(&obj)
        .output()
        .expect("run the compiler");
    assert!(
        out.status.success() && out.stderr.is_empty(),
        "{} on {name}:\n{}",
        build.compiler,
        String::from_utf8_lossy(&out.stderr)
    );
    let nm = Command::new("nm").arg(&obj).output().expect("run nm");
    let _ = (std::fs::remove_file(&src), std::fs::remove_file(&obj));
    String::from_utf8_lossy(&nm.stdout).into_owned()
}

#[test]
fn header_honours_include_guards_the_linkage_macro_and_extern_c() {
    // Included twice, with external linkage chosen through ROLL_CRITERION_API: as C, and as
    // C++, where the extern "C" guard must keep the names unmangled.
    let source = "#define ROLL_CRITERION_API\n#include \"roll_criterion.h\"\n#include \"roll_criterion.h\"\n";
    for build in [GCC, GXX] {
        if !required(build.compiler) {
            continue;
        }
        let symbols = object_symbols(&build, "linkage", source);
        for f in calls::LABELS[0] {
            let name = f.split('(').next().unwrap();
            assert!(
                symbols.contains(&format!(" T {name}\n")),
                "{}: {name} is not an unmangled external definition with ROLL_CRITERION_API empty:\n{symbols}",
                build.compiler
            );
        }
    }
}

#[test]
fn the_self_test_fails_when_a_constant_of_the_header_is_perturbed() {
    if !required("gcc") {
        return;
    }
    // Aircraft A's l_p moved by one part in 10^9 in a copy of the header.
    let header = std::fs::read_to_string(c_dir().join("roll_criterion.h")).unwrap();
    let line = header
        .lines()
        .find(|l| l.ends_with(", // l_p"))
        .expect("the l_p line of the data");
    let value: f64 = line.trim().split(',').next().unwrap().parse().unwrap();
    let perturbed = header.replacen(line, &format!("    {:?}, // l_p", value * (1.0 + 1e-9)), 1);
    let dir = tmp_dir().join(format!("perturbed_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("roll_criterion.h"), perturbed).unwrap();
    std::fs::copy(
        c_dir().join("test_roll_criterion.c"),
        dir.join("test_roll_criterion.c"),
    )
    .unwrap();
    let exe = dir.join("test_roll_criterion");
    compile_self_test(&GCC, OPTS[0].flags, &dir, &exe);
    let run = Command::new(&exe).output().expect("run the self-test");
    let _ = std::fs::remove_dir_all(&dir);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        !run.status.success()
            && stdout.contains("FAIL rc_")
            && stdout.contains("(&rc_aircraft_a_derivatives"),
        "the self-test did not notice the perturbed l_p:\n{stdout}"
    );
}

/// The names the header defines functions for, in order.
fn header_functions(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("\nROLL_CRITERION_API ") {
        rest = &rest[i + 1..];
        let open = rest.find('(').unwrap();
        let name = rest[..open].split_whitespace().last().unwrap().to_string();
        let body_start = rest.find("\n{\n").unwrap();
        let body_end = rest.find("\n}\n").unwrap();
        out.push((name, rest[body_start + 3..body_end].to_string()));
        rest = &rest[body_end..];
    }
    out
}

#[test]
fn header_functions_are_straight_line_with_one_return_and_only_sqrt_and_copysign() {
    let text = std::fs::read_to_string(c_dir().join("roll_criterion.h")).unwrap();
    for guard in [
        "#ifndef ROLL_CRITERION_H",
        "#ifdef __cplusplus\nextern \"C\" {",
        "#define ROLL_CRITERION_API static inline",
        "static const struct rc_derivatives rc_aircraft_a_derivatives",
        "static const struct rc_derivatives rc_aircraft_b_derivatives",
        "// @generated by `cargo run -p model -- emit`",
    ] {
        assert!(text.contains(guard), "header lacks {guard:?}");
    }
    let fns = header_functions(&text);
    // Every output label of the cross-check names a header function, and vice versa.
    // Every function a label names (`rc_prepared_det_k(&rc_prepared_new(&...))` names two);
    // the aircraft data `rc_aircraft_a_derivatives` are not functions.
    let mut called: Vec<String> = calls::LABELS
        .iter()
        .flatten()
        .flat_map(|l| l.split(|c: char| !(c.is_alphanumeric() || c == '_')))
        .filter(|w| w.starts_with("rc_") && !w.ends_with("_derivatives"))
        .map(str::to_string)
        .collect();
    called.sort();
    called.dedup();
    let mut defined: Vec<String> = fns.iter().map(|(n, _)| n.clone()).collect();
    defined.sort();
    assert_eq!(called, defined);
    for (name, body) in &fns {
        if name == "rc_prepared_det_k_into" {
            // The slice form: a loop whose body is one call of the straight-line det_k.
            assert_eq!(
                body.trim(),
                "size_t i;\n    for (i = 0; i < n; i++) {\n        out[i] = rc_prepared_det_k(self, p0[i]);\n    }",
                "{name}"
            );
            continue;
        }
        assert_eq!(body.matches("return").count(), 1, "{name}: one return");
        for word in body.split(|c: char| !(c.is_alphanumeric() || c == '_')) {
            assert!(
                !matches!(
                    word,
                    "if" | "else" | "for" | "while" | "do" | "switch" | "goto" | "malloc"
                ),
                "{name} uses `{word}`"
            );
        }
        assert!(!body.contains('?'), "{name} has a conditional expression");
        for (i, _) in body.match_indices('(') {
            let before = body[..i].trim_end();
            let callee = before
                .rsplit(|c: char| !(c.is_alphanumeric() || c == '_'))
                .next()
                .unwrap();
            assert!(
                matches!(callee, "" | "sqrt" | "copysign" | "void" | "return"),
                "{name} calls {callee}"
            );
        }
    }
}

/// The random value of an argument, by name (P0 in [0, 6] rad/s, the elevator and rudder
/// within 10 deg).
fn sample(name: &str, rng: &mut Lcg) -> f64 {
    let deg10 = 10f64.to_radians();
    match name {
        "p0" | "p" => rng.range(0.0, 6.0),
        "delta_e" | "delta_r" => rng.range(-deg10, deg10),
        "alpha" | "beta" => rng.range(-0.5, 0.5),
        _ => rng.range(-1.0, 1.0),
    }
}

type Record = (usize, [f64; calls::COLUMNS.len()]);

/// Non-finite and extreme records for each aircraft, then `n` random ones (seeded).
fn records(n: usize) -> Vec<Record> {
    let mut out = Vec::new();
    for aircraft in 0..calls::AIRCRAFT.len() {
        for x in [0.0, -0.0, f64::NAN, f64::INFINITY, -1e300, 5e-324] {
            out.push((aircraft, [x; calls::COLUMNS.len()]));
        }
    }
    let mut rng = Lcg(0x05ee_dc99);
    for _ in 0..n {
        let aircraft = ((rng.next_f64() * calls::AIRCRAFT.len() as f64) as usize)
            .min(calls::AIRCRAFT.len() - 1);
        let mut x = [0.0; calls::COLUMNS.len()];
        for (v, name) in x.iter_mut().zip(calls::COLUMNS) {
            *v = sample(name, &mut rng);
        }
        out.push((aircraft, x));
    }
    out
}

/// Writes `records` as the input file of `--bits` under `name` in the temporary directory.
fn write_records(name: &str, records: &[Record]) -> PathBuf {
    let path = tmp_dir().join(format!("{name}_{}", std::process::id()));
    let mut text = String::with_capacity(records.len() * 160);
    for (aircraft, x) in records {
        text.push_str(&aircraft.to_string());
        for v in x {
            text.push_str(&format!(" {:x}", v.to_bits()));
        }
        text.push('\n');
    }
    std::fs::write(&path, text).unwrap();
    path
}

/// Runs `exe --bits` on the `n` records of the file `path`; the C results as written, one
/// double per output in host byte order (decoded by [`c_value`]).
fn c_outputs(exe: &Path, path: &Path, n: usize) -> Vec<u8> {
    let out = Command::new(exe)
        .arg("--bits")
        .arg(path)
        .output()
        .expect("run --bits");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let outputs = calls::LABELS[0].len();
    assert_eq!(out.stdout.len(), n * outputs * 8, "one double per output");
    out.stdout
}

/// Output `k` of the C results `c` (outputs of all records in a row).
fn c_value(c: &[u8], k: usize) -> f64 {
    f64::from_ne_bytes(c[8 * k..8 * k + 8].try_into().unwrap())
}

/// Same bits, or both NaN (payloads of NaN may differ between compilers).
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

/// The Rust results of record `i`.
type Rust<'a> = &'a dyn Fn(usize) -> [f64; calls::LABELS[0].len()];

/// The first record and output where C and Rust differ, as a message naming the input.
fn first_difference(records: &[Record], c: &[u8], rust: Rust) -> Option<String> {
    let n = calls::LABELS[0].len();
    for (i, (aircraft, x)) in records.iter().enumerate() {
        let r = rust(i);
        let got = |j: usize| c_value(c, i * n + j);
        if let Some(j) = (0..n).find(|j| !same(got(*j), r[*j])) {
            let inputs: Vec<String> = calls::COLUMNS
                .iter()
                .zip(x)
                .map(|(name, v)| format!("{name} = {v:e}"))
                .collect();
            return Some(format!(
                "record {i} ({}, {}): {} is {:e} ({:#018x}) in C but {:e} ({:#018x}) in Rust",
                calls::AIRCRAFT[*aircraft],
                inputs.join(", "),
                calls::LABELS[*aircraft][j],
                got(j),
                got(j).to_bits(),
                r[j],
                r[j].to_bits()
            ));
        }
    }
    None
}

/// Every build of [`builds`]: each compiler at each optimisation level, the vectorised
/// `-O3 -march=x86-64-v3` included.
#[test]
fn c_and_rust_results_are_bit_identical_on_100000_random_inputs_in_every_build() {
    let records = records(RECORDS);
    let path = write_records("records", &records);
    let rust: Vec<_> = records
        .iter()
        .map(|(aircraft, x)| calls::outputs(*aircraft, x))
        .collect();
    let lookup = |i: usize| rust[i];
    // One build at a time: the outputs of a build take 8 bytes x 172 outputs x 10^5 records.
    let failures: Vec<String> = builds()
        .iter()
        .filter_map(|b| {
            let c = c_outputs(&b.exe, &path, records.len());
            first_difference(&records, &c, &lookup).map(|msg| {
                format!(
                    "{}: C and Rust differ at the first differing input, {msg}",
                    b.name()
                )
            })
        })
        .collect();
    std::fs::remove_file(&path).unwrap();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn the_cross_check_detects_a_one_ulp_difference_and_names_the_input() {
    let Some(build) = builds().first() else {
        return;
    };
    let records = records(50);
    let path = write_records("records50", &records);
    let c = c_outputs(&build.exe, &path, records.len());
    std::fs::remove_file(&path).unwrap();
    let rust = |i: usize| calls::outputs(records[i].0, &records[i].1);
    assert_eq!(first_difference(&records, &c, &rust), None);
    // One output of record 20 moved by one ulp on the Rust side.
    let perturbed = |i: usize| {
        let mut r = rust(i);
        if i == 20 {
            r[3] = f64::from_bits(r[3].to_bits() + 1);
        }
        r
    };
    let msg = first_difference(&records, &c, &perturbed).expect("a difference");
    assert!(
        msg.starts_with("record 20 (") && msg.contains(calls::LABELS[records[20].0][3]),
        "{msg}"
    );
    // An input one ulp away gives different bits somewhere, and that is found too.
    let shifted = |i: usize| {
        let (aircraft, x) = &records[i];
        calls::outputs(*aircraft, &x.map(|v| f64::from_bits(v.to_bits() + 1)))
    };
    let msg = first_difference(&records, &c, &shifted).expect("a difference");
    assert!(
        msg.starts_with("record 0 (") || msg.contains("record "),
        "{msg}"
    );
    // NaN equals NaN whatever the payload; signed zeros differ.
    assert!(same(f64::NAN, f64::from_bits(f64::NAN.to_bits() ^ 1)));
    assert!(!same(0.0, -0.0));
}

/// The mnemonics of x86's fused multiply-add instructions (`vfmadd231sd`, `vfmaddsub132pd`,
/// `vfnmsub213pd`, ...): one rounding where the Rust code rounds twice.
const FMA_MNEMONICS: &[&str] = &["vfmadd", "vfmsub", "vfnmadd", "vfnmsub"];

/// The functions of `exe` (its disassembly by `objdump`) that contain a fused multiply-add
/// instruction, with the first such instruction of each.
fn fused_multiply_adds(exe: &Path) -> Vec<String> {
    let out = Command::new("objdump")
        .args(["-d", "--no-show-raw-insn"])
        .arg(exe)
        .output()
        .expect("run objdump");
    assert!(out.status.success(), "objdump {exe:?} failed");
    let mut found: Vec<String> = Vec::new();
    let mut function = "";
    let text = String::from_utf8_lossy(&out.stdout);
    for line in text.lines() {
        if let Some(name) = line.strip_suffix(">:") {
            function = name.rsplit('<').next().unwrap_or(name);
            continue;
        }
        let Some(mnemonic) = line
            .split('\t')
            .nth(1)
            .and_then(|i| i.split_whitespace().next())
        else {
            continue;
        };
        if FMA_MNEMONICS.iter().any(|m| mnemonic.starts_with(m))
            && !found
                .iter()
                .any(|f| f.starts_with(&format!("{function}: ")))
        {
            found.push(format!("{function}: {mnemonic}"));
        }
    }
    found
}

/// A fused multiply-add rounds once where the Rust code rounds twice, so no build may contain
/// one: not from contraction, and not from a vectoriser pattern that ignores
/// `-ffp-contract=off`. The disassembly names the function where the random inputs of the
/// cross-check might miss the rounding difference.
#[test]
fn no_build_contains_a_fused_multiply_add_instruction() {
    if !cfg!(target_arch = "x86_64") {
        notice("SKIPPED the fused multiply-add scan: its mnemonics are x86's");
        return;
    }
    let failures: Vec<String> = builds()
        .iter()
        .filter_map(|b| {
            let found = fused_multiply_adds(&b.exe);
            (!found.is_empty()).then(|| format!("{}: {}", b.name(), found.join(", ")))
        })
        .collect();
    assert!(
        failures.is_empty(),
        "fused multiply-add instructions in\n{}",
        failures.join("\n")
    );
}

#[test]
fn guide_c_example_compiles_warning_free() {
    if !required("gcc") {
        return;
    }
    let page = std::fs::read_to_string(root().join("docs/generated.md")).unwrap();
    let section = &page[page
        .find("## The same criterion in C")
        .expect("the C section of docs/generated.md")..];
    let start = section.find("```c\n").expect("a C example") + 5;
    let example = &section[start..start + section[start..].find("```").unwrap()];
    let symbols = object_symbols(&GCC, "guide", example);
    assert!(symbols.contains(" T criterion\n"), "{symbols}");
}

/// No expression of the header is longer than the emitter's cap (the same programs
/// as the Rust crate, so the same split): the right-hand side of every `const double` and
/// `result` assignment and every `return`, on one line.
#[test]
fn header_expressions_are_within_the_width_cap() {
    let text = std::fs::read_to_string(c_dir().join("roll_criterion.h")).unwrap();
    let cap = model::emit::statements::MAX_WIDTH;
    let mut widths = Vec::new();
    for (name, body) in header_functions(&text) {
        let code: String = body
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join(" ");
        for stmt in code.split(';') {
            let stmt = stmt.split_whitespace().collect::<Vec<_>>().join(" ");
            let rhs = match stmt.strip_prefix("return ") {
                Some(r) => r,
                None => match stmt.split_once(" = ") {
                    Some((_, r)) => r,
                    None => continue,
                },
            };
            assert!(
                rhs.len() <= cap,
                "{name}: an expression of {} characters (cap {cap}): {rhs}",
                rhs.len()
            );
            widths.push(rhs.len());
        }
    }
    assert!(widths.len() > 1000, "expressions not found");
    println!(
        "{} expressions, widest {} characters",
        widths.len(),
        widths.iter().max().unwrap()
    );
}
