//! What a long command shows on stderr while it runs: a progress bar when stderr is a terminal
//! (nothing when piped), and for a clearance map how long the other elevator settings will take.

use std::io::Write;

/// A progress bar on stderr when it is a terminal; nothing when piped.
pub fn progress_bar(what: &str) -> Option<indicatif::ProgressBar> {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new(1000);
    if let Ok(style) = indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {percent}%") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what.to_string());
    Some(bar)
}

/// Sets `bar`, if any, to the fraction `f` done.
pub fn set(bar: &Option<indicatif::ProgressBar>, f: f64) {
    if let Some(b) = bar {
        b.set_position((f * 1000.0) as u64);
    }
}

/// Tells on stderr, once the first of `n` elevator settings took `first_s` seconds, how long
/// the others will take at that pace (each proof is bounded by its budgets of work, so a map
/// of many settings can take minutes).
pub fn say_how_long(n: usize, first_s: f64) {
    let rest = first_s * (n - 1) as f64;
    let _ = writeln!(
        std::io::stderr(),
        "clear: {n} elevator settings; the first took {first_s:.1} s, so the other {} will \
         take about {} at that pace",
        n - 1,
        if rest < 120.0 {
            format!("{rest:.0} s")
        } else {
            format!("{:.1} min", rest / 60.0)
        }
    );
}
