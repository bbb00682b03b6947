//! A deterministic generator of hostile inputs (issue 18, item 7), run by `make test`:
//! every bundled case file, photometric file and OBJ mesh, and a solution file, mutated a
//! fixed number of times with a fixed seed (truncation at every kind of place, deleted,
//! repeated and swapped lines, numbers replaced by hostile ones, flipped and inserted
//! bytes); every reader must return `Ok` or a clean `Err`, never panic, and never take
//! more than a second. Each failure is listed with the input that caused it (saved under
//! the system temp folder), so that it can be added to `tests/data/hostile/`, whose
//! files are replayed first.

mod generator;
mod readers;
