//! Every reader against the generator: case files (TOML), IES and EULUMDAT files, OBJ
//! meshes (through a case that names them) and solution files (HDF5).

use super::generator::Mutator;
use crate::support::{scratch, ugo};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use ugo::io::read_solution;
use ugo::photometry::{parse_ies, parse_ldt};
use ugo::scene::{CaseFile, CaseFiles, Scene};

const SEED: u64 = 18;
/// Mutations of each input file.
const MUTATIONS: u64 = 1000;
/// Longest a reader may take on one input.
const PATIENCE: Duration = Duration::from_secs(1);

struct Report {
    runs: usize,
    refused: usize,
    failures: Vec<String>,
    /// Longest a reader may take on one input.
    patience: Duration,
}

impl Default for Report {
    fn default() -> Self {
        Report { runs: 0, refused: 0, failures: Vec::new(), patience: PATIENCE }
    }
}

impl Report {
    /// Runs `read` on `input` (named `what`, mutated by `how`); a panic (the test's own
    /// `panic!("wrong: …")` for a wrongly accepted input) or a slow answer is a failure,
    /// and the input is saved for the corpus. A slow answer is timed once more: an input
    /// that hangs is slow every time, a machine busy with the other tests only once (a CI
    /// run beside a dense LU once took 4.2 s on two case files against a 4 s patience).
    fn run(&mut self, what: &str, how: &str, input: &[u8], read: impl Fn() -> Result<(), String>) {
        let start = Instant::now();
        let outcome = catch_unwind(AssertUnwindSafe(&read));
        let took = start.elapsed();
        self.runs += 1;
        let failure = match outcome {
            Err(panic) => {
                let message = panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                Some(format!("panicked: {message}"))
            }
            Ok(Err(message)) if message.trim().is_empty() => Some("an error without a message".into()),
            Ok(Err(_)) => {
                self.refused += 1;
                None
            }
            Ok(Ok(())) => None,
        };
        let failure = failure.or_else(|| {
            (took > self.patience).then_some(())?;
            let start = Instant::now();
            let _ = catch_unwind(AssertUnwindSafe(&read));
            let again = start.elapsed();
            (again > self.patience).then(|| format!("took {took:?}, then {again:?}"))
        });
        if let Some(why) = failure {
            let saved = std::env::temp_dir().join(format!("ugo-hostile-{}-{}", self.failures.len(), file_name(what)));
            let _ = std::fs::write(&saved, input);
            self.failures.push(format!("{what}, {how}: {why} (input saved to {})", saved.display()));
        }
    }

    fn check(self, what: &str) {
        eprintln!("{what}: {} inputs, {} refused cleanly, {} failures", self.runs, self.refused, self.failures.len());
        assert!(self.failures.is_empty(), "{what}:\n{}", self.failures.join("\n"));
    }
}

fn file_name(path: &str) -> String {
    Path::new(path).file_name().map_or("input".into(), |n| n.to_string_lossy().into_owned())
}

