//! Tests of the model (`ugo::model`): its values checked for range where they first appear.

mod mesh_formats;
mod part_rows;
mod range;
