//! `ugo probes CASE -o FILE`: the hard probes of a case placed by class (`ugo::placement`,
//! issue 34) and written as `[[probe]]` tables, with the command that made them in a
//! comment: the case with these tables in place of its own probes is a benchmark case
//! (`tools/accuracy/`, `docs/accuracy.md`). Prints how many probes each class got.

use super::options::Discretize;
use super::{check_writable, load};
use anyhow::{Result, bail};
use std::path::{Path, PathBuf};
use ugo::io::write_bytes;
use ugo::placement::{Options, Placement, place};

/// What `ugo probes` was asked for.
pub struct ProbesJob {
    /// Where the tables go.
    pub output: PathBuf,
    /// The placement's counts and seed.
    pub options: Options,
}

pub fn run(case: &Path, d: &Discretize, job: &ProbesJob) -> Result<()> {
    if job.options.count == 0 || job.options.candidates == 0 {
        bail!("--count and --candidates must be at least 1");
    }
    let scene = load(case, d)?;
    check_writable(&job.output)?;
    let start = std::time::Instant::now();
    let placement = place(&scene, &job.options);
    write_bytes(&job.output, tables(case, &job.options, &placement).as_bytes())?;
    say!(
        "  {} probes from {} candidates ({:.1} s) → {}",
        placement.probes.len(),
        placement.drawn,
        start.elapsed().as_secs_f64(),
        job.output.display()
    );
    for (class, count) in placement.counts() {
        say!("    {:<14} {count:>5}", class.name());
    }
    Ok(())
}

/// The `[[probe]]` tables, headed by the command and the counts.
fn tables(case: &Path, options: &Options, placement: &Placement) -> String {
    let counts: Vec<String> = placement.counts().iter().map(|(c, n)| format!("{} {n}", c.name())).collect();
    let mut text = format!(
        "# Hard probes of {} by class (issue 34): `ugo probes {} --count {} --seed {} --candidates {}`,\n\
         # {} candidates drawn. Per class: {}.\n",
        case.display(),
        case.display(),
        options.count,
        options.seed,
        options.candidates,
        placement.drawn,
        counts.join(", ")
    );
    for p in &placement.probes {
        let (x, n) = (p.position, p.normal);
        text += &format!(
            "\n[[probe]]\nname = \"{}\"\nposition = [{:.6}, {:.6}, {:.6}]\nnormal = [{:.9}, {:.9}, {:.9}]\n",
            p.name(),
            x.x,
            x.y,
            x.z,
            n.x,
            n.y,
            n.z
        );
    }
    text
}
