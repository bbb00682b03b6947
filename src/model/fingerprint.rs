//! The fingerprint of a kernel (issue 15, `docs/kernel-file.md`): what `G`, the blocks `B`
//! and the luminaires' direct light `D` of `K = B·G`, `L0 = L_e + B·D` (`docs/design.md` §3) are
//! computed from, in named parts, so that a saved kernel is reused only for the case it was
//! assembled for and a refusal names the part that changed.
//!
//! Each part is a 64-bit FNV-1a hash of a canonical text (every float in its exact
//! shortest round-trip form) with a short summary for messages. The uniform `G` depends
//! on the geometry, the discretization, the visibility rules and the program, and on its
//! mirrors (which surfaces mirror, how much, and whether every luminaire is a point source:
//! plane mirrors are carried by images, `docs/mirrors.md`); a change of the other
//! reflectances only rebuilds `B` and `L0`, a change of the luminaires (among point sources)
//! only `D` and `L0`. Probes, grids, cameras, the solver and the surfaces' own emission (`L_e`, taken
//! from the case every time) are not part of the kernel.

use crate::geometry::{Shape, Surface};
use crate::kernel::hierarchy::Options;
use crate::luminaire::Source;
use crate::material::MaterialModel;
use crate::scene::{Discretization, KernelKind, Scene};
use crate::transfer::form_factor::Quadrature;
use crate::transfer::occlusion::{POINTS, SHADOW_DEPTH};
use crate::visibility::VisibilityOptions;
use std::fmt::Write;

/// The layout of the `/kernel` group; a file of another layout is another version.
pub const KERNEL_FORMAT: u32 = 3;

/// The named parts of a fingerprint.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// The surfaces' shapes, sides and orientation (the mesh before `patch_size`).
    Geometry,
    /// The materials that `G` depends on (none for the uniform kernel).
    Materials,
    /// Patch size, direction cells, assembly method, precision of `G`, quadrature.
    Discretization,
    /// The ray caster and the occlusion sample points.
    Visibility,
    /// The program's version and the kernel file's layout.
    Version,
    /// The material blocks `B` and which material each surface uses.
    Reflectances,
    /// The luminaires, placed (their direct light `D`).
    Luminaires,
}

impl Part {
    /// Every part, in the order they are stored and compared.
    pub const ALL: [Part; 7] = [
        Part::Geometry,
        Part::Materials,
        Part::Discretization,
        Part::Visibility,
        Part::Version,
        Part::Reflectances,
        Part::Luminaires,
    ];

    /// The part's name in the file and in messages.
    pub fn name(self) -> &'static str {
        match self {
            Part::Geometry => "geometry",
            Part::Materials => "materials",
            Part::Discretization => "discretization",
            Part::Visibility => "visibility",
            Part::Version => "version",
            Part::Reflectances => "reflectances",
            Part::Luminaires => "luminaires",
        }
    }

    /// The part of a stored name; `None` if unknown.
    pub fn parse(name: &str) -> Option<Part> {
        Part::ALL.into_iter().find(|p| p.name() == name)
    }

    /// What is rebuilt from the case when only this part changed (`G` is reused), or
    /// `None` when `G` itself depends on it and the kernel cannot be reused.
    pub fn rebuilt(self) -> Option<&'static str> {
        match self {
            Part::Reflectances => Some("the blocks B and L0 = L_e + B·D rebuilt from the case"),
            Part::Luminaires => Some("the luminaires' direct light D and L0 recomputed from the case"),
            _ => None,
        }
    }
}

/// One part: its hash and a summary for messages.
#[derive(Debug, Clone, PartialEq)]
pub struct Stamp {
    /// The part stamped.
    pub part: Part,
    /// The hash of everything in the part.
    pub hash: u64,
    /// What the part holds, in words, for messages.
    pub summary: String,
}

/// A part that differs between a stored fingerprint and a case's.
#[derive(Debug, Clone, PartialEq)]
pub struct Change {
    /// The part that changed.
    pub part: Part,
    /// The stored summary (`None` when the file lacks the part).
    pub stored: Option<String>,
    /// The case's summary.
    pub case: String,
}

impl std::fmt::Display for Change {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match &self.stored {
            Some(s) if *s != self.case => {
                let (file, case): (Vec<&str>, Vec<&str>) = (s.split(", ").collect(), self.case.split(", ").collect());
                if file.len() != case.len() {
                    return write!(f, "{} (file: {s}; case: {})", self.part.name(), self.case);
                }
                let differ: Vec<String> = file
                    .iter()
                    .zip(&case)
                    .filter(|(a, b)| a != b)
                    .map(|(a, b)| format!("{a} in the file, {b} in the case"))
                    .collect();
                write!(f, "{} ({})", self.part.name(), differ.join("; "))
            }
            Some(_) => write!(f, "{} ({})", self.part.name(), self.case),
            None => write!(f, "{} (not in the file)", self.part.name()),
        }
    }
}

/// Everything a kernel depends on, part by part.
#[derive(Debug, Clone, PartialEq)]
pub struct Fingerprint {
    /// One stamp per part, in the order of [`Part::ALL`].
    pub stamps: Vec<Stamp>,
}

