//! How a long pipeline reports its progress: stages that begin with a total, advance, and
//! end. The command line draws bars (or, when stderr is not a terminal, a line every few
//! seconds); a library caller may pass [`Silent`]. [`time_left`] and [`line`] are the
//! estimate and the text both show.

/// A listener of long work.
pub trait Progress: Sync {
    /// A stage named `what` begins (or learns its total, `0` when not yet known).
    fn begin(&self, what: &str, total: u64);
    /// `done` more units of the stage are finished.
    fn advance(&self, done: u64);
    /// The stage stands at `position`, with a short message (a method's residual).
    fn at(&self, position: u64, message: &str);
    /// The stage is over.
    fn end(&self);
}

/// No progress shown.
pub struct Silent;

impl Progress for Silent {
    fn begin(&self, _: &str, _: u64) {}
    fn advance(&self, _: u64) {}
    fn at(&self, _: u64, _: &str) {}
    fn end(&self) {}
}

/// Seconds left of a stage `done` of `total` units into it after `elapsed` seconds, at the
/// average rate since it began (not a recent rate: parallel work finishes in bursts).
/// `None` before the first unit, or when the total is not known.
pub fn time_left(elapsed: f64, done: u64, total: u64) -> Option<f64> {
    (done > 0 && total > 0).then(|| elapsed * total.saturating_sub(done) as f64 / done as f64)
}

/// The line printed for a stage when stderr is not a terminal:
/// `ugo: progress: assembly 40% (400/1000), 12 s, about 18 s left`.
pub fn line(what: &str, done: u64, total: u64, elapsed: f64) -> String {
    match time_left(elapsed, done, total) {
        Some(left) => {
            let percent = (100 * done.min(total)) / total;
            format!("ugo: progress: {what} {percent}% ({done}/{total}), {elapsed:.0} s, about {left:.0} s left")
        }
        None if total > 0 => format!("ugo: progress: {what} 0% (0/{total}), {elapsed:.0} s"),
        None => format!("ugo: progress: {what} at {done}, {elapsed:.0} s"),
    }
}
