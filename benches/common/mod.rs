//! What every benchmark's summary needs: criterion's estimates of this run, the interleaved ratio,
//! and the machine's load beside the figures.

pub mod constrained;

use std::sync::Mutex;
use std::time::Instant;

/// Whether this is a smoke run (`-- --test`): nothing is timed.
pub fn smoke_run() -> bool {
    std::env::args().any(|a| a == "--test")
}

/// Mean time of one benchmark from criterion's estimates of this run, in ns.
pub fn mean_ns(group: &str, bench: &str) -> Option<f64> {
    let dir = std::env::var_os("CARGO_TARGET_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"));
    let path = dir
        .join("criterion")
        .join(group)
        .join(bench)
        .join("new")
        .join("estimates.json");
    let text = std::fs::read_to_string(path).ok()?;
    let json: serde_json::Value = serde_json::from_str(&text).ok()?;
    json["mean"]["point_estimate"].as_f64()
}

/// The load average (1, 5, 15 minutes) as the kernel reports it, to print beside the figures.
pub fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".to_string())
}

/// Interleaved ratios measured so far: (label, first quartile, median, third quartile).
static INTERLEAVED: Mutex<Vec<(String, [f64; 3])>> = Mutex::new(Vec::new());

/// The interleaved ratio `measured / baseline`, recorded under `label` for [`print_interleaved`]:
/// 41 rounds, each timing about 2 ms of calls of one side and then the same number of calls of the
/// other (the order alternating from round to round); the median of the per-round ratios and its
/// quartiles. A drift of the machine's speed between two measurements seconds apart moves a ratio of
/// criterion's means; within a round (milliseconds) it hits both sides alike.
pub fn interleave(label: &str, mut baseline: impl FnMut(), mut measured: impl FnMut()) {
    if smoke_run() {
        return;
    }
    const ROUNDS: usize = 41;
    let batch = |f: &mut dyn FnMut(), calls: u64| {
        let start = Instant::now();
        for _ in 0..calls {
            f();
        }
        start.elapsed().as_secs_f64()
    };
    // Calls per batch: about 2 ms of the baseline.
    let probe = batch(&mut baseline, 1_000).max(1e-7);
    let calls = ((2e-3 / probe) * 1_000.0).clamp(20.0, 1e7) as u64;
    let mut ratios: Vec<f64> = (0..ROUNDS)
        .map(|round| {
            let (b, m) = if round % 2 == 0 {
                let b = batch(&mut baseline, calls);
                (b, batch(&mut measured, calls))
            } else {
                let m = batch(&mut measured, calls);
                (batch(&mut baseline, calls), m)
            };
            m / b
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    let quartiles = [
        ratios[ROUNDS / 4],
        ratios[ROUNDS / 2],
        ratios[3 * ROUNDS / 4],
    ];
    INTERLEAVED
        .lock()
        .unwrap()
        .push((label.to_string(), quartiles));
}

/// Prints every interleaved ratio recorded so far, under `title`.
pub fn print_interleaved(title: &str) {
    println!(
        "\n{title} (median of 41 interleaved rounds [quartiles]; load average {}):",
        load_average()
    );
    for (label, [low, median, high]) in INTERLEAVED.lock().unwrap().iter() {
        println!("  {label:<22} {median:.2}×  [{low:.2}, {high:.2}]");
    }
}
