//! Output files under faults: a write that fails (a full disk, a file-size limit) leaves
//! the previous file byte for byte and exits non-zero; a process killed mid-write leaves a
//! temporary file that the next run removes; of concurrent writers of one path one writes
//! and the others are refused; a signal stops every long stage within a second
//! (`stages.rs`). The kernel file (`kernel_file.rs`, `kernel_check.py`) and its
//! exports (`export.rs`). The grids' plans, their round ticks and isolux lines
//! (`grid_map.rs`, `ticks.rs`, `isolines.rs`), the luminaires and the section they draw
//! (`plan_marks.rs`). The HTML report checked by a parser against its file (`report.rs`,
//! `report_check.py`).

mod export;
mod faults;
mod grid_map;
mod hierarchy_file;
mod isolines;
mod kernel_file;
mod part_file;
mod plan_marks;
mod report;
mod stages;
mod ticks;
