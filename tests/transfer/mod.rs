//! The transfer toolkit: exposed areas of patches that furniture stands on.

mod exposure;
