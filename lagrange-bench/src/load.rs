//! The machine's load, written next to timings (the `work-precision` report, `step-cost`).

/// The load averages over 1, 5 and 15 minutes of `/proc/loadavg` (what `uptime` prints), joined
/// by `separator`; `None` where the file cannot be read.
pub fn load_averages(separator: &str) -> Option<String> {
    std::fs::read_to_string("/proc/loadavg").ok().map(|s| {
        s.split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(separator)
    })
}
