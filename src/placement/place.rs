//! Drawing candidates until every class is full: a point uniform over the area of the
//! surfaces that do not emit (their exposed part, `transfer::exposure`), what it sees
//! (`around.rs`), and the first class still short of probes, fewest first, that it can
//! give a probe: moved along its surface to a corner, an edge or a contact (`settle.rs`),
//! or where it stands. Every candidate gives one probe at most; the first `20 × count`
//! clear ones are the pool of the dimmest 5 % (`dim.rs`). The candidates' random streams
//! are keyed by `(seed, index)`: the same seed gives the same probes. `y` is up.

use super::around::{Around, Spot, look};
use super::class::{Class, Placed};
use super::dim::dimmest;
use super::lights::lit;
use super::settle::settle;
use super::shell::Shell;
use super::sight::Sight;
use crate::geometry::Mesh;
use crate::luminaire::Source;
use crate::random::Rng;
use crate::scene::Scene;
use crate::trace::World;
use glam::DVec3;
use std::collections::BTreeMap;

/// How many probes of each class, from which seed, out of how many candidates at most.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Probes per class (fewer where the candidates run out first).
    pub count: usize,
    /// The seed of the candidates' streams.
    pub seed: u64,
    /// Candidates drawn at most.
    pub candidates: usize,
}

/// The probes placed, by class and number.
#[derive(Debug, Clone, PartialEq)]
pub struct Placement {
    /// Every probe, class by class in the order of [`Class::all`].
    pub probes: Vec<Placed>,
    /// The candidates drawn.
    pub drawn: usize,
}

impl Placement {
    /// How many probes each class got, every class listed.
    pub fn counts(&self) -> Vec<(Class, usize)> {
        Class::all().into_iter().map(|c| (c, self.probes.iter().filter(|p| p.class == c).count())).collect()
    }
}

/// The up direction.
const UP: DVec3 = DVec3::Y;

/// Places the hard probes of `scene`, its surfaces meshed at its patch size.
pub fn place(scene: &Scene, options: &Options) -> Placement {
    let world = World::new(scene, Mesh::build(&scene.surfaces, scene.discretization.patch_size));
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    Room { sight: Sight::new(&world), shell: Shell::of(&world.mesh), sources, options: *options }.place()
}

/// A scene ready for placing.
struct Room<'a> {
    sight: Sight<'a>,
    shell: Shell,
    sources: Vec<Source>,
    options: Options,
}

