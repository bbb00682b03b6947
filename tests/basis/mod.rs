//! Kernel factorization: the harmonics themselves, then SH and SVD solutions against the
//! full angular solution.

mod cli;
mod harmonics;
mod reduced;
