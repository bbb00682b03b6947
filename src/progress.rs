//! How a long pipeline reports its progress: stages that begin with a total, advance, and
//! end. The command line draws bars; a library caller may pass [`Silent`].

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
