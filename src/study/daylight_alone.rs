//! The daylight readings of a case (`docs/daylight.md`, "Daylight beside electric light"):
//! SC, ERC, IRC and `DF = E / E_h` are shares of the light of the sky, the ground and the
//! sun alone. In a case lit by luminaires or emitting surfaces as well, `E` of the case's
//! own field holds their light too (a desk by the window read DF 23 % for SC 15 % and IRC
//! 3 %), so the daylight sources (every `[[window]]` and the `[sky]`'s sun) are solved
//! alone on the case's kernel (`docs/design.md` (1.6): the field is linear in its sources)
//! and the probes and grids read again on that field. A case lit by daylight alone reads
//! its own field, with no second solve.

use super::error::StudyError;
use super::light_scenes::{GroupSolves, Operators};
use crate::luminaire::Light;
use crate::model::Model;
use crate::progress::Progress;
use crate::readout::daylight::{DaylightReadings, read_daylight};
use crate::readout::field::Field;
use crate::readout::grid::{GridReading, read_grids};
use crate::readout::probe::{ProbeReading, read_probes};
use crate::scene::Scene;
use crate::solve::solve;

/// The daylight readings of `scene` on `model`, whose solved readings are `probes` and
/// `grids`; `None` without a sky. With other sources lit, the daylight is solved alone
/// (`how`) on the model relit by it, and the model is given back as it came.
pub fn daylight_readings(
    scene: &Scene,
    model: &mut Model,
    (probes, grids): (&[ProbeReading], &[GridReading]),
    how: &GroupSolves,
    progress: &dyn Progress,
) -> Result<Option<DaylightReadings>, StudyError> {
    let Some(sky) = scene.sky.as_ref() else { return Ok(None) };
    if lit_by_daylight_alone(scene, model) {
        return Ok(Some(read_daylight(model, sky, probes, grids)));
    }
    let daylight: Vec<usize> = (0..model.sources.len()).filter(|&i| is_daylight(scene, model, i)).collect();
    // The openings' light costs far more to integrate again than the luminaires': it is
    // the case's own less theirs.
    let others: Vec<usize> = (0..model.sources.len()).filter(|i| !daylight.contains(i)).collect();
    let surfaces: Vec<usize> =
        (0..model.mesh.patches.iter().map(|p| p.surface as usize + 1).max().unwrap_or(0)).collect();
    let term = model.source_term_without(&others, &surfaces);
    let x = solve_alone(model, &term.l0, how, progress)?;
    let mut lit = vec![0.0; model.sources.len()];
    daylight.iter().for_each(|&i| lit[i] = 1.0);
    let sources = model.sources.iter().zip(lit).map(|(s, f)| s.scaled(f)).collect();
    let own = model.relight(sources, term);
    let field = Field::from_unknowns(&x, model.kernel.cells());
    let probes = read_probes(&scene.probes, model, &field, progress);
    let grids = read_grids(&scene.grids, model, &field, progress);
    let readings = read_daylight(model, sky, &probes, &grids);
    model.relight(own.0, own.1);
    crate::interrupt::check(|| "the daylight's readouts".to_string())?;
    Ok(Some(readings))
}

/// True when `model` is lit by daylight alone (every source is a window's sky and ground or
/// the sun, no surface emits): its own field is the daylight's, and the daylight factors are
/// read on it with no second solve.
pub(super) fn lit_by_daylight_alone(scene: &Scene, model: &Model) -> bool {
    (0..model.sources.len()).all(|i| is_daylight(scene, model, i)) && model.mesh.emission.iter().all(|&e| e <= 0.0)
}

/// True for source `i` of `model` when it is daylight: a window's sky and ground, or the
/// shining sun of the `[sky]` (the parallel source it names "sun", a name no `[[luminaire]]`
/// may take then).
fn is_daylight(scene: &Scene, model: &Model, i: usize) -> bool {
    match &model.sources[i].light {
        Light::Window { .. } => true,
        Light::Parallel { .. } => {
            scene.sky.as_ref().is_some_and(|sky| sky.sun_horizontal > 0.0) && model.sources[i].name == "sun"
        }
        Light::Point { .. } => false,
    }
}

/// The unknowns of `x = l0 + K x` on `model`'s kernel, solved as `how` says.
fn solve_alone(model: &Model, l0: &[f64], how: &GroupSolves, progress: &dyn Progress) -> Result<Vec<f64>, StudyError> {
    let operators = Operators::new(model, how)?;
    progress.begin("daylight alone", how.params.max_iterations as u64);
    let solved = solve(how.method, &operators.system(l0), &how.params, &mut |n, r| {
        progress.at(n as u64, &format!("daylight alone: {} {r:.1e}", how.method.name()))
    });
    progress.end();
    Ok(solved?.0)
}
