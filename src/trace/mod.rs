//! Monte Carlo references for the global illumination equation (`docs/design.md` §4): the
//! lecture's two directions of ray tracing, both summing the reflection-order expansion
//! `L = Σ_n Kⁿ L0` with the continuous materials and sharing no discretization with the
//! linear system.
//!
//! * [`backward`] (from the eye): path tracing with next-event estimation, multiple
//!   importance sampling and Russian roulette; [`probe`] makes the readings of a
//!   `[[probe]]` (a `[[camera]]`'s traced image is `crate::render`'s, one floor up).
//! * [`forward`] (from the sources): light tracing into the `(patch, direction cell)` bins,
//!   a Monte Carlo estimate of the discrete field `L(i,k)` with standard errors.
//! * [`agreement`]: a deterministic result against either, in units of the standard error;
//!   [`leaf_errors`]: against the forward bins precise enough to tell, in relative error.
//!
//! The pieces they share: [`world`] (geometry, materials, ray casting), [`emitters`]
//! (sources sampled by flux), [`luminaires`] (delta lights gathered exactly, photon
//! sources), [`openings`] (the sky and the ground through the `[[window]]`s),
//! [`daylight_photons`] (the sky's and the sun's photons through them) and
//! [`statistics`] (means and standard errors). The continuous materials and their
//! samplers are `crate::material`'s; the random streams `crate::random`'s.

pub mod agreement;
pub mod backward;
pub mod daylight_photons;
pub mod emitters;
pub mod forward;
pub mod leaf_errors;
pub mod luminaires;
pub mod openings;
pub mod probe;
pub mod statistics;
pub mod world;

pub use agreement::{Agreement, agreement};
pub use backward::{Start, TraceOptions, luminance_along};
pub use forward::{FieldEstimate, trace_photons};
pub use leaf_errors::{LeafErrors, leaf_errors};
pub use openings::Openings;
pub use probe::{ProbeEstimate, trace_probes};
pub use world::{Cast, World};
