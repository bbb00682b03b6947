//! The report's light scenes (`docs/report.md`): for every `[[light_scene]]` of
//! `/light_groups` its groups' levels, the flux it emits and, from
//! `/light_scenes/<name>`, every grid against its targets and every observer's UGR (against its `UGR_L`, coloured); then
//! each grid's plan in each light scene, its luminaires drawn full, dimmed or off.

use super::super::grid_map::Shown;
use super::super::read::{Result, Why};
use super::glare::ugr_against;
use super::grids::{figures, plan, reading, sources, target_head};
use super::h5::H5;
use super::html::{escape, image, number, section, table};
use crate::io::StoredSolution;

/// The light scenes' table, or nothing for a case without light scenes.
pub(super) fn light_scenes(h: &H5, stored: &StoredSolution) -> Result<Option<String>> {
    if !h.has("light_groups/scene_names") {
        return Ok(None);
    }
    let (groups, scenes) = (h.strings("light_groups/name")?, h.strings("light_groups/scene_names")?);
    let factors = h.numbers_of("light_groups/factors", groups.len() * scenes.len())?;
    let observers = if h.has("observers/name") { h.strings("observers/name")? } else { Vec::new() };
    let limits = if observers.is_empty() { Vec::new() } else { h.numbers_of("observers/ugr_limit", observers.len())? };
    let grids = &stored.scene.grids;
    let mut head =
        vec!["light scene".to_string(), "groups".to_string(), "flux emitted (lm)".to_string(), "grid".to_string()];
    head.extend(target_head());
    head.extend(observers.iter().map(|o| format!("UGR {o}")));
    let mut rows = Vec::new();
    let mut plans = String::new();
    for (s, scene) in scenes.iter().enumerate() {
        let at = format!("light_scenes/{scene}");
        if !h.has(&at) {
            return Err(Why(format!("/light_groups/scene_names names \"{scene}\", but there is no /{at}")));
        }
        let levels = &factors[s * groups.len()..(s + 1) * groups.len()];
        plans += &scene_plans(h, stored, scene, &groups, levels)?;
        let levels: Vec<String> =
            groups.iter().zip(levels).map(|(g, f)| format!("{} {:.0} %", escape(g), f * 100.0)).collect();
        let ugrs = h.numbers_of(&format!("{at}/observers/ugr"), observers.len())?;
        let flux = h.attr(&at, "flux_emitted").unwrap_or(f64::NAN);
        // one row per grid (a row with dashes for a case without grids)
        let shown: Vec<Option<&crate::scene::Grid>> =
            if grids.is_empty() { vec![None] } else { grids.iter().map(Some).collect() };
        for grid in shown {
            let mut row = vec![escape(scene), levels.join(", "), number(flux, 1)];
            match grid {
                Some(g) => {
                    row.push(escape(&g.name));
                    row.extend(figures(h, &format!("{at}/grids/{}", g.name), g));
                }
                None => row.extend(std::iter::repeat_n("—".to_string(), target_head().len() + 1)),
            }
            row.extend(ugrs.iter().zip(&limits).map(|(&u, &l)| ugr_against(u, l)));
            rows.push(row);
        }
    }
    let body = table("light-scenes", &head, &rows) + &plans;
    Ok(Some(section("light-scenes", "Light scenes", &body)))
}

/// The plans of every grid in the light scene `scene`, its luminaires dimmed by `levels`
/// (one per group of `groups`; a source in no group at full output).
fn scene_plans(h: &H5, stored: &StoredSolution, scene: &str, groups: &[String], levels: &[f64]) -> Result<String> {
    let member_of = h.strings("luminaires/group")?;
    let mut lit = sources(stored);
    if lit.len() != member_of.len() {
        return Err(Why(format!("/luminaires/group has {} rows for {} luminaires", member_of.len(), lit.len())));
    }
    for (source, group) in lit.iter_mut().zip(&member_of) {
        source.dimmed = groups.iter().position(|g| g == group).map_or(1.0, |k| levels[k]);
    }
    let mut plans = String::new();
    for grid in &stored.scene.grids {
        let r = reading(h, &format!("light_scenes/{scene}/grids/{}", grid.name), grid)?;
        let png = plan(stored, &r, &Shown::illuminance(&r), &lit)?;
        plans += &image(&png, &format!("plan of the grid {} in the light scene {scene}: illuminance, lx", grid.name));
    }
    Ok(plans)
}
