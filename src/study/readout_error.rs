//! [`ReadoutError`]: why `ugo readout` (`super::after_solve`) refuses to read an edited case
//! on a stored field (`docs/light-scenes.md`, "After the solve: ugo readout"): the field
//! `x = (I − K)⁻¹ L0` of `docs/design.md` §1 is the case's only while its sources,
//! reflectances and groups are the solved ones.

use crate::model::Change;
use std::path::PathBuf;
use thiserror::Error;

/// Why the stored field cannot be read out for the case.
#[derive(Debug, Error)]
pub enum ReadoutError {
    /// Parts that leave the kernel but change the field.
    #[error(
        "{} changes {} from the case {} was solved for: the stored field is not its field; solve it again",
        case.display(),
        changes.iter().map(Change::to_string).collect::<Vec<_>>().join(", "),
        file.display()
    )]
    Changed {
        /// The case file.
        case: PathBuf,
        /// The solution file.
        file: PathBuf,
        /// The parts changed.
        changes: Vec<Change>,
    },
    /// A surface's emission differs from the solved one.
    #[error(
        "{}: [[surface]] \"{surface}\" emits {case_value} cd/m² on patch {patch}, {stored} cd/m² when {} was \
         solved: the stored field is not its field; solve it again",
        case.display(),
        file.display()
    )]
    Emission {
        /// The case file.
        case: PathBuf,
        /// The solution file.
        file: PathBuf,
        /// The surface's name.
        surface: String,
        /// The first patch that differs.
        patch: usize,
        /// Its emission in the case, cd/m².
        case_value: f64,
        /// Its emission in the file, cd/m².
        stored: f64,
    },
    /// A light scene lights a group whose field the file does not hold.
    #[error(
        "{}: [[light_scene]] \"{scene}\" lights group \"{group}\", whose field {} does not hold \
         (its groups: {}); solve the case again to add a group",
        case.display(),
        file.display(),
        if present.is_empty() { "none: it was solved without [[light_scene]]".to_string() } else { present.join(", ") }
    )]
    AbsentGroup {
        /// The case file.
        case: PathBuf,
        /// The solution file.
        file: PathBuf,
        /// The light scene.
        scene: String,
        /// The group it lights.
        group: String,
        /// The groups the file holds.
        present: Vec<String>,
    },
    /// The case's groups of sources are not the solved ones.
    #[error(
        "{}: group \"{group}\" holds other sources than when {} was solved: its stored field is not this group's; \
         solve the case again",
        case.display(),
        file.display()
    )]
    OtherGroup {
        /// The case file.
        case: PathBuf,
        /// The solution file.
        file: PathBuf,
        /// The group.
        group: String,
    },
    /// The case has a sky, other light and new probes or grids: their daylight factors need
    /// a solve of the daylight alone.
    #[error(
        "{}: the case has a [sky] beside other light and its probes or grids differ from those {} was solved \
         with: their daylight factors need the daylight solved alone, which ugo readout does not do; solve the \
         case again",
        case.display(),
        file.display()
    )]
    Daylight {
        /// The case file.
        case: PathBuf,
        /// The solution file.
        file: PathBuf,
    },
}
