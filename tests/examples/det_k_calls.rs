//! Calls the generated parametric `det_k` N times (N from the command line), for counting
//! instructions per call with callgrind. With a second argument `loop` it runs the same loop
//! without the call: (Ir(N) - Ir(N loop)) / N is the cost of one call, call included.
//!
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null target/release/examples/det_k_calls 100000 [loop]`

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(0);
    let call = std::env::args().nth(2).is_none();
    let k = std::hint::black_box(roll_criterion::aircraft_b::DERIVATIVES);
    let mut s = 0.0;
    for i in 0..n {
        let p0 = 0.2 + 4.5 * (i % 1000) as f64 / 1000.0;
        s += if call {
            roll_criterion::det_k(
                std::hint::black_box(&k),
                std::hint::black_box(p0),
                0.0349,
                0.0,
            )
        } else {
            std::hint::black_box(p0)
        };
    }
    println!("{s}");
}
