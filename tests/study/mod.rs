//! Tests of the study pipelines (`ugo::study`).

mod light_scenes;