impl Room<'_> {
    fn place(&self) -> Placement {
        let (count, pool_size) = (self.options.count, 20 * self.options.count);
        let mut found: BTreeMap<Class, Vec<Spot>> = Class::all().into_iter().map(|c| (c, Vec::new())).collect();
        let mut pool = Vec::new();
        let area = self.area();
        let mut drawn = 0;
        while drawn < self.options.candidates && !self.full(&found, pool.len()) {
            let mut rng = Rng::stream(self.options.seed, drawn as u64);
            drawn += 1;
            let Some(spot) = self.draw(&area, &mut rng) else { break };
            let turn = rng.uniform();
            let around = look(&self.sight, &self.shell, &spot, turn);
            if !around.clear() {
                continue;
            }
            if pool.len() < pool_size {
                pool.push(spot);
            }
            let mut wanted: Vec<Class> =
                found.iter().filter(|(c, s)| **c != Class::Dim && s.len() < count).map(|(c, _)| *c).collect();
            wanted.sort_by_key(|c| found[c].len());
            if let Some((class, probe)) =
                wanted.into_iter().find_map(|c| self.offer(c, &spot, &around, turn, &mut rng).map(|s| (c, s)))
            {
                found.get_mut(&class).expect("every class is listed").push(probe);
            }
        }
        found.insert(Class::Dim, dimmest(self.sight.world, &pool, count, self.options.seed));
        let probes = found
            .into_iter()
            .flat_map(|(class, spots)| {
                spots.into_iter().enumerate().map(move |(number, s)| Placed {
                    class,
                    number,
                    position: s.probe(),
                    normal: s.normal(),
                })
            })
            .collect();
        Placement { probes, drawn }
    }

    /// True when every class but the dimmest is full and the pool of the dimmest too.
    fn full(&self, found: &BTreeMap<Class, Vec<Spot>>, pool: usize) -> bool {
        let count = self.options.count;
        pool >= 20 * count && found.iter().all(|(c, s)| *c == Class::Dim || s.len() >= count)
    }

    /// Cumulative exposed area of the patches that may hold probes (those that do not
    /// emit), with each patch's index.
    fn area(&self) -> Vec<(f64, usize)> {
        let mesh = &self.sight.world.mesh;
        let mut total = 0.0;
        let mut out = Vec::new();
        for (i, p) in mesh.patches.iter().enumerate() {
            if mesh.emission[i] <= 0.0 && p.exposed > 0.0 {
                total += p.exposed;
                out.push((total, i));
            }
        }
        out
    }

    /// A point uniform over `area`'s patches.
    fn draw(&self, area: &[(f64, usize)], rng: &mut Rng) -> Option<Spot> {
        let total = area.last()?.0;
        let u = rng.uniform() * total;
        let (_, i) = area[area.partition_point(|(c, _)| *c <= u).min(area.len() - 1)];
        let patch = &self.sight.world.mesh.patches[i];
        let point = patch.polygon.point_at(rng.uniform(), rng.uniform(), rng.uniform());
        Some(Spot { patch: i, point, frame: patch.frame(), face: patch.face, shell: self.shell.holds(patch) })
    }

    /// The spot of a probe of `class` from `spot`, if it can give one.
    fn offer(&self, class: Class, spot: &Spot, around: &Around, turn: f64, rng: &mut Rng) -> Option<Spot> {
        let n = spot.normal();
        let mesh = &self.sight.world.mesh;
        match class {
            Class::Corner(_) | Class::Edge(_) | Class::Contact(_) => self.at_edge(class, spot, around, turn),
            Class::Underside => {
                (n.dot(UP) < -0.7 && !spot.shell && around.facing_within(1.0).is_some()).then_some(*spot)
            }
            Class::Under => {
                let (_, above) = around.facing_within(1.0)?;
                let furniture = !self.shell.holds(&mesh.patches[above]) && mesh.patches[above].normal.dot(UP) < -0.7;
                (n.dot(UP) > 0.7 && spot.shell && furniture).then_some(*spot)
            }
            Class::Gap => {
                let (_, facing) = around.facing_within(0.03)?;
                (mesh.patches[facing].normal.dot(n) < -0.7).then_some(*spot)
            }
            Class::Umbra | Class::Penumbra | Class::Open => {
                let share = lit(self.sight.world, &self.sources, spot.probe(), n, spot.face, rng).share();
                let fits = match class {
                    Class::Umbra => share == Some(0.0),
                    Class::Penumbra => share.is_some_and(|s| (0.02..0.98).contains(&s)),
                    _ => share.is_none_or(|s| s == 1.0) && open(around),
                };
                fits.then_some(*spot)
            }
            Class::Dim => None,
        }
    }

    /// `spot` moved to a corner, an edge or a contact of `class`.
    fn at_edge(&self, class: Class, spot: &Spot, around: &Around, turn: f64) -> Option<Spot> {
        let distance = class.distance()?;
        let shell: Vec<_> = around.walls.iter().filter(|w| w.shell).copied().collect();
        match class {
            Class::Corner(_) if spot.shell => {
                let a = *shell.first()?;
                let b = *shell.iter().find(|w| w.normal.dot(a.normal).abs() < 0.5)?;
                settle(&self.sight, spot, &[a, b], distance)
            }
            Class::Edge(_) if spot.shell => {
                let wall = *shell.first()?;
                let moved = settle(&self.sight, spot, &[wall], distance)?;
                let there = look(&self.sight, &self.shell, &moved, turn);
                let mut near = there.walls_within(3.0 * distance);
                let alone = near.next().is_some_and(|w| w.same_plane(&wall)) && near.next().is_none();
                alone.then_some(moved)
            }
            Class::Contact(_) => {
                let wall = *around.walls.iter().find(|w| !(w.shell && spot.shell))?;
                settle(&self.sight, spot, &[wall], distance)
            }
            _ => None,
        }
    }
}

/// Away from every wall across the surface by 0.3 m, and nothing straight in front within 0.5 m.
fn open(around: &Around) -> bool {
    around.walls_within(0.3).next().is_none() && around.ahead.is_none_or(|s| s.distance > 0.5)
}
