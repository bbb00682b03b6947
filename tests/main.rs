//! The one integration-test crate of ugo; its folders mirror `src/`.

mod kernel;
mod scene;
mod solve;
mod support;