impl Fingerprint {
    /// The fingerprint of the kernel of `scene` as discretized.
    pub fn of(scene: &Scene) -> Fingerprint {
        let hierarchical = matches!(scene.discretization.kernel, KernelKind::Hierarchical(_));
        let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
        let stamps = Part::ALL
            .into_iter()
            .map(|part| {
                let mut h = Fnv::default();
                let summary = match part {
                    Part::Geometry => geometry(&scene.surfaces, &mut h),
                    Part::Materials if hierarchical => {
                        // The hierarchy's mirrors reflect cell to cell: its stored operator
                        // depends on no material (its refinement did, see `rebuilt`).
                        let _ = write!(h, "none");
                        "none (the hierarchical G is stored as refined)".to_string()
                    }
                    Part::Materials => mirrors(scene, &sources, &mut h),
                    Part::Discretization => discretization(&scene.discretization, &mut h),
                    Part::Visibility => {
                        let text = format!(
                            "{:?}, {POINTS} occlusion points per patch, shadow depth {SHADOW_DEPTH}",
                            VisibilityOptions::default()
                        );
                        let _ = write!(h, "{text}");
                        text
                    }
                    Part::Version => {
                        let text = format!("ugo {}, kernel format {KERNEL_FORMAT}", env!("CARGO_PKG_VERSION"));
                        let _ = write!(h, "{text}");
                        text
                    }
                    Part::Reflectances => {
                        let _ = write!(h, "{:?}", scene.materials);
                        scene.surfaces.iter().for_each(|s| {
                            let _ = write!(h, "{},", s.material);
                        });
                        let names: Vec<&str> = scene.materials.iter().map(|m| m.name.as_str()).collect();
                        format!("{} materials: {}", names.len(), names.join(", "))
                    }
                    Part::Luminaires => {
                        let _ = write!(h, "{:?}", sources.iter().map(|s| &s.light).collect::<Vec<_>>());
                        format!("{} luminaires", sources.len())
                    }
                };
                Stamp { part, hash: h.0, summary }
            })
            .collect();
        Fingerprint { stamps }
    }

    /// The parts of `self` (the case's) that `stored` lacks or holds with another hash.
    pub fn changes_from(&self, stored: &Fingerprint) -> Vec<Change> {
        self.stamps
            .iter()
            .filter_map(|ours| {
                let theirs = stored.stamps.iter().find(|s| s.part == ours.part);
                match theirs {
                    Some(t) if t.hash == ours.hash => None,
                    _ => Some(Change {
                        part: ours.part,
                        stored: theirs.map(|t| t.summary.clone()),
                        case: ours.summary.clone(),
                    }),
                }
            })
            .collect()
    }
}

/// The surfaces' shapes (an OBJ's triangles, not its path), sides and orientation.
fn geometry(surfaces: &[Surface], h: &mut Fnv) -> String {
    for s in surfaces {
        match &s.shape {
            Shape::Mesh { triangles, .. } => write!(h, "mesh {triangles:?}"),
            shape => write!(h, "{shape:?}"),
        }
        .and_then(|()| write!(h, " two_sided {} inside {};", s.two_sided, s.inside))
        .unwrap_or(());
    }
    format!("{} surfaces", surfaces.len())
}

fn discretization(d: &Discretization, h: &mut Fnv) -> String {
    let (kernel, quadrature) = match d.kernel {
        // the name that kernel files have stored for the uniform kernel from the start
        KernelKind::Uniform => ("Explicit".to_string(), Quadrature::default()),
        KernelKind::Hierarchical(h) => {
            let o = Options::default();
            let text = format!(
                "hierarchical, root_size {:?} m, link_tolerance {:?}, dim_floor {:?}, reading_weight {:?}, passes {}, balanced {}",
                h.root_size, h.link_tolerance, o.dim_floor, o.reading_weight, h.passes, o.balance
            );
            (text, o.quadrature)
        }
    };
    let text = format!(
        "patch_size {:?} m, directions {}, method {kernel}, G in {}, quadrature eta {:?} depth {}",
        d.patch_size,
        d.directions.set().name(),
        d.precision.name(),
        quadrature.eta,
        quadrature.max_depth
    );
    let _ = write!(h, "{text}");
    text
}

/// 64-bit FNV-1a over what is written into it.
pub(super) struct Fnv(pub u64);

impl Default for Fnv {
    fn default() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
}

impl Write for Fnv {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        for b in s.bytes() {
            self.0 = (self.0 ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
        Ok(())
    }
}

/// What the uniform `G` takes of the materials: the mirrors' reflectances and surfaces, and
/// whether only point sources light the scene (else its mirrors reflect cell to cell:
/// `model::uniform::mirrors_of`). Hashed as `none` when no surface mirrors.
fn mirrors(scene: &Scene, sources: &[Source], h: &mut Fnv) -> String {
    let mirroring: Vec<(usize, f64)> = scene
        .surfaces
        .iter()
        .enumerate()
        .filter_map(|(i, s)| match scene.materials.get(s.material)?.model {
            MaterialModel::Mirror { reflectance } => Some((i, reflectance)),
            _ => None,
        })
        .collect();
    if mirroring.is_empty() {
        let _ = write!(h, "none");
        return "none (the uniform G depends on no material)".to_string();
    }
    let points = sources.iter().all(Source::mirrored_by_image);
    let _ = write!(h, "{mirroring:?} {points}");
    let images = if points { "carried by images" } else { "reflecting cell to cell" };
    format!("mirrors on {} surfaces {images}", mirroring.len())
}