/// The files of `dir` (recursively) whose names end with one of `endings`.
fn files(dir: &str, endings: &[&str]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![PathBuf::from(dir)];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if endings.iter().any(|e| path.to_string_lossy().ends_with(e)) {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The saved inputs of `tests/data/hostile/` that end with `ending`, replayed first.
fn corpus(ending: &str) -> Vec<(PathBuf, Vec<u8>)> {
    files("tests/data/hostile", &[ending]).into_iter().map(|p| (p.clone(), std::fs::read(&p).unwrap())).collect()
}

/// `base` and its mutations, the corpus first.
fn inputs(base: &Path, ending: &str, stream: u64) -> Vec<(String, Vec<u8>)> {
    inputs_up_to(base, ending, stream, MUTATIONS)
}

/// `base`, the corpus and `mutations` mutations of `base`.
fn inputs_up_to(base: &Path, ending: &str, stream: u64, mutations: u64) -> Vec<(String, Vec<u8>)> {
    let bytes = std::fs::read(base).unwrap();
    let mut out: Vec<(String, Vec<u8>)> =
        corpus(ending).into_iter().map(|(p, b)| (format!("corpus {}", p.display()), b)).collect();
    out.push(("unchanged".into(), bytes.clone()));
    let mut mutator = Mutator::new(SEED, stream);
    out.extend((0..mutations).map(|_| {
        let (m, how) = mutator.mutate(&bytes);
        (how, m)
    }));
    out
}

/// Time for the mutations of one case file: a case that reads a large OBJ mesh (the hall's
/// 197,120 seat triangles) is mutated fewer times, and may take as long as its unchanged
/// self (the OBJ reader meets hostile meshes of its own below).
const CASE_BUDGET: Duration = Duration::from_secs(5);

#[test]
fn case_files_are_read_or_refused_cleanly() {
    let mut report = Report::default();
    for (n, case) in files("cases", &[".toml"]).iter().enumerate() {
        let what = case.display().to_string();
        let read = |input: &[u8]| {
            let text = String::from_utf8_lossy(input).into_owned();
            match Scene::parse(case, text) {
                Ok(scene) => {
                    let _ = scene.warnings();
                    Ok(())
                }
                Err(e) if e.to_string().starts_with(&what) => Err(e.to_string()),
                Err(e) => panic!("wrong: the error does not name the file: {e}"),
            }
        };
        let start = Instant::now();
        let _ = read(&std::fs::read(case).unwrap());
        let once = start.elapsed().max(Duration::from_millis(1));
        let mutations = (CASE_BUDGET.as_secs_f64() / once.as_secs_f64()).clamp(20.0, MUTATIONS as f64) as u64;
        report.patience = PATIENCE.max(4 * once);
        for (how, input) in inputs_up_to(case, ".toml", n as u64, mutations) {
            report.run(&what, &how, &input, || read(&input));
        }
    }
    report.check("case files");
}

#[test]
fn photometric_files_are_read_or_refused_cleanly() {
    let mut report = Report::default();
    let mut all = files("tests/data/photometry", &[".ies", ".ldt"]);
    all.extend(files("cases", &[".ies", ".ldt"]));
    for (n, file) in all.iter().enumerate() {
        let what = file.display().to_string();
        let ending = if what.ends_with(".ldt") { ".ldt" } else { ".ies" };
        for (how, input) in inputs(file, ending, 100 + n as u64) {
            report.run(&what, &how, &input, || {
                let text = String::from_utf8_lossy(&input);
                let read = if ending == ".ldt" { parse_ldt(file, &text) } else { parse_ies(file, &text) };
                match read {
                    Ok(table) if !(table.flux().is_finite() && table.flux() >= 0.0) => {
                        panic!("wrong: accepted with flux {}", table.flux())
                    }
                    Ok(_) => Ok(()),
                    Err(e) => Err(e.to_string()),
                }
            });
        }
    }
    report.check("photometric files");
}

/// OBJ meshes: faces of 3, 4 and 5 vertices, negative (relative) indices, normals and
/// texture coordinates, groups.
const OBJS: [&str; 3] = [
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 1 2 5\n",
    "o pentagon\nv 0 0 0\nv 1 0 0\nv 1.3 0.9 0\nv 0.5 1.5 0\nv -0.3 0.9 0\nvn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 3/1/1 4/1/1 5/1/1\n",
    "g box\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nf -6 -5 -4\nf -6 -4 -3\nf 1 2 6 5\n",
];

#[test]
fn obj_meshes_are_read_or_refused_cleanly() {
    let mut report = Report::default();
    let case = Path::new("virtual/case.toml");
    let text = "[discretization]\npatch_size = 0.5\n[[material]]\nname = \"m\"\ntype = \"lambert\"\nreflectance = 0.5\n\
                [[surface]]\nname = \"model\"\nshape = \"mesh\"\nmaterial = \"m\"\nfile = \"model.obj\"\n\
                emission = { luminance = 1 }\n";
    let dir = scratch("hostile-obj");
    for (n, obj) in OBJS.iter().enumerate() {
        let base = dir.join(format!("model-{n}.obj"));
        std::fs::write(&base, obj).unwrap();
        for (how, input) in inputs(&base, ".obj", 200 + n as u64) {
            report.run(&format!("OBJ #{n}"), &how, &input, || {
                let files = CaseFiles::stored(vec![CaseFile {
                    path: PathBuf::from("virtual/model.obj"),
                    bytes: input.clone(),
                }]);
                Scene::parse_with(case, text.to_string(), files).map(|_| ()).map_err(|e| e.to_string())
            });
        }
    }
    report.check("OBJ meshes");
}

/// A fresh copy of the solution `base` with `edit` applied through the HDF5 library.
fn edited(base: &Path, dir: &Path, name: &str, edit: impl FnOnce(&hdf5::File) -> hdf5::Result<()>) -> PathBuf {
    let path = dir.join(format!("{name}.h5"));
    std::fs::copy(base, &path).unwrap();
    let file = hdf5::File::open_rw(&path).unwrap();
    edit(&file).unwrap();
    file.close().unwrap();
    path
}

fn replace<T: hdf5::H5Type, D: ndarray::Dimension>(
    f: &hdf5::File,
    name: &str,
    data: &ndarray::Array<T, D>,
) -> hdf5::Result<()> {
    f.unlink(name)?;
    f.new_dataset_builder().with_data(data).create(name).map(|_| ())
}

fn set_text(f: &hdf5::File, name: &str, value: &str) -> hdf5::Result<()> {
    f.delete_attr(name)?;
    let value: hdf5::types::VarLenUnicode = value.parse().unwrap();
    f.new_attr::<hdf5::types::VarLenUnicode>().create(name)?.write_scalar(&value)
}

#[test]
fn solution_files_are_read_or_refused_cleanly() {
    let dir = scratch("hostile-h5");
    let base = dir.join("furnace.h5");
    let o = ugo(&["solve", "cases/furnace-box.toml", "-o", base.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    const N: usize = 600;
    type Edit = Box<dyn FnOnce(&hdf5::File) -> hdf5::Result<()>>;
    let edits: Vec<(&str, Edit)> = vec![
        ("material-id", Box::new(|f| f.dataset("mesh/material_id")?.write_slice(&[99u32], 0..1))),
        ("surface-id", Box::new(|f| f.dataset("mesh/surface_id")?.write_slice(&[99u32], 0..1))),
        ("nan-vertex", Box::new(|f| f.dataset("mesh/vertices")?.write_slice(&[f64::NAN], (0, 0, 0..1)))),
        ("collapsed-patch", Box::new(|f| f.dataset("mesh/vertices")?.write(&ndarray::Array3::<f64>::zeros((N, 4, 3))))),
        ("vertex-count", Box::new(|f| f.dataset("mesh/vertex_count")?.write_slice(&[7u8], 0..1))),
        ("face-huge", Box::new(|f| f.dataset("mesh/face")?.write_slice(&[1_000_000_000u32], 0..1))),
        ("twin-wrong", Box::new(|f| f.dataset("mesh/twin")?.write_slice(&[5u32], 0..1))),
        ("luminance-nan", Box::new(|f| f.dataset("field/luminance")?.write_slice(&[f64::NAN], (0, 0, 0..1)))),
        ("luminance-shape", Box::new(|f| replace(f, "field/luminance", &ndarray::Array3::<f64>::zeros((N, 2, 1))))),
        ("vertices-shape", Box::new(|f| replace(f, "mesh/vertices", &ndarray::Array3::<f64>::zeros((N, 4, 2))))),
        ("no-vertices", Box::new(|f| f.unlink("mesh/vertices"))),
        ("no-field", Box::new(|f| f.unlink("field"))),
        ("directions-huge", Box::new(|f| set_text(f, "directions", "1000000000"))),
        ("directions-unknown", Box::new(|f| set_text(f, "directions", "klemz"))),
        ("scene-text", Box::new(|f| set_text(f, "scene_text", "[discretization]\npatch_size = -1\n"))),
        (
            "declared-huge",
            Box::new(|f| {
                f.unlink("mesh/face")?;
                f.new_dataset::<u32>().shape(1_000_000_000usize).create("mesh/face").map(|_| ())
            }),
        ),
    ];
    let mut report = Report::default();
    for (name, edit) in edits {
        let path = edited(&base, &dir, name, edit);
        report.run(&format!("solution ({name})"), "edited", &std::fs::read(&path).unwrap(), || {
            match read_solution(&path) {
                Ok(_) => panic!("wrong: accepted"),
                Err(e) => Err(e.to_string()),
            }
        });
    }
    // The commands that read solutions end with a clean error on the edits the issue saw.
    for name in ["material-id", "surface-id", "nan-vertex", "face-huge"] {
        let path = dir.join(format!("{name}.h5"));
        let o = ugo(&["render", path.to_str().unwrap(), "-o", dir.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.starts_with("ugo: error:") && !err.contains("panicked"), "{name}: {err}");
        let o = ugo(&["agree", base.to_str().unwrap(), path.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.starts_with("ugo: error:") && !err.contains("panicked"), "{name}: {err}");
    }
    // Truncations and flipped bytes anywhere in the file.
    let bytes = std::fs::read(&base).unwrap();
    let mut rng = ugo::random::Rng::stream(SEED, 300);
    let copy = dir.join("mutated.h5");
    for i in 0..120 {
        let mut m = bytes.clone();
        let at = (rng.next_u64() % bytes.len() as u64) as usize;
        let how = if i % 3 == 0 {
            m.truncate(at);
            format!("truncated at byte {at}")
        } else {
            m[at] ^= 1 << (rng.next_u64() % 8);
            format!("a bit of byte {at} flipped")
        };
        std::fs::write(&copy, &m).unwrap();
        report.run("solution", &how, &m, || read_solution(&copy).map(|_| ()).map_err(|e| e.to_string()));
    }
    report.check("solution files");
}
