//! The subcommands, one file each, and what they share.

pub mod agree;
pub mod basis;
pub mod bench;
pub mod daylight;
pub mod export;
pub mod glare;
pub mod glare_grid;
pub mod glare_table;
pub mod info;
pub mod kernel;
pub mod light_scenes;
pub mod options;
pub mod part;
pub mod probes;
pub mod readout;
pub mod render;
pub mod report;
pub mod size_key;
pub mod solve;
pub mod spectrum;
pub mod stop;
pub mod trace;

use anyhow::{Result, bail};
use options::Discretize;
use std::path::{Path, PathBuf};
use ugo::luminaire::{Light, Source};
use ugo::photometry::Distribution;
use ugo::progress::{line, time_left};
use ugo::scene::{KernelKind, Scene};

/// Loads a case with the command line's discretization flags resolved into it (the one
/// record of its discretization), telling its old spellings and a kernel chosen by size.
pub fn load(case: &Path, d: &Discretize) -> Result<Scene> {
    let mut scene = Scene::load(case)?;
    let warnings = scene.warnings();
    // the same key and message in several tables (a hint on each instance of an OBJ) once
    let mut alike: Vec<(&ugo::scene::SceneError, usize)> = Vec::new();
    for w in &warnings {
        match alike.iter_mut().find(|(f, _)| f.key() == w.key() && f.message() == w.message()) {
            Some((_, n)) => *n += 1,
            None => alike.push((w, 1)),
        }
    }
    for (warning, n) in alike {
        match n {
            1 => eprintln!("ugo: warning: {warning}"),
            n => eprintln!("ugo: warning: {warning} (and {} more tables alike)", n - 1),
        }
    }
    for old in &scene.old_spelling {
        eprintln!("ugo: note: {old}");
    }
    scene.discretize(&d.asked())?;
    let discretization = &scene.discretization;
    if let (Some(chosen), KernelKind::Hierarchical(_)) = (discretization.chosen_by_size, discretization.kernel) {
        eprintln!("ugo: note: no `kernel` in [discretization]: {chosen}");
    }
    Ok(scene)
}

/// Refuses, before any work, an output file that could not be written: a folder of that
/// name, a missing folder, or one where no file can be created (tried with a file of the
/// temporary name the writer would use, removed at once; a stale one is swept later).
pub fn check_writable(path: &Path) -> Result<()> {
    let shown = path.display();
    if path.is_dir() {
        bail!("cannot write {shown}: it is a folder; give a file name");
    }
    let folder = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !folder.is_dir() {
        bail!("cannot write {shown}: the folder {} does not exist", folder.display());
    }
    let mut probe = path.file_name().unwrap_or_default().to_owned();
    probe.push(format!(".{}.00000000.tmp", std::process::id()));
    let probe = folder.join(probe);
    match std::fs::OpenOptions::new().write(true).create_new(true).open(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => bail!("cannot write {shown}: cannot create a file in {}: {e}", folder.display()),
    }
}

/// One line about a luminaire: its distribution, the flux integrated from it and the
/// flux its file states, or the parallel light's illuminance.
pub fn describe(source: &Source) -> String {
    match &source.light {
        Light::Point { position, distribution, scale, .. } => {
            let what = match distribution {
                Distribution::Isotropic { intensity } => format!("isotropic, {intensity:.4} cd"),
                Distribution::Lambertian { peak } => format!("lambertian, I0 = {peak:.4} cd"),
                Distribution::Table(t) => {
                    let stated =
                        t.stated_flux.map_or("none (absolute photometry)".to_string(), |f| format!("{f:.4} lm"));
                    format!("{}: integrated {:.4} lm, the file states {stated}", t.description, t.flux())
                }
            };
            let at = format!("[{}, {}, {}]", position.x, position.y, position.z);
            format!("at {at}, scale {scale:.4}, {what}")
        }
        Light::Parallel { direction, illuminance, glass } => {
            let through: Vec<String> = glass
                .panes()
                .iter()
                .map(|p| format!(", through \"{}\" times τ·M = {:.4}", p.name, p.share(-*direction)))
                .collect();
            format!(
                "parallel light along [{:.4}, {:.4}, {:.4}], {illuminance} lx normal to the beam{}",
                direction.x,
                direction.y,
                direction.z,
                through.concat()
            )
        }
        Light::Window { window, sky } => format!(
            "opening of {:.4} m²{}, sky {:?} as let in (times its maintenance factor): E_h = {:.1} lx, \
             L_z = {:.1} cd/m², ground ρ = {}",
            window.polygon.area(),
            window.glazing.map_or(String::new(), |g| format!(" {g}")),
            sky.distribution,
            sky.horizontal_illuminance,
            sky.zenith_luminance,
            sky.ground_reflectance
        ),
    }
}

