//! Calls the generated parametric `det_k`, `Prepared::det_k` or `Prepared::det_k_into` N times
//! (N from the command line), for counting instructions per call with callgrind. The second
//! argument picks the route: `det_k` (default), `prepared`, `into` (slices of 1000 roll rates),
//! or `loop`, the same loop without any call: (Ir(N route) - Ir(N loop)) / N is the cost of one
//! call, call included. `into` fills its roll rates once, not per call as the others do: its
//! cost per element is (Ir(2N into) - Ir(N into)) / N.
//!
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/det_k_calls 100000 [det_k|prepared|into|loop]`

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(0);
    let route = std::env::args().nth(2).unwrap_or_else(|| "det_k".into());
    let k = std::hint::black_box(roll_criterion::aircraft_b::DERIVATIVES);
    let prepared = roll_criterion::Prepared::new(&k, 0.0349, 0.0);
    let p0 = |i: usize| 0.2 + 4.5 * (i % 1000) as f64 / 1000.0;
    let mut s = 0.0;
    if route == "into" {
        // The same roll rates, 1000 at a time, through the slice form.
        let mut ps = [0.0; 1000];
        let mut out = [0.0; 1000];
        for (i, p) in ps.iter_mut().enumerate() {
            *p = p0(i);
        }
        for _ in 0..n / 1000 {
            prepared.det_k_into(std::hint::black_box(&ps), &mut out);
            s += std::hint::black_box(&out)[0];
        }
    } else {
        for i in 0..n {
            let p = std::hint::black_box(p0(i));
            s += match route.as_str() {
                "prepared" => std::hint::black_box(&prepared).det_k(p),
                "loop" => p,
                _ => roll_criterion::det_k(std::hint::black_box(&k), p, 0.0349, 0.0),
            };
        }
    }
    println!("{s}");
}
