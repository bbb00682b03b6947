//! The transfer toolkit: exposed areas of patches that furniture stands on, and closure.

mod closure;
mod exposure;
mod far_field;
mod one_ray;