/// A progress bar on stderr (hidden when stderr is not a terminal), its time left at the
/// stage's average rate (`ugo::progress::time_left`).
pub fn bar(total: u64, what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(total);
    let left = |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
        if let Some(t) = time_left(s.elapsed().as_secs_f64(), s.pos(), s.len().unwrap_or(0)) {
            let _ = write!(w, "eta {}", clock(t));
        }
    };
    let template = match total {
        0 => "{msg:>10} {spinner} {pos} {elapsed_precise}",
        _ => "{msg:>10} [{bar:40}] {percent:>3}% {elapsed_precise} {left}",
    };
    let style = indicatif::ProgressStyle::with_template(template)
        .map(|s| s.progress_chars("=> ").with_key("left", left))
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
    bar.set_style(style);
    bar.set_message(what.to_string());
    bar
}

/// Seconds as `h:mm:ss`.
fn clock(seconds: f64) -> String {
    let s = seconds.round() as u64;
    format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
}

/// Seconds between two progress lines when stderr is not a terminal (`UGO_PROGRESS_SECONDS`
/// overrides it; 0 prints one per step).
const LINE_SECONDS: f64 = 5.0;

/// Progress on stderr, one stage at a time: a bar on a terminal, else a line
/// (`ugo: progress: …`) every [`LINE_SECONDS`].
pub struct Bars {
    current: std::sync::Mutex<Option<Stage>>,
    /// Seconds between lines; `None` on a terminal (the bar is drawn instead).
    every: Option<f64>,
}

struct Stage {
    bar: indicatif::ProgressBar,
    printed: std::time::Instant,
}

impl Default for Bars {
    fn default() -> Bars {
        use std::io::IsTerminal;
        let every = std::env::var("UGO_PROGRESS_SECONDS").ok().and_then(|s| s.parse::<f64>().ok());
        let every = (!std::io::stderr().is_terminal()).then(|| every.unwrap_or(LINE_SECONDS));
        Bars { current: std::sync::Mutex::new(None), every }
    }
}

impl Bars {
    fn with(&self, f: impl FnOnce(&indicatif::ProgressBar)) {
        if let Some(stage) = self.current.lock().unwrap_or_else(|e| e.into_inner()).as_mut() {
            f(&stage.bar);
            let Some(every) = self.every else { return };
            if stage.printed.elapsed().as_secs_f64() >= every {
                stage.printed = std::time::Instant::now();
                let b = &stage.bar;
                eprintln!("{}", line(&b.message(), b.position(), b.length().unwrap_or(0), b.elapsed().as_secs_f64()));
            }
        }
    }
}

impl ugo::progress::Progress for Bars {
    fn begin(&self, what: &str, total: u64) {
        let stage = Stage { bar: bar(total, what), printed: std::time::Instant::now() };
        *self.current.lock().unwrap_or_else(|e| e.into_inner()) = Some(stage);
    }

    fn advance(&self, done: u64) {
        self.with(|b| b.inc(done));
    }

    fn at(&self, position: u64, message: &str) {
        self.with(|b| {
            b.set_position(position);
            b.set_message(message.to_string());
        });
    }

    fn end(&self) {
        if let Some(stage) = self.current.lock().unwrap_or_else(|e| e.into_inner()).take() {
            stage.bar.finish_and_clear();
        }
    }
}

/// Bytes as GiB/MiB text.
pub fn bytes(b: f64) -> String {
    let gib = b / (1u64 << 30) as f64;
    match gib {
        g if !g.is_finite() => "more than can be counted".to_string(),
        g if g >= 1e4 => format!("{g:.3e} GiB"),
        g if g >= 1.0 => format!("{g:.2} GiB"),
        _ => format!("{:.1} MiB", b / (1u64 << 20) as f64),
    }
}

/// A table name (camera, grid) made safe for a file name.
pub fn file_name(name: &str) -> String {
    name.chars().map(|c| if c.is_alphanumeric() || c == '-' || c == '_' { c } else { '_' }).collect()
}

/// `base` with `suffix` appended to its file name.
pub fn sibling(base: &Path, suffix: &str) -> PathBuf {
    let mut name = base.as_os_str().to_owned();
    name.push(suffix);
    PathBuf::from(name)
}

/// A file written beside `output`: its name without the extension, then `suffix`
/// (`DIR/x.h5`, `-probes.csv` → `DIR/x-probes.csv`).
pub fn beside(output: &Path, suffix: &str) -> PathBuf {
    sibling(&output.with_extension(""), suffix)
}
