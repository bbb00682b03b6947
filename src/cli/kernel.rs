//! `--save-kernel` and `--kernel-file FILE.h5` of `solve`, `norms` and `compare` (issue 15,
//! docs/kernel-file.md): the options, and the summary line of a reused kernel.

use std::path::PathBuf;
use ugo::io::KernelRecord;
use ugo::study;

/// Saving and reusing the assembled kernel.
#[derive(clap::Args, Clone, Debug)]
pub struct KernelOptions {
    /// Store the kernel (the uniform G in CSR, or the hierarchy's tree, links and operator;
    /// the blocks B, the direct light D, L0 and the case's fingerprint) in the output's
    /// /kernel group.
    #[arg(long)]
    pub save_kernel: bool,
    /// Reuse the kernel saved in this file instead of assembling it, when it was assembled
    /// for this case (refused naming the part that changed; new reflectances or luminaires
    /// reuse G).
    #[arg(long, value_name = "FILE.h5")]
    pub kernel_file: Option<PathBuf>,
}

impl KernelOptions {
    /// A study job with these options and the defaults otherwise.
    pub fn job(self) -> study::Job {
        study::Job { kernel_file: self.kernel_file, save_kernel: self.save_kernel, ..Default::default() }
    }

    pub fn given(&self) -> bool {
        self.save_kernel || self.kernel_file.is_some()
    }
}

/// Where the kernel came from, for the summary.
pub fn print_record(record: &KernelRecord) {
    if let Some(loaded) = &record.loaded {
        say!(
            "  kernel             {:>12.3} s   (G read from {}, not assembled)",
            loaded.seconds,
            loaded.path.display()
        );
        for change in &loaded.rebuilt {
            let rebuilt = change.part.rebuilt().unwrap_or_default();
            say!("    {change} changed: G reused, {rebuilt}");
        }
        if loaded.hierarchical && !loaded.rebuilt.is_empty() {
            say!(
                "    note: the hierarchy's leaves and links were refined under the file's reflectances and luminaires, not the case's: they are reused as they are (a fresh solve would refine them for the case)"
            );
        }
    }
    if record.save.is_some() {
        say!("  kernel saved in    /kernel of the output (docs/kernel-file.md)");
    }
}
