//! The report's probes (`docs/report.md`): every `[[probe]]` of `/probes` with its reading,
//! its error bar (`docs/design.md` (5.5)), its direct part and its luminance, then its
//! illuminance in each light scene (`/light_scenes/<name>/probes`) with that scene's bar.

use super::super::read::Result;
use super::h5::H5;
use super::html::{escape, number, section, table, with_bar};

/// A probe table's readings under `at` (`probes` or `light_scenes/<name>/probes`): the
/// illuminance, its error bar where the file holds one, the direct part and the luminance.
struct Readings {
    illuminance: Vec<f64>,
    bar: Option<Vec<f64>>,
    direct: Option<Vec<f64>>,
    luminance: Vec<f64>,
}

impl Readings {
    fn read(h: &H5, at: &str, n: usize) -> Result<Readings> {
        let optional = |key: &str| {
            let path = format!("{at}/{key}");
            if h.has(&path) { h.numbers_of(&path, n).map(Some) } else { Ok(None) }
        };
        Ok(Readings {
            illuminance: h.numbers_of(&format!("{at}/illuminance"), n)?,
            bar: optional("error")?,
            direct: optional("direct")?,
            luminance: h.numbers_of(&format!("{at}/luminance"), n)?,
        })
    }

    /// Probe `i`'s illuminance as shown, "value ± bar" where it has a bar.
    fn illuminance(&self, i: usize) -> String {
        with_bar(self.illuminance[i], self.bar.as_ref().map(|b| b[i]), 1)
    }
}

/// The probes' readings, or nothing for a case without probes.
pub(super) fn probes(h: &H5) -> Result<Option<String>> {
    let names = if h.has("probes/name") { h.strings("probes/name")? } else { Vec::new() };
    if names.is_empty() {
        return Ok(None);
    }
    let n = names.len();
    let kinds = h.strings("probes/kind")?;
    let case = Readings::read(h, "probes", n)?;
    let scenes: Vec<String> =
        if h.has("light_groups/scene_names") { h.strings("light_groups/scene_names")? } else { Vec::new() };
    let in_scenes =
        scenes.iter().map(|s| Readings::read(h, &format!("light_scenes/{s}/probes"), n)).collect::<Result<Vec<_>>>()?;
    let rows: Vec<Vec<String>> = (0..n)
        .map(|i| {
            let kind = kinds.get(i).map_or("—".to_string(), |k| escape(k));
            let direct = case.direct.as_ref().map_or(f64::NAN, |d| d[i]);
            let mut row =
                vec![escape(&names[i]), kind, case.illuminance(i), number(direct, 1), number(case.luminance[i], 2)];
            row.extend(in_scenes.iter().map(|s| s.illuminance(i)));
            row
        })
        .collect();
    let mut head: Vec<String> =
        ["probe", "kind", "illuminance (lx)", "of it direct (lx)", "luminance (cd/m²)"].map(str::to_string).into();
    head.extend(scenes.iter().map(|s| format!("illuminance in {s} (lx)")));
    Ok(Some(section("probes", "Probes", &table("probes", &head, &rows))))
}
