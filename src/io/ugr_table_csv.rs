//! `ugo glare --table … --csv FILE`: a luminaire's UGR table of CIE 190
//! (`ugo::readout::ugr_table`, `docs/photometry.md`, "The UGR table") as CSV, one row per
//! cell: `x_H,y_H,viewing,ceiling,walls,floor,room_index,UGR_reference,UGR,L_b_cd_m2`
//! (`UGR_reference` at `REFERENCE_FLUX`, `UGR` and `L_b` at the lamps' flux).

use super::error::IoError;
use crate::readout::ugr_table::UgrTable;
use std::path::Path;

/// Writes `table` to `path` through a temporary file.
pub fn write_ugr_table_csv(path: &Path, table: &UgrTable) -> Result<(), IoError> {
    let mut text = String::from("x_H,y_H,viewing,ceiling,walls,floor,room_index,UGR_reference,UGR,L_b_cd_m2\n");
    for c in &table.cells {
        let r = c.reflectances;
        text += &format!(
            "{},{},{},{},{},{},{:.4},{:.4},{:.4},{:.6e}\n",
            c.room[0],
            c.room[1],
            c.viewing.name(),
            r.ceiling,
            r.walls,
            r.floor,
            c.room_index,
            c.ugr - table.summand(),
            c.ugr,
            c.background
        );
    }
    super::write_bytes(path, text.as_bytes())
}
